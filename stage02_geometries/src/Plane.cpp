#include "geometries/Plane.h"

#include <stdexcept>

#include "primitives/Checks.h"

namespace rt {

namespace {
Vector normalOf(const Point& p1, const Point& p2, const Point& p3) {
  // BEGIN SOLUTION: hint: normalOf, normalize((p2-p1) x (p3-p1)); collinear points throw
  // (p2 - p1) x (p3 - p1) is zero exactly when two points coincide or all three are collinear.
  const Double3 n = (p2.xyz() - p1.xyz()).cross(p3.xyz() - p1.xyz());
  if (n.isZero()) {
    throw std::invalid_argument("Plane: the points " + p1.xyz().str() + ", " + p2.xyz().str() +
                                ", " + p3.xyz().str() +
                                " do not define a plane (two coincide or all are collinear)");
  }
  if (!n.isFinite()) {
    throw std::invalid_argument("Plane: the normal of the points " + p1.xyz().str() + ", " +
                                p2.xyz().str() + ", " + p3.xyz().str() +
                                " overflows (coordinates too large)");
  }
  return Vector(n).normalized();
  // END SOLUTION
}
}  // namespace

// Coordinates so large that the normal overflows (|coordinate| beyond ~1e154) leave a NaN
// normal; both constructors refuse it rather than build a plane every ray misses.
Plane::Plane(const Point& q, const Vector& normal) : q_(q), normal_(normal.normalized()) {
  requireFinite(q_.xyz(), "Plane", "point");
  requireFinite(normal_.xyz(), "Plane", "normal");
}

Plane::Plane(const Point& p1, const Point& p2, const Point& p3)
    : q_(p1), normal_(normalOf(p1, p2, p3)) {
  requireFinite(q_.xyz(), "Plane", "point");
}

}  // namespace rt
