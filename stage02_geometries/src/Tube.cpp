#include "geometries/Tube.h"

#include <stdexcept>

#include "primitives/Checks.h"
#include "primitives/Util.h"

namespace rt {

Tube::Tube(double radius, const Ray& axis)
    : radius_(requirePositive(radius, "Tube", "radius")), axis_(axis) {}

Double3 Tube::radial(const Point& p) const noexcept {
  // BEGIN SOLUTION: hint: Tube::radial, P - O with O = P0 + t*dir, t = dir.(P - P0)
  // s is p's coordinate along the axis; O = P0 + s·dir is the axis point level with p. When s is
  // zero (p - P0 orthogonal to the axis) O is the axis head itself.
  const Double3& dir = axis_.direction().xyz();
  const Double3 fromHead = p.xyz() - axis_.head().xyz();
  const Double3 o = axis_.head().xyz() + dir * alignZero(dir.dot(fromHead));
  return p.xyz() - o;
  // END SOLUTION
}

Vector Tube::normal(const Point& p) const {
  // BEGIN SOLUTION: hint: Tube::normal, normalize(radial(p)); a point on the axis throws
  const Double3 n = radial(p);
  if (n.isZero()) {
    throw std::invalid_argument("Tube normal: the point " + p.xyz().str() +
                                " lies on the axis, where the normal is undefined");
  }
  return Vector(n).normalized();
  // END SOLUTION
}

std::optional<Vector> Tube::tryNormal(const Point& p) const noexcept {
  // BEGIN SOLUTION: hint: Tube::tryNormal, the normal or nullopt on the axis; never throws
  const Double3 n = radial(p);
  if (n.isExactlyZero()) return std::nullopt;
  return Vector::unchecked(n).normalized();
  // END SOLUTION
}

}  // namespace rt
