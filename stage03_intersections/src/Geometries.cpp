#include "intersections/Geometries.h"

#include <algorithm>

#include "intersections/HitRules.h"

namespace rt {

std::uint32_t Geometries::add(Geometry shape) {
  shapes_.push_back(std::move(shape));
  return static_cast<std::uint32_t>(shapes_.size() - 1);
}

std::optional<Hit> Geometries::closestHit(const Ray& ray, double tMax,
                                          QueryCounts* counts) const noexcept {
  // BEGIN SOLUTION: hint: Geometries::closestHit, the smallest (t, index) within tMax (HitRules.h)
  NearestHit nearest(tMax);
  for (std::uint32_t i = 0; i < shapes_.size(); ++i)
    nearest.offer(intersectRoots(shapes_[i], ray), i);
  if (counts != nullptr) counts->shapeTests += shapes_.size();
  return nearest.hit();
  // END SOLUTION
}

bool Geometries::forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                            QueryCounts* counts) const {
  // BEGIN SOLUTION: hint: Geometries::forEachHit, visit each hit within tMax until false
  std::uint32_t tested = 0;
  bool complete = true;
  for (std::uint32_t i = 0; i < shapes_.size() && complete; ++i) {
    ++tested;
    complete = visitHits(intersectRoots(shapes_[i], ray), i, tMax, visit);
  }
  if (counts != nullptr) counts->shapeTests += tested;
  return complete;
  // END SOLUTION
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
