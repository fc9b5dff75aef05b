#pragma once
/// @file Plane.h

#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {

/// An infinite plane, stored as a point q on it and a unit normal n.
class Plane {
 public:
  /// @param normal any non-zero vector; stored normalised.
  Plane(const Point& q, const Vector& normal);
  /// The plane through three points, normal = normalize((p2 - p1) x (p3 - p1)).
  /// @throws std::invalid_argument when two points coincide or the three are collinear.
  Plane(const Point& p1, const Point& p2, const Point& p3);

  const Point& point() const { return q_; }
  const Vector& normal() const { return normal_; }
  /// The same normal everywhere; the point is ignored.
  const Vector& normal(const Point&) const { return normal_; }

 private:
  /// A Triangle keeps only its plane's normal and makes the plane from it when asked.
  friend class Triangle;
  /// The plane through q of a normal already unit (a normal this class made), not normalised
  /// again, so that it is the same bits.
  static Plane ofUnitNormal(const Point& q, const Vector& unitNormal) noexcept {
    return Plane(q, unitNormal, Unit{});
  }
  struct Unit {};
  Plane(const Point& q, const Vector& unitNormal, Unit) noexcept : q_(q), normal_(unitNormal) {}

  Point q_;
  Vector normal_;
};

}  // namespace rt
