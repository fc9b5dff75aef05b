#include "geometries/Sphere.h"

#include "primitives/Checks.h"

namespace rt {

Sphere::Sphere(const Point& center, double radius)
    : center_(requireFinite(center.xyz(), "Sphere", "center")),
      radius_(requirePositive(radius, "Sphere", "radius")) {}

Vector Sphere::normal(const Point& p) const { return (p - center_).normalized(); }

std::optional<Vector> Sphere::tryNormal(const Point& p) const noexcept {
  const Double3 d = p.xyz() - center_.xyz();
  if (d.x == 0 && d.y == 0 && d.z == 0) return std::nullopt;
  return Vector::unchecked(d).normalized();
}

}  // namespace rt
