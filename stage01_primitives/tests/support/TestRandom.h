#pragma once
/// @file TestRandom.h
/// Random numbers, points and directions for the tests' random scenes and rays, the same on every
/// compiler and standard library.
///
/// Two things make a seeded fixture differ between platforms, and this helper avoids both:
///  - std::uniform_real_distribution and std::uniform_int_distribution are not specified to the
///    bit: libstdc++, libc++ and MSVC turn the same engine output into different numbers. Here the
///    numbers come from the engine's own RandomStream (primitives/Random.h: SplitMix64, fully
///    specified), turned into doubles and integers by the formulas below.
///  - The order in which a call's arguments (or an operator's operands) are evaluated is
///    unspecified: `Double3(r.unit(), r.unit(), r.unit())` gets its three numbers in an order
///    that GCC and Clang choose differently. Every function here that draws more than one number
///    draws them in statements of their own; a test that draws several numbers must do the same
///    (one named variable per draw, or a braced list, whose elements C++ evaluates in order).

#include <cmath>
#include <cstdint>
#include <utility>

#include "primitives/Double3.h"
#include "primitives/Random.h"

namespace rt::test {

class TestRandom {
 public:
  /// The numbers of `seed`: those of RandomStream(seed, x, y, 0), in order (x and y give one seed
  /// unrelated streams, a test's per item say).
  explicit TestRandom(std::uint64_t seed, std::uint32_t x = 0, std::uint32_t y = 0) noexcept
      : stream_(seed, x, y, 0) {}

  /// Uniform in [0, 1), 53 random bits.
  double unit() noexcept { return stream_.next(); }
  /// lo + (hi − lo)·unit(): in [lo, hi] (hi itself only by the rounding of the product).
  double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * unit(); }
  /// An integer in [lo, hi], each with probability 1/(hi − lo + 1) to within 2^-52 (lo <= hi,
  /// and the range below 2^31: within a double's exact integers, unit()·range is below range).
  int integer(int lo, int hi) noexcept {
    const double range = static_cast<double>(hi) - lo + 1;
    return lo + static_cast<int>(unit() * range);
  }
  /// True with probability p.
  bool chance(double p) noexcept { return unit() < p; }
  /// +1 or −1, each with probability 1/2.
  double sign() noexcept { return chance(0.5) ? 1 : -1; }

  /// Uniform in the box [lo, hi]: x, then y, then z.
  Double3 inBox(const Double3& lo, const Double3& hi) noexcept {
    const double x = uniform(lo.x, hi.x);
    const double y = uniform(lo.y, hi.y);
    const double z = uniform(lo.z, hi.z);
    return Double3(x, y, z);
  }
  /// Uniform in the cube [lo, hi]³.
  Double3 inCube(double lo, double hi) noexcept { return inBox(Double3(lo), Double3(hi)); }
  /// Uniform on the unit sphere (rejection from the cube [−1, 1]³).
  Double3 direction() noexcept {
    for (;;) {
      const Double3 d = inCube(-1, 1);
      const double l2 = d.lengthSquared();
      if (l2 > 1e-4 && l2 <= 1) return d / std::sqrt(l2);
    }
  }

  /// Fisher–Yates: the elements of [first, last) in a random order (std::shuffle's algorithm
  /// is not specified, so its order differs between standard libraries).
  template <typename Iterator>
  void shuffle(Iterator first, Iterator last) noexcept {
    const auto n = static_cast<int>(last - first);
    for (int i = n - 1; i > 0; --i) {
      using std::swap;
      swap(first[i], first[integer(0, i)]);
    }
  }

 private:
  RandomStream stream_;
};

}  // namespace rt::test
