#include "geometries/Sphere.h"

#include "primitives/Checks.h"

namespace rt {

Sphere::Sphere(const Point& center, double radius)
    : center_(requireFinite(center.xyz(), "Sphere", "center")),
      radius_(requirePositive(radius, "Sphere", "radius")) {}

Vector Sphere::normal(const Point& p) const {
  // BEGIN SOLUTION: hint: Sphere::normal, n = normalize(P - center)
  return (p - center_).normalized();
  // END SOLUTION
}

std::optional<Vector> Sphere::tryNormal(const Point& p) const noexcept {
  // BEGIN SOLUTION: hint: Sphere::tryNormal, the normal or nullopt at the centre; never throws
  const Double3 d = p.xyz() - center_.xyz();
  if (d.isExactlyZero()) return std::nullopt;
  return Vector::unchecked(d).normalized();
  // END SOLUTION
}

}  // namespace rt
