#include "intersections/Geometries.h"

#include <algorithm>

namespace rt {

std::uint32_t Geometries::add(Geometry shape) {
  shapes_.push_back(std::move(shape));
  return static_cast<std::uint32_t>(shapes_.size() - 1);
}

std::optional<Hit> Geometries::closestHit(const Ray& ray, double tMax,
                                          QueryCounts* counts) const noexcept {
  // BEGIN SOLUTION: hint: Geometries::closestHit, the smallest (t, index) within tMax
  std::optional<Hit> best;
  for (std::uint32_t i = 0; i < shapes_.size(); ++i) {
    const Roots roots = intersectRoots(shapes_[i], ray);
    // Roots are ascending: the first is this shape's nearest. Shapes come in index order, so a
    // strictly nearer hit is needed to replace the best one: equal t keeps the smaller index.
    if (!roots.empty() && withinDistance(roots[0], tMax) && (!best || roots[0] < best->t))
      best = Hit{roots[0], i};
  }
  if (counts != nullptr) counts->shapeTests += shapes_.size();
  return best;
  // END SOLUTION
}

bool Geometries::forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                            QueryCounts* counts) const {
  // BEGIN SOLUTION: hint: Geometries::forEachHit, visit each hit within tMax until false
  std::uint32_t tested = 0;
  bool complete = true;
  for (std::uint32_t i = 0; i < shapes_.size() && complete; ++i) {
    ++tested;
    for (double t : intersectRoots(shapes_[i], ray)) {
      if (!withinDistance(t, tMax)) break;
      if (!visit(Hit{t, i})) {
        complete = false;
        break;
      }
    }
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
