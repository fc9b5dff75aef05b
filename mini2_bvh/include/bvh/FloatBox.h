#pragma once
/// @file FloatBox.h
/// A box as the queries store it: six floats (24 bytes, half an Aabb, so that a BVH node fits in
/// 32 bytes), rounded outwards so that it never shrinks.
///
/// Trusting a box means: a shape whose box the ray misses, or whose box starts beyond a hit
/// already found, can be skipped without changing any answer. That holds when every t that the
/// shape's solver computes (stage 3, with its own rounding) falls inside the ray's interval
/// through the box. The exact box holds the exact surface; the computed hit points lie off the
/// surface by the solvers' rounding, which grows with the coordinates' size. So a shape's stored
/// box is its exact box padded by 2^-20 of its largest coordinate (about eight float ulps of that
/// coordinate), then rounded outwards to floats: conservativeBox below.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bvh/Aabb.h"

namespace rt {

struct FloatBox {
  std::array<float, 3> lo;
  std::array<float, 3> hi;

  /// The empty box (lo = +∞, hi = −∞), the identity of expand.
  static constexpr FloatBox empty() noexcept {
    constexpr float inf = std::numeric_limits<float>::infinity();
    return FloatBox{{inf, inf, inf}, {-inf, -inf, -inf}};
  }

  /// Grows the box to hold b: the union, exact (a minimum or maximum of floats is a float).
  constexpr FloatBox& expand(const FloatBox& b) noexcept {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], b.lo[a]);
      hi[a] = std::max(hi[a], b.hi[a]);
    }
    return *this;
  }

  /// The smallest float box holding b: each bound rounded outwards (down for lo, up for hi), so
  /// it is exact when the bounds are floats already; bounds beyond the float range become ±∞.
  static FloatBox enclosing(const Aabb& b) noexcept;

  /// The same box in double precision (exact: every float is a double).
  constexpr Aabb widen() const noexcept {
    return Aabb(Double3(lo[0], lo[1], lo[2]), Double3(hi[0], hi[1], hi[2]));
  }
};

/// The largest float <= x (-∞ below the float range, FLT_MAX above it). A double beyond the
/// float range must not be cast (undefined behaviour): it is clamped first. The step down is
/// done on the bits, without a branch (the next float towards −∞ of a positive float is its bit
/// pattern minus one, of a negative one its pattern plus one), not with std::nextafter, a
/// library call: the wide BVH rounds twelve numbers per ray with this.
inline float floatBelow(double x) noexcept {
  constexpr float max = std::numeric_limits<float>::max();
  constexpr float inf = std::numeric_limits<float>::infinity();
  if (x >= max) return max;
  if (x < -max) return -inf;
  const float f = static_cast<float>(x);  // round to nearest: may land above x
  // When f > x (then x >= −FLT_MAX keeps f above −FLT_MAX): a positive f steps down by one
  // bit pattern, a negative one up; f = ±0 means x is a negative number nearer to 0 than half
  // the smallest subnormal, whose float below is −(smallest subnormal), the pattern of −0 plus 1.
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t below = f > 0 ? bits - 1 : (bits | 0x8000'0000u) + 1;
  return f > x ? std::bit_cast<float>(below) : f;
}
/// The smallest float >= x (+∞ above the float range, -FLT_MAX below it).
inline float floatAbove(double x) noexcept { return -floatBelow(-x); }

/// The relative margin added to a shape's exact box before it is stored: 2^-20 of the largest
/// absolute coordinate of the box, on every side.
inline constexpr double BOX_MARGIN = 0x1p-20;

/// The box a query may trust for a shape whose exact box is `exact`: padded by BOX_MARGIN, then
/// rounded outwards to floats.
FloatBox conservativeBox(const Aabb& exact) noexcept;

}  // namespace rt
