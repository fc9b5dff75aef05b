#pragma once
/// @file FloatRay.h
/// The wide BVH's ray-box test in single precision, four boxes at once, and why it never
/// misses a box that the exact test hits.
///
/// The test is SlabRay.h's (Kay and Kajiya's slabs, the inverse direction computed once per
/// ray), but in float, so that one SSE instruction handles the four children of a wide node:
///
///     t_in_a  = fl( fl(near_a − oIn_a)  · invIn_a  )     tNear = max(0,     t_in_x,  t_in_y,
///     t_in_z) t_out_a = fl( fl(far_a  − oOut_a) · invOut_a )     tFar  = min(limit, t_out_x,
///     t_out_y, t_out_z)
///                                                        hit  <=>  tNear <= tFar
///
/// where near_a and far_a are the box's bounds on axis a in the order the ray meets them (lo
/// then hi when d_a is positive, its sign bit clear), and fl() is float rounding to nearest. The
/// box bounds are floats already (FloatBox.h); the ray's double origin o, its inverse direction
/// and the limit are rounded once per ray, each in the direction that widens the interval:
///
///  - oIn_a is a float at or beyond o_a towards the far side (>= o_a when d_a > 0, <= o_a when
///    d_a < 0), oOut_a one at or beyond it towards the near side; so near_a − oIn_a and
///    far_a − oOut_a are, in real numbers, on the near side of the exact near_a − o_a and
///    far_a − o_a;
///  - invIn_a is fl((1/d_a)·(1 − C)), clamped to ±FLT_MAX, invOut_a is fl((1/d_a)·(1 + C))
///    (±∞ beyond the float range), with C = 8·2^-24, the products computed in double;
///  - limit is the double limit rounded up.
/// (Rounding to nearest, with a margin that outweighs it, rather than directed rounding: the
/// margins are added without a branch, and the ray's setup costs a few nanoseconds, where
/// choosing a direction per number cost 30, more than testing the boxes: see FloatRay below.)
///
/// **Claim**: whenever the exact interval is not empty (exact tNear <= exact tFar, computed in
/// real numbers from the double ray and the float box), the computed one is not empty either.
///
/// **Proof.** Write u = 2^-24 (float's unit roundoff) and p for a product before its final
/// rounding, so that t = fl(p). Take an axis with d > 0 (d < 0 is its mirror image).
///  1. Entering: let e = near − o be exact, e' = near − oIn <= e. If e <= 0 then e' <= 0, fl(e')
///     <= 0 (rounding keeps the sign) and p_in <= 0: the axis leaves tNear at 0 or below, and
///     exact tNear >= 0 too. If e > 0 and e' > 0: fl(e') <= e'(1 + u) <= e(1 + u) and invIn <=
///     (1/d)(1 − C)(1 + 2^-52)(1 + u) (two double roundings of 1/d·(1 − C), then the float
///     one), so p_in <= (e/d)·(1 + u)²(1 − 8u)(1 + 2^-52) < e/d.
///     If e' <= 0 < e, p_in <= 0 < e/d. In every case max(0, p_in) <= max(0, exact t_in).
///     Clamping invIn to FLT_MAX only lowers it further.
///  2. Leaving: let x = far − o, x' = far − oOut >= x. If the exact interval is not empty, x >= 0,
///     so x' >= 0 and fl(x') >= x'(1 − u) >= x(1 − u); invOut >= (1/d)(1 + C)(1 − 2^-52)(1 − u),
///     so p_out >= (x/d)·(1 − u)²(1 + 8u)(1 − 2^-52) > x/d (or +∞, the same conclusion).
///  3. So, for the real numbers before the last rounding: every max(0, p_in_a) <= exact tNear
///     <= exact tFar <= every p_out_b, and exact tFar <= limit <= limitF. Rounding to nearest is
///     monotone (x <= y implies fl(x) <= fl(y), ±∞ included), so fl(p_in_a) <= fl(p_out_b),
///     fl(p_in_a) <= limitF (a float, its own rounding) and 0 <= fl(p_out_b): the computed
///     tNear <= tFar. Overflow and underflow are covered by the same monotony: a product beyond
///     FLT_MAX becomes +∞ on both sides alike, a subnormal rounds the same way for both.
///     (The subtractions' results are exact when subnormal, so their bound holds there too.)
///  4. NaN: a ray parallel to a slab (d = ±0) has invOut = ±∞, and fl(x')·∞ is NaN when
///     x' = 0. max and min below take the new value as their first operand, and SSE's maxps and
///     minps return the second operand when either is NaN: a NaN leaves tNear or tFar as it was,
///     which is the exact test's "no constraint from this axis" (the origin on the slab's
///     bound lies in the closed slab). invIn is finite, so the entering side never makes a NaN.
///     A parallel ray outside the slab gives ±∞ and a miss, or, within a rounding of the bound,
///     an inside verdict: conservative, never a miss of a box the exact test hits.
///
/// The entry point returned, tNear, is at most the exact entry (part 1): a closest-hit walk that
/// prunes a child whose entry lies beyond the best hit so far never prunes one that the double
/// test would keep. The leaves are tested with the exact double solvers, so the hits, and the
/// image's bits, are those of the linear scan.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "bvh/FloatBox.h"
#include "primitives/Ray.h"

namespace rt {

/// A ray prepared for the wide BVH's float box tests (see the file comment).
struct FloatRay {
  /// C of the file comment: the relative widening of the inverse direction.
  static constexpr double WIDEN = 8 * 0x1p-24;
  /// A coordinate o is moved by |o|·2^-22 + 2^-126 before it is rounded to the nearest float:
  /// more than the rounding's error (at most 2^-24 of the result, or 2^-150 among the
  /// subnormals), so the float lies on the side it was moved to. Coordinates beyond
  /// ORIGIN_RANGE (no scene has them) take the exact, slower directed rounding instead.
  static constexpr double ORIGIN_MARGIN = 0x1p-22;
  static constexpr double ORIGIN_FLOOR = 0x1p-126;
  static constexpr double ORIGIN_RANGE = 1e37;

  std::array<float, 3> originIn;   ///< o moved towards the far side of each slab
  std::array<float, 3> originOut;  ///< o moved towards the near side
  std::array<float, 3> invIn;      ///< fl((1/d)(1 − WIDEN)), within ±FLT_MAX
  std::array<float, 3> invOut;     ///< fl((1/d)(1 + WIDEN)), ±∞ beyond
  std::array<bool, 3> negative;    ///< signbit(1/d_a): the ray meets hi before lo on axis a

  explicit FloatRay(const Ray& ray) noexcept {
    const Double3& o = ray.head().xyz();
    const Double3& d = ray.direction().xyz();
    const std::array<double, 3> origin{o.x, o.y, o.z};
    const std::array<double, 3> inv{1 / d.x, 1 / d.y, 1 / d.z};
    constexpr double max = std::numeric_limits<float>::max();
    constexpr float inf = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a) {
      negative[a] = std::signbit(inv[a]);
      // Selections by index, not by branch: the signs are as random as the rays.
      std::array<float, 2> upDown;
      if (std::abs(origin[a]) <= ORIGIN_RANGE) {
        const double margin = std::abs(origin[a]) * ORIGIN_MARGIN + ORIGIN_FLOOR;
        upDown = {static_cast<float>(origin[a] + margin), static_cast<float>(origin[a] - margin)};
      } else {
        upDown = {floatAbove(origin[a]), floatBelow(origin[a])};
      }
      originIn[a] = upDown[negative[a]];
      originOut[a] = upDown[!negative[a]];
      invIn[a] = static_cast<float>(std::clamp(inv[a] * (1 - WIDEN), -max, max));
      const double out = inv[a] * (1 + WIDEN);
      invOut[a] = std::abs(out) <= max ? static_cast<float>(out)
                                       : std::copysign(inf, static_cast<float>(out));
    }
  }
};

/// The float limit for a double one: rounded up, so that the float test keeps every box the
/// double test keeps within it.
inline float floatLimit(double limit) noexcept { return floatAbove(limit); }

}  // namespace rt
