#include "geometries/Cylinder.h"

#include "primitives/Checks.h"
#include "primitives/Util.h"

namespace rt {

Cylinder::Cylinder(double radius, const Ray& axis, double height)
    : tube_(radius, axis), height_(requirePositive(height, "Cylinder", "height")) {}

std::optional<Vector> Cylinder::baseNormal(const Point& p) const noexcept {
  const Vector& dir = tube_.axis().direction();
  const double s = dir.xyz().dot(p.xyz() - tube_.axis().head().xyz());
  if (isZero(s)) return -dir;           // bottom base, its centre and its rim
  if (isZero(s - height_)) return dir;  // top base, its centre and its rim
  return std::nullopt;
}

Vector Cylinder::normal(const Point& p) const {
  if (const std::optional<Vector> base = baseNormal(p)) return *base;
  return tube_.normal(p);
}

std::optional<Vector> Cylinder::tryNormal(const Point& p) const noexcept {
  if (const std::optional<Vector> base = baseNormal(p)) return base;
  return tube_.tryNormal(p);
}

}  // namespace rt
