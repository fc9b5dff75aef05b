#pragma once
/// @file RayOffset.h
/// Where a secondary ray (shadow, reflected, refracted) starts, so that it does not find the
/// surface it leaves.
///
/// A hit point computed in floating point lies a little off its surface, on either side. A ray
/// launched from it can hit that same surface again at a tiny t ("acne": speckled self-shadow).
/// The cure is to move the origin off the surface along the normal, to the side the new ray
/// goes to:
///
///            n                   dir·n > 0: shift along +n
///            ^    dir            dir·n <= 0: shift along −n (the course's rule)
///            |   /
///      P' =  o  /                P' = P ± ε·n
///            | /
///   ---------P------------ surface
///
/// How large ε must be depends on the size of the rounding error, which grows with the
/// magnitude of the coordinates (a double carries ~16 significant digits: at |x| ~ 1e8 one ulp
/// is ~1.5e-8). So the default offset is scale-aware:
///
///     ε(P) = relative · max(1, |P.x|, |P.y|, |P.z|),   relative = DEFAULT_RELATIVE = 1e-9
///
/// The course's fixed DELTA = 0.1 is kept as RayOffset::course(). A fixed ε fails at one end of
/// the scale or the other: too small for large coordinates (the shift is lost in the rounding
/// of P, acne comes back), too large for small details (the origin jumps over thin or nearby
/// objects: light leaks through a thin wall, a contact shadow disappears). See the README.

#include <algorithm>
#include <cmath>

#include "primitives/Point.h"
#include "primitives/Ray.h"
#include "primitives/Vector.h"

namespace rt {

class RayOffset {
 public:
  /// ε per unit of coordinate magnitude: ~4500 ulps of the coordinate, far above the rounding
  /// error of a hit point, far below any feature size a scene is drawn at.
  static constexpr double DEFAULT_RELATIVE = 1e-9;
  /// The course's absolute shift along the normal.
  static constexpr double COURSE_DELTA = 0.1;

  /// The t-range of a shadow ray, measured from the shifted origin: t in [tMin, tMax].
  struct Range {
    double tMin;
    double tMax;
  };

  /// The default: scale-aware with DEFAULT_RELATIVE.
  constexpr RayOffset() = default;

  /// ε(P) = relative · max(1, max|P_i|); shadow range [ε, d − ε].
  /// @throws std::invalid_argument unless relative is a positive finite number.
  static RayOffset scaled(double relative = DEFAULT_RELATIVE);
  /// ε = delta everywhere, with the course's shadow range (0, d], d measured from the unshifted
  /// point. @throws std::invalid_argument unless delta is a positive finite number.
  static RayOffset fixed(double delta);
  /// The course: fixed(COURSE_DELTA).
  static RayOffset course() { return fixed(COURSE_DELTA); }

  bool isScaled() const noexcept { return scaled_; }
  /// The relative factor (scale-aware) or the fixed delta.
  double amount() const noexcept { return amount_; }

  /// The shift ε at point p.
  double epsilon(const Point& p) const noexcept {
    if (!scaled_) return amount_;
    const Double3& c = p.xyz();
    return amount_ * std::max({1.0, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
  }

  /// p moved by ε(p) along +n when n·dir > 0, else along −n. n and dir unit vectors.
  Point shift(const Point& p, const Vector& n, const Vector& dir) const noexcept {
    const double e = n.dot(dir) > 0 ? epsilon(p) : -epsilon(p);
    return Point(p.xyz() + n.xyz() * e);
  }

  /// The secondary ray leaving p (on a surface of normal n) along the unit direction dir.
  Ray ray(const Point& p, const Vector& n, const Vector& dir) const noexcept {
    return Ray::withUnitDirection(shift(p, n, dir), dir);
  }

  /// The part of a shadow ray that may hold blockers, for a light at distance lightDistance from
  /// the unshifted point p (+infinity for a directional light). Scale-aware: [ε, d − ε], since
  /// the shift changes the distance to the light by at most ε, so d − ε never reaches past the
  /// light, and nothing closer than ε to the shifted origin is taken for a blocker. Fixed (the
  /// course): (0, d].
  Range shadowRange(const Point& p, double lightDistance) const noexcept {
    if (!scaled_) return {0.0, lightDistance};
    const double e = epsilon(p);
    return {e, lightDistance - e};
  }

  bool operator==(const RayOffset& o) const = default;

 private:
  constexpr RayOffset(bool scaled, double amount) : scaled_(scaled), amount_(amount) {}
  bool scaled_ = true;
  double amount_ = DEFAULT_RELATIVE;
};

}  // namespace rt
