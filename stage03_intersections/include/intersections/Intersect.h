#pragma once
/// @file Intersect.h
/// Ray-shape intersection, one root solver per shape.
///
/// Each solver returns the ray parameters t of the ray's crossings with the shape, keeping only
/// t > 0 after alignZero (a ray that starts on a surface does not hit it there), in ascending
/// order. Both queries of this stage are built on these solvers, so the maths exists once:
///  - findIntersections: every crossing as a Point, sorted by distance (the course's API);
///  - closestHit: the smallest t within (0, tMax] (what the renderer uses; no allocation).
/// The maximum distance is inclusive: a crossing exactly at tMax counts.

#include <limits>
#include <optional>
#include <span>
#include <vector>

#include <cstddef>

#include "geometries/Geometry.h"
#include "geometries/TriangleMesh.h"
#include "primitives/Ray.h"
#include "primitives/Util.h"

namespace rt {

inline constexpr double INFINITE_DISTANCE = std::numeric_limits<double>::infinity();

/// Up to four ray parameters, ascending, all > 0. Stack storage only.
class Roots {
 public:
  static constexpr int CAPACITY = 4;
  /// Keeps t when alignZero(t) > 0, inserting it in ascending order.
  void add(double t) noexcept;
  int size() const noexcept { return count_; }
  bool empty() const noexcept { return count_ == 0; }
  double operator[](int i) const noexcept { return t_[i]; }
  const double* begin() const noexcept { return t_; }
  const double* end() const noexcept { return t_ + count_; }

 private:
  double t_[CAPACITY] = {};
  int count_ = 0;
};

/// True when t is within the inclusive maximum distance: alignZero(t - tMax) <= 0.
inline bool withinDistance(double t, double tMax) noexcept {
  return t <= tMax || alignZero(t - tMax) <= 0;
}

/// The parameter where the ray meets the plane through q with unit normal n, or NaN when the
/// ray is parallel to the plane (alignZero(n·dir) == 0), starts on it (n·(q − head) within
/// 8 ulps of the coordinates' size), or meets it behind its head (t < 0). Roots::add drops NaN
/// and t <= 0. What the plane's, the triangle's and the polygon's solvers share.
double planeT(const Double3& q, const Double3& n, const Ray& ray) noexcept;

/// The course's inside test for a convex polygon hit by the ray: with vi = Pi − P0 and
/// ni = vi × v(i+1), the ray passes inside iff dir·ni has the same sign for every edge. A zero
/// (the course's alignZero of dir·normalize(ni)) means the ray meets an edge or a vertex: a
/// miss. The triangle's and the polygon's solvers are planeT and this.
bool passesInside(std::span<const Point> vertices, const Ray& ray) noexcept;

/// The sphere's solver on its bare data, the centre's coordinates and the radius. It is what
/// intersectRoots(Sphere) runs; a structure that keeps spheres in a compact array of its own
/// (the BVH of mini project 2) calls it too, so both find the same roots, bit for bit.
Roots intersectSphereRoots(const Double3& centre, double radius, const Ray& ray) noexcept;

Roots intersectRoots(const Sphere& s, const Ray& ray) noexcept;
Roots intersectRoots(const Plane& p, const Ray& ray) noexcept;
Roots intersectRoots(const Triangle& t, const Ray& ray) noexcept;
Roots intersectRoots(const Polygon& p, const Ray& ray) noexcept;
Roots intersectRoots(const Tube& t, const Ray& ray) noexcept;
Roots intersectRoots(const Cylinder& c, const Ray& ray) noexcept;
Roots intersectRoots(const Geometry& g, const Ray& ray) noexcept;
/// Triangle t of a mesh: the roots a `Triangle` of the same three corners gives, bit for bit (the
/// same plane point, the mesh's flatNormal, the same inside test), computed from the shared
/// vertices. The unit normal is worked out per test (a square root) rather than stored, which
/// would cost 24 bytes per triangle.
Roots intersectRoots(const TriangleMesh& mesh, std::size_t t, const Ray& ray) noexcept;

/// The course's findIntersections: every crossing with t in (0, maxDistance], sorted by
/// distance from the ray's head; empty when there is none (the course returns null).
template <typename Shape>
std::vector<Point> findIntersections(const Shape& shape, const Ray& ray,
                                     double maxDistance = INFINITE_DISTANCE) {
  std::vector<Point> points;
  for (double t : intersectRoots(shape, ray))
    if (withinDistance(t, maxDistance)) points.push_back(ray.point(t));
  return points;
}

/// The nearest crossing's t within (0, tMax], if any.
template <typename Shape>
std::optional<double> closestHit(const Shape& shape, const Ray& ray,
                                 double tMax = INFINITE_DISTANCE) noexcept {
  const Roots roots = intersectRoots(shape, ray);
  if (!roots.empty() && withinDistance(roots[0], tMax)) return roots[0];
  return std::nullopt;
}

}  // namespace rt
