#include "intersections/Geometries.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "intersections/HitRules.h"

namespace rt {

std::uint32_t Geometries::add(Geometry shape) {
  if (primitiveCount() == MAX_PRIMITIVES)
    throw std::length_error("Geometries: no room for another shape (" + std::to_string(size()) +
                            " shapes and " + std::to_string(triangles_) +
                            " mesh triangles, at most " + std::to_string(MAX_PRIMITIVES) + ")");
  shapes_.push_back(std::move(shape));
  return static_cast<std::uint32_t>(shapes_.size() - 1);
}

std::uint32_t Geometries::addMesh(std::shared_ptr<const TriangleMesh> mesh) {
  if (mesh == nullptr) throw std::invalid_argument("Geometries::addMesh: the mesh is null");
  const std::uint64_t after = std::uint64_t{primitiveCount()} + mesh->triangleCount();
  if (after > MAX_PRIMITIVES)
    throw std::length_error("Geometries::addMesh: a mesh of " +
                            std::to_string(mesh->triangleCount()) + " triangles would make " +
                            std::to_string(after) + " primitives, at most " +
                            std::to_string(MAX_PRIMITIVES));
  meshes_.push_back(PlacedMesh{std::move(mesh), triangles_});
  triangles_ += static_cast<std::uint32_t>(meshes_.back().mesh->triangleCount());
  return static_cast<std::uint32_t>(meshes_.size() - 1);
}

Vector Geometries::hitNormal(std::uint32_t primitive, const Point& p,
                             const Vector& fallback) const noexcept {
  if (primitive < size()) return rt::hitNormal(shapes_[primitive], p, fallback);
  const MeshTriangle m = primitives().meshTriangle(primitive);
  return meshes_[m.mesh].mesh->normalAt(m.triangle, p);
}

Vector Geometries::normalAt(std::uint32_t primitive, const Point& p) const {
  if (primitive < size()) return rt::normalAt(shapes_[primitive], p);
  const MeshTriangle m = primitives().meshTriangle(primitive);
  return meshes_[m.mesh].mesh->normalAt(m.triangle, p);
}

std::optional<Hit> Geometries::closestHit(const Ray& ray, double tMax,
                                          QueryCounts* counts) const noexcept {
  NearestHit nearest(tMax);
  // BEGIN SOLUTION: hint: Geometries::closestHit, the smallest (t, index) within tMax (HitRules.h)
  for (std::uint32_t i = 0; i < shapes_.size(); ++i)
    nearest.offer(intersectRoots(shapes_[i], ray), i);
  if (counts != nullptr) counts->shapeTests += shapes_.size();
  // END SOLUTION
  // The meshes' triangles, by the same rule, numbered after the shapes.
  std::uint32_t primitive = size();
  for (const PlacedMesh& placed : meshes_)
    for (std::size_t t = 0; t < placed.mesh->triangleCount(); ++t)
      nearest.offer(intersectRoots(*placed.mesh, t, ray), primitive++);
  if (counts != nullptr) counts->shapeTests += triangles_;
  return nearest.hit();
}

bool Geometries::forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                            QueryCounts* counts) const {
  std::uint32_t tested = 0;
  bool complete = true;
  // BEGIN SOLUTION: hint: Geometries::forEachHit, each hit within tMax until visit says false
  for (std::uint32_t i = 0; i < shapes_.size() && complete; ++i) {
    ++tested;
    complete = visitHits(intersectRoots(shapes_[i], ray), i, tMax, visit);
  }
  // END SOLUTION
  // The meshes' triangles, by the same rule, numbered after the shapes.
  std::uint32_t primitive = size();
  for (std::size_t m = 0; m < meshes_.size() && complete; ++m) {
    const TriangleMesh& mesh = *meshes_[m].mesh;
    for (std::size_t t = 0; t < mesh.triangleCount() && complete; ++t) {
      ++tested;
      complete = visitHits(intersectRoots(mesh, t, ray), primitive++, tMax, visit);
    }
  }
  if (counts != nullptr) counts->shapeTests += tested;
  return complete;
}

void Intersectable::closestHits(std::span<const Ray> rays, double tMax,
                                std::span<std::optional<Hit>> hits,
                                QueryCounts* counts) const noexcept {
  for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = closestHit(rays[i], tMax, counts);
}

std::vector<GeoPoint> Intersectable::findGeoIntersections(const Ray& ray,
                                                          double maxDistance) const {
  // BEGIN SOLUTION: hint: findGeoIntersections, every hit sorted by (t, geometry index)
  std::vector<GeoPoint> points;
  forEachHit(ray, maxDistance, [&](const Hit& hit) {
    points.push_back(GeoPoint{hit.geometry, ray.point(hit.t), hit.t});
    return true;
  });
  std::sort(points.begin(), points.end(), [](const GeoPoint& a, const GeoPoint& b) {
    return a.t < b.t || (a.t == b.t && a.geometry < b.geometry);
  });
  return points;
  // END SOLUTION
}

std::vector<Point> Intersectable::findIntersections(const Ray& ray, double maxDistance) const {
  std::vector<Point> points;
  for (const GeoPoint& gp : findGeoIntersections(ray, maxDistance)) points.push_back(gp.point);
  return points;
}

}  // namespace rt
