#include "geometries/Tube.h"

#include <stdexcept>

#include "Checks.h"
#include "primitives/Util.h"

namespace rt {

Tube::Tube(double radius, const Ray& axis)
    : radius_(detail::requirePositive(radius, "Tube", "radius")), axis_(axis) {}

Vector Tube::normal(const Point& p) const {
  // s is p's coordinate along the axis; O = P0 + s·dir is the axis point level with p. When s is
  // zero (p - P0 orthogonal to the axis) O is the axis head itself.
  const Double3& dir = axis_.direction().xyz();
  const Double3 fromHead = p.xyz() - axis_.head().xyz();
  const Double3 o = axis_.head().xyz() + dir * alignZero(dir.dot(fromHead));
  const Double3 n = p.xyz() - o;
  if (n.isZero()) {
    throw std::invalid_argument("Tube normal: the point " + p.xyz().str() +
                                " lies on the axis, where the normal is undefined");
  }
  return Vector(n).normalized();
}

}  // namespace rt
