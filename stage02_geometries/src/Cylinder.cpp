#include "geometries/Cylinder.h"

#include "primitives/Checks.h"
#include "primitives/Util.h"

namespace rt {

Cylinder::Cylinder(double radius, const Ray& axis, double height)
    : tube_(radius, axis), height_(requirePositive(height, "Cylinder", "height")) {}

std::optional<Vector> Cylinder::baseNormal(const Point& p) const noexcept {
  // BEGIN SOLUTION: hint: Cylinder::baseNormal, -dir on the bottom base, dir on the top, else none
  const Vector& dir = tube_.axis().direction();
  const double s = dir.xyz().dot(p.xyz() - tube_.axis().head().xyz());
  if (isZero(s)) return -dir;           // bottom base, its centre and its rim
  if (isZero(s - height_)) return dir;  // top base, its centre and its rim
  return std::nullopt;
  // END SOLUTION
}

Vector Cylinder::normal(const Point& p) const {
  // BEGIN SOLUTION: hint: Cylinder::normal, a base's normal on a base, else the tube's
  if (const std::optional<Vector> base = baseNormal(p)) return *base;
  return tube_.normal(p);
  // END SOLUTION
}

std::optional<Vector> Cylinder::tryNormal(const Point& p) const noexcept {
  // BEGIN SOLUTION: hint: Cylinder::tryNormal, as normal() but never throws
  if (const std::optional<Vector> base = baseNormal(p)) return base;
  return tube_.tryNormal(p);
  // END SOLUTION
}

}  // namespace rt
