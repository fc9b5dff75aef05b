#pragma once
/// @file Aabb.h
/// An axis-aligned bounding box in double precision: the exact maths of boxes (union, surface
/// area, centroid, longest axis). What a query stores and trusts is a FloatBox (FloatBox.h),
/// made from an Aabb; the ray-box test is in SlabRay.h.

#include <algorithm>
#include <limits>

#include "primitives/Double3.h"

namespace rt {

/// Component `axis` (0 = x, 1 = y, 2 = z) of a triple.
constexpr double component(const Double3& v, int axis) noexcept {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/// The box [lo.x, hi.x] × [lo.y, hi.y] × [lo.z, hi.z], bounds included. The default box is
/// empty (lo = +∞, hi = −∞), the identity of the union: expanding it by a point gives that
/// point's box.
struct Aabb {
  static constexpr double INF = std::numeric_limits<double>::infinity();

  Double3 lo{INF, INF, INF};
  Double3 hi{-INF, -INF, -INF};

  constexpr Aabb() = default;
  constexpr Aabb(const Double3& lower, const Double3& upper) : lo(lower), hi(upper) {}

  /// True when the box holds no point (some lo > hi).
  constexpr bool isEmpty() const noexcept { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }

  /// Grows the box to hold p.
  constexpr Aabb& expand(const Double3& p) noexcept {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    return *this;
  }
  /// Grows the box to hold b (the union); an empty b changes nothing.
  constexpr Aabb& expand(const Aabb& b) noexcept {
    if (b.isEmpty()) return *this;
    return expand(b.lo).expand(b.hi);
  }

  /// hi − lo.
  constexpr Double3 extent() const noexcept { return hi - lo; }
  /// (lo + hi) / 2, the point the SAH sorts primitives by.
  constexpr Double3 centroid() const noexcept { return (lo + hi) * 0.5; }
  /// 2(dx·dy + dy·dz + dz·dx); 0 for an empty box. A flat box (a triangle's in a plane x =
  /// const) has the area of its two faces, a segment's box 0. By Crofton's formula, the chance
  /// that a random line meeting a convex body A also meets a convex body B inside it is
  /// SA(B)/SA(A): the surface-area heuristic's probabilities.
  constexpr double surfaceArea() const noexcept {
    if (isEmpty()) return 0;
    const Double3 d = extent();
    return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  /// The axis (0, 1, 2) along which the box is longest; the lower axis on a tie.
  constexpr int longestAxis() const noexcept {
    const Double3 d = extent();
    if (d.x >= d.y && d.x >= d.z) return 0;
    return d.y >= d.z ? 1 : 2;
  }
  /// True when p lies in the box (bounds included).
  constexpr bool contains(const Double3& p) const noexcept {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
  }
  /// True when b lies in the box; an empty b lies in every box.
  constexpr bool contains(const Aabb& b) const noexcept {
    return b.isEmpty() || (contains(b.lo) && contains(b.hi));
  }

  /// Exact comparison of the six bounds (not the course's approximate Double3 equality).
  constexpr bool operator==(const Aabb& o) const noexcept {
    return lo.x == o.lo.x && lo.y == o.lo.y && lo.z == o.lo.z && hi.x == o.hi.x && hi.y == o.hi.y &&
           hi.z == o.hi.z;
  }
};

/// The union of two boxes.
constexpr Aabb unite(Aabb a, const Aabb& b) noexcept { return a.expand(b); }

}  // namespace rt
