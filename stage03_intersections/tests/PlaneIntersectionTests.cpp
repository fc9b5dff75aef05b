// Stage 3: ray-plane intersections (catalogue PlaneTests). Plane through (1,0,0), normal (0,0,1).
#include <gtest/gtest.h>

#include "geometries/Plane.h"
#include "intersections/Intersect.h"

#include "ExpectHits.h"

namespace rt {
namespace {

using test::hits;

const Plane kPlane(Point(1, 0, 0), Vector(0, 0, 1));

TEST(PlaneIntersectionTests, equivalencePartitions) {
  // TC01: the ray crosses the plane (1 point)
  EXPECT_TRUE(hits(kPlane, Ray(Point(1, 0, -1), Vector(1, 0, 1)), {Point(2, 0, 0)}));
  // TC02: the ray does not cross the plane (0 points)
  EXPECT_TRUE(hits(kPlane, Ray(Point(1, 0, 1), Vector(1, 0, 1)), {}));
  // TC03: a plane given by three points, crossed from above
  const Plane tilted(Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1));
  EXPECT_TRUE(
      hits(tilted, Ray(Point(1, 1, 1), Vector(-1, -1, -1)), {Point(1.0 / 3, 1.0 / 3, 1.0 / 3)}));
}

TEST(PlaneIntersectionTests, boundaryParallel) {
  // **** Group: the ray is parallel to the plane
  // TC11: the ray is outside the plane (0 points)
  EXPECT_TRUE(hits(kPlane, Ray(Point(1, 0, 1), Vector(1, 0, 0)), {}));
  // TC12: the ray is in the plane (0 points)
  EXPECT_TRUE(hits(kPlane, Ray(Point(2, 0, 0), Vector(1, 0, 0)), {}));
}

TEST(PlaneIntersectionTests, boundaryOrthogonal) {
  // **** Group: the ray is orthogonal to the plane
  // TC13: the ray starts on the plane (0 points)
  EXPECT_TRUE(hits(kPlane, Ray(Point(1, 0, 0), Vector(0, 0, 1)), {}));
  // TC14: the ray starts before the plane (1 point)
  EXPECT_TRUE(hits(kPlane, Ray(Point(1, 0, -1), Vector(0, 0, 1)), {Point(1, 0, 0)}));
  // TC15: the ray starts after the plane (0 points)
  EXPECT_TRUE(hits(kPlane, Ray(Point(1, 0, 1), Vector(0, 0, 1)), {}));
}

TEST(PlaneIntersectionTests, boundaryNeitherParallelNorOrthogonal) {
  // TC16: the ray starts on the plane (0 points)
  EXPECT_TRUE(hits(kPlane, Ray(Point(2, 0, 0), Vector(1, 0, 1)), {}));
  // TC17: the ray starts at the plane's reference point q (0 points)
  EXPECT_TRUE(hits(kPlane, Ray(Point(1, 0, 0), Vector(1, 1, 1)), {}));
  // TC18: almost parallel (slope 1e-6) crosses far away: t = 1/1e-6 along x
  EXPECT_TRUE(hits(kPlane, Ray(Point(0, 0, -1), Vector(1, 0, 1e-6)), {Point(1e6, 0, 0)}));
}

TEST(PlaneIntersectionTests, maxDistance) {
  // The ray from (2,0,1) along (0,0,-1) meets the plane at t = 1, at (2,0,0).
  const Ray ray(Point(2, 0, 1), Vector(0, 0, -1));
  // TC01: the maximum distance is beyond the plane (1 point)
  EXPECT_TRUE(hits(kPlane, ray, {Point(2, 0, 0)}, 2));
  // TC02: the maximum distance is before the plane (0 points)
  EXPECT_TRUE(hits(kPlane, ray, {}, 0.5));
  // TC11: the maximum distance is exactly the plane (inclusive: 1 point)
  EXPECT_TRUE(hits(kPlane, ray, {Point(2, 0, 0)}, 1));
}

}  // namespace
}  // namespace rt
