#include "geometries/Plane.h"

#include <stdexcept>

namespace rt {

namespace {
Vector normalOf(const Point& p1, const Point& p2, const Point& p3) {
  // (p2 - p1) x (p3 - p1) is zero exactly when two points coincide or all three are collinear.
  const Double3 n = (p2.xyz() - p1.xyz()).cross(p3.xyz() - p1.xyz());
  if (n.isZero()) {
    throw std::invalid_argument("Plane: the points " + p1.xyz().str() + ", " + p2.xyz().str() +
                                ", " + p3.xyz().str() +
                                " do not define a plane (two coincide or all are collinear)");
  }
  return Vector(n).normalized();
}
}  // namespace

Plane::Plane(const Point& q, const Vector& normal) : q_(q), normal_(normal.normalized()) {}

Plane::Plane(const Point& p1, const Point& p2, const Point& p3)
    : q_(p1), normal_(normalOf(p1, p2, p3)) {}

}  // namespace rt
