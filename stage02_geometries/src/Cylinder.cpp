#include "geometries/Cylinder.h"

#include "Checks.h"
#include "primitives/Util.h"

namespace rt {

Cylinder::Cylinder(double radius, const Ray& axis, double height)
    : tube_(radius, axis), height_(detail::requirePositive(height, "Cylinder", "height")) {}

Vector Cylinder::normal(const Point& p) const {
  const Vector& dir = tube_.axis().direction();
  const double s = dir.xyz().dot(p.xyz() - tube_.axis().head().xyz());
  if (isZero(s)) return -dir;           // bottom base, its centre and its rim
  if (isZero(s - height_)) return dir;  // top base, its centre and its rim
  return tube_.normal(p);
}

}  // namespace rt
