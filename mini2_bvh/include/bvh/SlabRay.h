#pragma once
/// @file SlabRay.h
/// The ray-box test of the queries: Kay and Kajiya's slabs, with the inverse direction computed
/// once per ray (Williams et al. 2005), made robust the way pbrt does it.
///
/// A box is the intersection of three slabs lo_i <= x_i <= hi_i. The ray P0 + t·d is inside slab
/// i for t between (lo_i − P0_i)/d_i and (hi_i − P0_i)/d_i (swapped when d_i < 0); it meets the
/// box when the three intervals and [0, tMax] overlap:
///
///     tNear = max(0,    t_in_x,  t_in_y,  t_in_z)
///     tFar  = min(tMax, t_out_x, t_out_y, t_out_z)        hit  <=>  tNear <= tFar
///
///          x = lo_x        x = hi_x
///              |             |
///         ---- +-------------+ ---- y = hi_y
///              |     box     |
///         ---- +-------------+ ---- y = lo_y
///        P0 .  |             |
///            `-.-- t_in_x    |
///
/// Division is replaced by multiplication with 1/d_i, computed once per ray. Three details make
/// the test exact where it matters:
///  - d_i = ±0 (the ray is parallel to slab i): 1/d_i = ±∞, so the slab's t are ±∞ (the origin
///    outside the slab: a miss; inside: no constraint), or 0·∞ = NaN when the origin lies on a
///    bound; the comparisons are written so that a NaN leaves the interval as it is, which counts
///    the ray as inside the slab (conservative). The sign of 1/d_i (its sign bit, so −0 is
///    negative) decides which bound is entered first.
///  - Rounding: a t computed as (b − P0)·(1/d) has three roundings, so its relative error is at
///    most γ(3), γ(n) = n·u/(1 − n·u), u = 2^-53 (Higham). pbrt scales tFar by 1 + 2γ(3); here
///    t_in is scaled down as well, since a node is skipped when its entry lies beyond the best
///    hit, and a too-late entry would skip an equal-t hit of a smaller index. The scalings are
///    folded into the inverse direction, computed once per ray: 1/d_i·(1 − 2γ(4)) for entering,
///    1/d_i·(1 + 2γ(4)) for leaving. That makes four roundings (b − P0, 1/d, the scaling, the
///    product), and (1 − u)^4·(1 + 2γ(4)) > 1 > (1 + u)^4·(1 − 2γ(4)): the computed t_in never
///    exceeds the exact one, the computed t_out is never below it.
///  - The test never decides a NaN or a tie against the box: conservative means it may say "hit"
///    for a box the exact test just misses, never the reverse.
/// Direction components below 1/DBL_MAX (about 5.6e-309) make 1/d overflow to ±∞: such a ray is
/// treated as parallel to that slab.

#include <array>
#include <cmath>

#include "bvh/Aabb.h"
#include "bvh/FloatBox.h"
#include "primitives/Ray.h"
#include "primitives/Util.h"

namespace rt {

/// γ(n) = n·u/(1 − n·u), u = 2^-53: the bound on the relative error of n successive roundings.
constexpr double gamma(int n) noexcept {
  constexpr double u = 0x1p-53;
  return n * u / (1 - n * u);
}

/// A ray prepared for many box tests: its origin and 1/d_i, stored twice, scaled for rounding
/// (see the file comment): once slightly smaller, for the entering t, once slightly larger, for
/// the leaving t.
struct SlabRay {
  std::array<double, 3> origin;
  std::array<double, 3> invIn;   ///< (1/d_i)·(1 − 2γ(4)), ±∞ for d_i = ±0
  std::array<double, 3> invOut;  ///< (1/d_i)·(1 + 2γ(4)), ±∞ for d_i = ±0
  std::array<bool, 3> negative;  ///< signbit(1/d_i): the ray runs towards lower x_i

  explicit SlabRay(const Ray& ray) noexcept {
    constexpr double shrink = 1 - 2 * gamma(4);
    constexpr double grow = 1 + 2 * gamma(4);
    const Double3& o = ray.head().xyz();
    const Double3& d = ray.direction().xyz();
    origin = {o.x, o.y, o.z};
    const std::array<double, 3> inv{1 / d.x, 1 / d.y, 1 / d.z};
    for (int a = 0; a < 3; ++a) {
      invIn[a] = inv[a] * shrink;
      invOut[a] = inv[a] * grow;
      negative[a] = std::signbit(inv[a]);
    }
  }
};

/// The largest box entry that can still lead to a hit within tMax. withinDistance accepts
/// t - tMax below the course's zero threshold (2^-40); a box entered later holds no such hit.
inline double slabLimit(double tMax) noexcept { return tMax + 2 * ZERO_THRESHOLD; }

namespace detail {
/// Narrows [tNear, tFar] to slab lo <= x <= hi of one axis.
inline void clipSlab(double lo, double hi, double origin, double invIn, double invOut,
                     bool negative, double& tNear, double& tFar) noexcept {
  const double tIn = ((negative ? hi : lo) - origin) * invIn;
  const double tOut = ((negative ? lo : hi) - origin) * invOut;
  // Not std::max/min: a NaN tIn or tOut (0·∞) must leave the bound unchanged.
  tNear = tIn > tNear ? tIn : tNear;
  tFar = tOut < tFar ? tOut : tFar;
}
}  // namespace detail

/// True when the ray meets the box [lo, hi] at some t in [0, tMax] (conservatively: see the file
/// comment). On a hit, tEntry is where the ray enters the box (0 when it starts inside),
/// rounded down.
inline bool slabHit(const SlabRay& r, const Double3& lo, const Double3& hi, double tMax,
                    double& tEntry) noexcept {
  double tNear = 0;
  double tFar = tMax;
  detail::clipSlab(lo.x, hi.x, r.origin[0], r.invIn[0], r.invOut[0], r.negative[0], tNear, tFar);
  detail::clipSlab(lo.y, hi.y, r.origin[1], r.invIn[1], r.invOut[1], r.negative[1], tNear, tFar);
  detail::clipSlab(lo.z, hi.z, r.origin[2], r.invIn[2], r.invOut[2], r.negative[2], tNear, tFar);
  tEntry = tNear;
  return tNear <= tFar;
}

inline bool slabHit(const SlabRay& r, const Aabb& box, double tMax, double& tEntry) noexcept {
  return slabHit(r, box.lo, box.hi, tMax, tEntry);
}

/// The float box is widened to double exactly; the test runs in double precision.
inline bool slabHit(const SlabRay& r, const FloatBox& box, double tMax, double& tEntry) noexcept {
  return slabHit(r, box.widen(), tMax, tEntry);
}

}  // namespace rt
