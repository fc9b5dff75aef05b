#include "geometries/Sphere.h"

#include "Checks.h"

namespace rt {

Sphere::Sphere(const Point& center, double radius)
    : center_(detail::requireFinite(center.xyz(), "Sphere", "center")),
      radius_(detail::requirePositive(radius, "Sphere", "radius")) {}

Vector Sphere::normal(const Point& p) const { return (p - center_).normalized(); }

}  // namespace rt
