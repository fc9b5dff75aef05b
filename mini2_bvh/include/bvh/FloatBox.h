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

/// The relative margin added to a shape's exact box before it is stored: 2^-20 of the largest
/// absolute coordinate of the box, on every side.
inline constexpr double BOX_MARGIN = 0x1p-20;

/// The box a query may trust for a shape whose exact box is `exact`: padded by BOX_MARGIN, then
/// rounded outwards to floats.
FloatBox conservativeBox(const Aabb& exact) noexcept;

}  // namespace rt
