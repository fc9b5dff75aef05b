#include "bvh/BoundingBox.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace rt {

namespace {
Aabb boxOfPoints(std::span<const Point> points) noexcept {
  Aabb box;
  for (const Point& p : points) box.expand(p.xyz());
  return box;
}
}  // namespace

Aabb boundingBox(const Sphere& s) noexcept {
  // BEGIN SOLUTION: hint: boundingBox(Sphere), the centre -/+ r on every axis
  const Double3 r(s.radius());
  return Aabb(s.center().xyz() - r, s.center().xyz() + r);
  // END SOLUTION
}

Aabb boundingBox(const Triangle& t) noexcept { return boxOfPoints(t.vertices()); }

Aabb boundingBox(const Polygon& p) noexcept { return boxOfPoints(p.vertices()); }

Aabb boundingBox(const Cylinder& c) noexcept {
  // BEGIN SOLUTION: hint: boundingBox(Cylinder), the two cap discs' boxes, r*sqrt(1 - a_i^2)
  const Double3& a = c.axis().direction().xyz();
  const Double3& bottom = c.axis().head().xyz();
  const Double3 top = bottom + a * c.height();
  // max(0, ·): a unit axis may exceed 1 in a component by rounding.
  const auto halfWidth = [&c](double ai) {
    return c.radius() * std::sqrt(std::max(0.0, 1 - ai * ai));
  };
  const Double3 e(halfWidth(a.x), halfWidth(a.y), halfWidth(a.z));
  return Aabb(bottom - e, bottom + e).expand(Aabb(top - e, top + e));
  // END SOLUTION
}

std::optional<Aabb> boundingBox(const Plane&) noexcept { return std::nullopt; }

std::optional<Aabb> boundingBox(const Tube&) noexcept { return std::nullopt; }

std::optional<Aabb> boundingBox(const Geometry& g) noexcept {
  return std::visit([](const auto& shape) -> std::optional<Aabb> { return boundingBox(shape); }, g);
}

Aabb boundingBox(const TriangleMesh& mesh, std::size_t t) noexcept {
  return boxOfPoints(mesh.corners(t));
}

std::optional<Aabb> boundingBox(const Primitives& primitives, std::uint32_t primitive) noexcept {
  if (primitives.isShape(primitive)) return boundingBox(primitives.shapes()[primitive]);
  const MeshTriangle m = primitives.meshTriangle(primitive);
  return boundingBox(*primitives.meshes()[m.mesh].mesh, m.triangle);
}

}  // namespace rt
