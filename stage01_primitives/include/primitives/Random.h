#pragma once
/// @file Random.h
/// Counter-based random numbers: every number is a pure function of
///
///     (seed, pixel x, pixel y, sample index, dimension)
///
/// and of nothing else: no state is shared between threads, no generator is advanced in an order
/// that depends on scheduling, and nothing is allocated. An image is then the same, bit for bit,
/// whatever the number of threads or the order of the tiles, and one pixel (or one sample of it)
/// can be computed again alone to debug it.
///
/// How. A sample's four coordinates are hashed once into a 64-bit key; the number of dimension d
/// is the SplitMix64 output for the counter key + (d + 1)·γ (γ = 2^64/φ, the golden ratio
/// increment):
///
///     key   = mix(mix(mix(seed + γ) ^ (x | y << 32)) ^ sample)
///     bits  = mix(key + (d + 1)·γ)
///     u     = (bits >> 11) · 2^-53                     uniform in [0, 1), 53 random bits
///
/// mix is Stafford's "Mix13" finaliser (the one of SplitMix64, Steele, Lea and Flood 2014): two
/// multiply-xorshift rounds, a bijection of 64-bit words whose outputs for consecutive
/// counters pass the BigCrush battery. Counting dimensions with a fixed increment is exactly
/// SplitMix64's own stream, so the numbers of one sample are one SplitMix64 sequence started at
/// the sample's key. Each step is a handful of integer multiplies and xor-shifts.
///
/// A RandomStream also keeps a dimension cursor, so that code which consumes numbers one after
/// another (a jittered beam, a lens sample, then a light sample) writes next() and still draws a
/// pure function of the coordinates: the n-th number a sample's path asks for is always
/// uniform(n).

#include <cstdint>

namespace rt {

/// The Mix13 finaliser of SplitMix64: a bijection of 64-bit words that spreads every input bit
/// over the whole output.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// A point of the unit square [0,1)², or of the unit disk: two sample coordinates.
struct Sample2 {
  double u = 0, v = 0;
};

class RandomStream {
 public:
  /// SplitMix64's increment: 2^64 divided by the golden ratio, odd.
  static constexpr std::uint64_t GAMMA = 0x9e3779b97f4a7c15ULL;

  /// The stream of seed 0, pixel (0, 0), sample 0.
  constexpr RandomStream() noexcept : RandomStream(0, 0, 0, 0) {}

  /// The stream of one sample: seed, pixel column x, pixel row y and the sample's index in its
  /// pixel. Any change of any coordinate gives an unrelated stream.
  constexpr RandomStream(std::uint64_t seed, std::uint32_t x, std::uint32_t y,
                         std::uint32_t sample) noexcept
      : key_(mix64(mix64(mix64(seed + GAMMA) ^ (std::uint64_t{x} | std::uint64_t{y} << 32)) ^
                   sample)) {}

  /// 64 random bits of dimension d. Pure: the cursor does not move.
  constexpr std::uint64_t bits(std::uint32_t d) const noexcept {
    return mix64(key_ + (std::uint64_t{d} + 1) * GAMMA);
  }

  /// The number of dimension d, uniform in [0, 1) with 53 random bits. Pure.
  constexpr double uniform(std::uint32_t d) const noexcept {
    return static_cast<double>(bits(d) >> 11) * 0x1p-53;
  }

  /// uniform(dimension()), then the cursor moves to the next dimension.
  constexpr double next() noexcept { return uniform(dimension_++); }

  /// Two numbers: next(), next().
  constexpr Sample2 next2D() noexcept {
    const double u = next();
    return {u, next()};
  }

  /// The dimension next() reads.
  constexpr std::uint32_t dimension() const noexcept { return dimension_; }
  /// Moves the cursor to dimension d (to re-read numbers, or to give a technique a fixed block
  /// of dimensions).
  constexpr void setDimension(std::uint32_t d) noexcept { dimension_ = d; }

  constexpr bool operator==(const RandomStream&) const noexcept = default;

 private:
  std::uint64_t key_;
  std::uint32_t dimension_ = 0;
};

/// A point jittered inside cell (i, j) of an n × n grid over the unit square:
/// ((i + u)/n, (j + v)/n) with (u, v) = r.next2D(). Stratified sampling: every cell receives
/// exactly one point, so n² points cover the square far more evenly than n² independent ones.
/// i and j in [0, n), n >= 1 (not checked: per-sample code).
inline Sample2 jitteredCell(int i, int j, int n, RandomStream& r) noexcept {
  const Sample2 s = r.next2D();
  return {(i + s.u) / n, (j + s.v) / n};
}

/// The unit square onto the unit disk, area-preserving and continuous (Shirley and Chiu's
/// concentric mapping, 1997): squares around the centre go to rings, so stratified points of the
/// square stay stratified on the disk. (0.5, 0.5) goes to the centre; the result (u, v) is the
/// point (u, v) of the disk x² + y² <= 1.
Sample2 squareToDisk(const Sample2& s) noexcept;

/// Point k of n evenly spread points of the unit disk, shifted by `shift`: the golden-ratio
/// lattice of the unit square, ((k + ½)/n, k·φ⁻¹) with φ⁻¹ = (√5 − 1)/2, moved by `shift` modulo 1
/// (a Cranley–Patterson rotation, so that each set of n points is a random one and their mean is
/// unbiased), then squareToDisk. One shift per set: a light's disk for a shadow beam, a lens for
/// a pixel's cell. k in [0, n), n >= 1, shift in [0, 1)² (not checked: per-sample code).
Sample2 diskLatticePoint(int k, int n, const Sample2& shift) noexcept;

}  // namespace rt
