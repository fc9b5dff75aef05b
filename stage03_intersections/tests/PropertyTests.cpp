// Stage 3: property tests with fixed seeds.
//  1. A ray from a random point inside a closed shape (sphere, finite cylinder with caps, box
//     of six polygons; also the infinite tube) in a random direction hits it exactly once, on
//     its surface, and closestHit agrees.
//  2. A ray re-launched from a hit point along the same direction does not find that hit again:
//     its hits are exactly the remaining hits of the original ray (for every shape kind).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <vector>

#include "intersections/Geometries.h"
#include "intersections/Intersect.h"
#include "support/TestRandom.h"

#include "ExpectHits.h"

namespace rt {
namespace {

constexpr int kRays = 1000;

/// Uniform numbers, points and directions (support/TestRandom.h: the same on every compiler and
/// standard library), as stage 1's points and vectors.
class Sampler : public test::TestRandom {
 public:
  using TestRandom::TestRandom;
  Point inBox(const Point& lo, const Point& hi) {
    return Point(TestRandom::inBox(lo.xyz(), hi.xyz()));
  }
  /// A direction uniform on the unit sphere.
  Vector direction() { return Vector(TestRandom::direction()); }
};

/// A box of six outward-wound polygons.
Geometries box(const Point& lo, const Point& hi) {
  const double x0 = lo.x(), y0 = lo.y(), z0 = lo.z(), x1 = hi.x(), y1 = hi.y(), z1 = hi.z();
  Geometries g;
  g.add(Polygon({Point(x0, y0, z0), Point(x0, y1, z0), Point(x1, y1, z0), Point(x1, y0, z0)}),
        Polygon({Point(x0, y0, z1), Point(x1, y0, z1), Point(x1, y1, z1), Point(x0, y1, z1)}),
        Polygon({Point(x0, y0, z0), Point(x1, y0, z0), Point(x1, y0, z1), Point(x0, y0, z1)}),
        Polygon({Point(x0, y1, z0), Point(x0, y1, z1), Point(x1, y1, z1), Point(x1, y1, z0)}),
        Polygon({Point(x0, y0, z0), Point(x0, y0, z1), Point(x0, y1, z1), Point(x0, y1, z0)}),
        Polygon({Point(x1, y0, z0), Point(x1, y1, z0), Point(x1, y1, z1), Point(x1, y0, z1)}));
  return g;
}

using FindAll = std::function<std::vector<Point>(const Ray&)>;
using FindClosest = std::function<std::optional<double>(const Ray&)>;

template <typename Shape>
FindAll findAllOf(const Shape& shape) {
  return [&shape](const Ray& ray) { return findIntersections(shape, ray); };
}
template <typename Shape>
FindClosest closestOf(const Shape& shape) {
  return [&shape](const Ray& ray) { return closestHit(shape, ray); };
}
FindAll findAllOf(const Geometries& g) {
  return [&g](const Ray& ray) { return g.findIntersections(ray); };
}
FindClosest closestOf(const Geometries& g) {
  return [&g](const Ray& ray) -> std::optional<double> {
    const auto hit = g.closestHit(ray);
    return hit ? std::optional<double>(hit->t) : std::nullopt;
  };
}

/// Property 1 for one ray from an interior point: exactly one hit, on the surface (onSurface),
/// closestHit agreeing. Returns false (after reporting) on a violation.
bool hitsOnceFromInside(const FindAll& findAll, const FindClosest& closest, const Ray& ray,
                        const std::function<bool(const Point&)>& onSurface) {
  const std::vector<Point> points = findAll(ray);
  const std::optional<double> t = closest(ray);
  if (points.size() != 1 || !t) {
    ADD_FAILURE() << "expected exactly one hit from inside, got " << points.size() << " "
                  << test::describe(points) << " for " << ray;
    return false;
  }
  if (!onSurface(points[0])) {
    ADD_FAILURE() << "the hit " << points[0] << " is not on the surface, for " << ray;
    return false;
  }
  if (!test::near(ray.point(*t), points[0])) {
    ADD_FAILURE() << "closestHit t = " << *t << " disagrees with " << points[0] << " for " << ray;
    return false;
  }
  return true;
}

/// Property 2 for one ray: relaunched from each of its hits, the ray finds exactly the remaining
/// hits (so never the hit it starts on, and the nearest one at t well above 0). Returns the
/// number of relaunches made.
int checkRelaunches(const FindAll& findAll, const FindClosest& closest, const Ray& ray) {
  const std::vector<Point> points = findAll(ray);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Ray again(points[i], ray.direction());
    const std::vector<Point> rest(points.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                  points.end());
    const std::vector<Point> found = findAll(again);
    bool same = found.size() == rest.size();
    for (std::size_t k = 0; same && k < found.size(); ++k)
      same = test::near(found[k], rest[k], 1e-7);
    if (!same) {
      ADD_FAILURE() << "relaunched from hit " << i << " " << points[i] << " of " << ray
                    << ": expected " << test::describe(rest) << ", got " << test::describe(found);
      return -1;
    }
    const std::optional<double> t = closest(again);
    if (rest.empty() != !t.has_value() ||
        (t && (*t < 1e-6 || std::abs(*t - points[i].distance(rest[0])) > 1e-7))) {
      ADD_FAILURE() << "relaunched closestHit from " << points[i] << " of " << ray << " gave "
                    << (t ? *t : -1.0);
      return -1;
    }
  }
  return static_cast<int>(points.size());
}

/// Runs property 2 on kRays rays aimed from random heads in [-6,6]³ at random targets in the
/// box [lo,hi] around the shape; expects at least minRelaunches relaunches (not vacuous).
void relaunchProperty(const FindAll& findAll, const FindClosest& closest, unsigned seed,
                      const Point& lo, const Point& hi, int minRelaunches) {
  Sampler sampler(seed);
  int relaunches = 0;
  for (int i = 0; i < kRays; ++i) {
    const Point head = sampler.inBox(Point(-6, -6, -6), Point(6, 6, 6));
    const Point target = sampler.inBox(lo, hi);
    if (head.distance(target) < 1e-3) continue;
    const int n = checkRelaunches(findAll, closest, Ray(head, target - head));
    if (n < 0) return;  // reported
    relaunches += n;
  }
  EXPECT_GE(relaunches, minRelaunches);
}

// ---------------------------------------------------------------- property 1: from inside

TEST(PropertyTests, sphereHitOnceFromInside) {
  // TC01: 1000 rays from random interior points of a sphere in random directions
  const Sphere sphere(Point(1, -2, 0.5), 3);
  Sampler sampler(20240516);
  int checked = 0;
  while (checked < kRays) {
    const Point p = sampler.inBox(Point(-2, -5, -2.5), Point(4, 1, 3.5));
    if (p.distance(sphere.center()) >= 0.99 * 3) continue;
    const Ray ray(p, sampler.direction());
    if (!hitsOnceFromInside(findAllOf(sphere), closestOf(sphere), ray, [&](const Point& q) {
          return std::abs(q.distance(sphere.center()) - 3) < 1e-9;
        }))
      return;
    ++checked;
  }
}

TEST(PropertyTests, cylinderHitOnceFromInside) {
  // TC01: 1000 rays from random interior points of a slanted closed cylinder
  const Point base(0.5, 1, -1);
  const Vector axis = Vector(1, 2, 2).normalized();
  const double r = 1.5, h = 3;
  const Cylinder cylinder(r, Ray(base, axis), h);
  const Vector e1 = axis.cross(Vector(1, 0, 0)).normalized();
  const Vector e2 = axis.cross(e1);
  const auto onSurface = [&](const Point& q) {
    const Double3 d = q.xyz() - base.xyz();
    const double s = d.dot(axis.xyz());
    const double radial = std::sqrt((d - axis.xyz() * s).lengthSquared());
    const bool onSide = std::abs(radial - r) < 1e-9 && s > -1e-9 && s < h + 1e-9;
    const bool onCap = (std::abs(s) < 1e-9 || std::abs(s - h) < 1e-9) && radial < r + 1e-9;
    return onSide || onCap;
  };
  Sampler sampler(20240525);
  for (int i = 0; i < kRays; ++i) {
    const double s = sampler.uniform(0.01 * h, 0.99 * h);
    const double rho = 0.99 * r * std::sqrt(sampler.uniform(0, 1));
    const double phi = sampler.uniform(0, 2 * std::numbers::pi);
    const Point p(base.xyz() + axis.xyz() * s + e1.xyz() * (rho * std::cos(phi)) +
                  e2.xyz() * (rho * std::sin(phi)));
    if (!hitsOnceFromInside(findAllOf(cylinder), closestOf(cylinder), Ray(p, sampler.direction()),
                            onSurface))
      return;
  }
}

TEST(PropertyTests, tubeHitOnceFromInside) {
  // TC01: 1000 rays from random points inside an infinite tube (not parallel to its axis)
  const Point head(-1, 0.5, 2);
  const Vector axis = Vector(0, 1, 1).normalized();
  const Tube tube(0.75, Ray(head, axis));
  const Vector e1 = axis.cross(Vector(1, 0, 0)).normalized();
  const Vector e2 = axis.cross(e1);
  const auto onSurface = [&](const Point& q) {
    const Double3 d = q.xyz() - head.xyz();
    const Double3 radial = d - axis.xyz() * d.dot(axis.xyz());
    return std::abs(std::sqrt(radial.lengthSquared()) - 0.75) < 1e-9;
  };
  Sampler sampler(20240601);
  for (int i = 0; i < kRays; ++i) {
    const double rho = 0.99 * 0.75 * std::sqrt(sampler.uniform(0, 1));
    const double phi = sampler.uniform(0, 2 * std::numbers::pi);
    const Point p(head.xyz() + axis.xyz() * sampler.uniform(-5, 5) +
                  e1.xyz() * (rho * std::cos(phi)) + e2.xyz() * (rho * std::sin(phi)));
    if (!hitsOnceFromInside(findAllOf(tube), closestOf(tube), Ray(p, sampler.direction()),
                            onSurface))
      return;
  }
}

TEST(PropertyTests, polygonBoxHitOnceFromInside) {
  // TC01: 1000 rays from random interior points of a closed box of six polygons
  const Point lo(-1, 0, -0.5), hi(2, 1.5, 3);
  const Geometries g = box(lo, hi);
  const auto onSurface = [&](const Point& q) {
    const bool inside = q.x() > lo.x() - 1e-9 && q.x() < hi.x() + 1e-9 && q.y() > lo.y() - 1e-9 &&
                        q.y() < hi.y() + 1e-9 && q.z() > lo.z() - 1e-9 && q.z() < hi.z() + 1e-9;
    const bool onFace = std::abs(q.x() - lo.x()) < 1e-9 || std::abs(q.x() - hi.x()) < 1e-9 ||
                        std::abs(q.y() - lo.y()) < 1e-9 || std::abs(q.y() - hi.y()) < 1e-9 ||
                        std::abs(q.z() - lo.z()) < 1e-9 || std::abs(q.z() - hi.z()) < 1e-9;
    return inside && onFace;
  };
  Sampler sampler(20240608);
  for (int i = 0; i < kRays; ++i) {
    const Point p = sampler.inBox(Point(-0.97, 0.015, -0.465), Point(1.97, 1.485, 2.965));
    if (!hitsOnceFromInside(findAllOf(g), closestOf(g), Ray(p, sampler.direction()), onSurface))
      return;
  }
}

// ------------------------------------------------------- property 2: relaunch from a hit

TEST(PropertyTests, relaunchSphere) {
  // TC01: rays crossing a sphere (2 hits) or starting inside it (1 hit)
  const Sphere sphere(Point(0.5, -0.5, 1), 1.5);
  relaunchProperty(findAllOf(sphere), closestOf(sphere), 1, Point(-1, -2, -0.5), Point(2, 1, 2.5),
                   1000);
}

TEST(PropertyTests, relaunchPlane) {
  // TC01: rays crossing a tilted plane
  const Plane plane(Point(0, 0, 0.3), Vector(1, 2, 3));
  relaunchProperty(findAllOf(plane), closestOf(plane), 2, Point(-2, -2, -2), Point(2, 2, 2), 500);
}

TEST(PropertyTests, relaunchTriangle) {
  // TC01: rays aimed at a triangle's neighbourhood
  const Triangle triangle(Point(-1, -1, 0.5), Point(2, 0, -0.5), Point(0, 2, 1));
  relaunchProperty(findAllOf(triangle), closestOf(triangle), 3, Point(-1, -1, -0.5), Point(2, 2, 1),
                   250);
}

TEST(PropertyTests, relaunchPolygon) {
  // TC01: rays aimed at a convex pentagon's neighbourhood (in the plane z = 0.25x + 0.1y)
  const Polygon pentagon({Point(0, 0, 0), Point(2, 0, 0.5), Point(3, 2, 0.95), Point(1, 3, 0.55),
                          Point(-1, 2, -0.05)});
  relaunchProperty(findAllOf(pentagon), closestOf(pentagon), 4, Point(-1, 0, 0), Point(3, 3, 1),
                   250);
}

TEST(PropertyTests, relaunchTube) {
  // TC01: rays crossing a slanted tube
  const Tube tube(0.8, Ray(Point(0.2, 0.1, -0.3), Vector(1, -1, 2)));
  relaunchProperty(findAllOf(tube), closestOf(tube), 5, Point(-1, -1, -1), Point(1, 1, 1), 1000);
}

TEST(PropertyTests, relaunchCylinder) {
  // TC01: rays crossing a slanted closed cylinder through its side and its caps
  const Cylinder cylinder(1.2, Ray(Point(-0.5, 0.3, -1), Vector(0.2, 0.4, 1)), 2.5);
  relaunchProperty(findAllOf(cylinder), closestOf(cylinder), 6, Point(-2, -1.5, -1.5),
                   Point(1.5, 2, 2), 1000);
}

TEST(PropertyTests, relaunchPolygonBox) {
  // TC01: rays crossing a box of six polygons (a Geometries)
  const Geometries g = box(Point(-1, 0, -0.5), Point(2, 1.5, 3));
  relaunchProperty(findAllOf(g), closestOf(g), 7, Point(-1.5, -0.5, -1), Point(2.5, 2, 3.5), 1000);
}

}  // namespace
}  // namespace rt
