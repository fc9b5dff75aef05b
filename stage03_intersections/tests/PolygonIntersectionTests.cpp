// Stage 3: ray-polygon intersections (catalogue PolygonTests, the bonus).
// Square (0,0,0),(4,0,0),(4,4,0),(0,4,0); every ray goes along (0,0,-1).
#include <gtest/gtest.h>

#include "geometries/Polygon.h"
#include "intersections/Intersect.h"

#include "ExpectHits.h"

namespace rt {
namespace {

using test::hits;

const Polygon kSquare({Point(0, 0, 0), Point(4, 0, 0), Point(4, 4, 0), Point(0, 4, 0)});
const Vector kDown(0, 0, -1);

TEST(PolygonIntersectionTests, equivalencePartitions) {
  // TC01: the ray passes inside the polygon (1 point)
  EXPECT_TRUE(hits(kSquare, Ray(Point(2, 2, 2), kDown), {Point(2, 2, 0)}));
  // TC02: outside, against an edge (0 points)
  EXPECT_TRUE(hits(kSquare, Ray(Point(2, 6, 1), kDown), {}));
  // TC03: outside, against a vertex (0 points)
  EXPECT_TRUE(hits(kSquare, Ray(Point(-1, -1, 1), kDown), {}));
  // TC04: a convex pentagon, oblique ray through its inside
  const Polygon pentagon(
      {Point(0, 0, 0), Point(2, 0, 0), Point(3, 2, 0), Point(1, 3, 0), Point(-1, 2, 0)});
  EXPECT_TRUE(hits(pentagon, Ray(Point(0, 1, 1), Vector(1, 0, -1)), {Point(1, 1, 0)}));
  // TC05: the pentagon missed beside its slanted edge (3,2)-(1,3)
  EXPECT_TRUE(hits(pentagon, Ray(Point(3, 3, 1), kDown), {}));
}

TEST(PolygonIntersectionTests, boundaryValues) {
  // TC11: the ray meets an edge (0 points)
  EXPECT_TRUE(hits(kSquare, Ray(Point(2, 0, 1), kDown), {}));
  // TC12: the ray meets a vertex (0 points)
  EXPECT_TRUE(hits(kSquare, Ray(Point(0, 0, 1), kDown), {}));
  // TC13: the ray meets an edge's continuation (0 points)
  EXPECT_TRUE(hits(kSquare, Ray(Point(5, 0, 1), kDown), {}));
  // TC14: the ray meets the last edge, (0,4)-(0,0), that closes the boundary (0 points)
  EXPECT_TRUE(hits(kSquare, Ray(Point(0, 2, 1), kDown), {}));
  // TC15: 1e-6 inside that closing edge (1 point)
  EXPECT_TRUE(hits(kSquare, Ray(Point(1e-6, 2, 1), kDown), {Point(1e-6, 2, 0)}));
}

TEST(PolygonIntersectionTests, maxDistance) {
  // The ray from (2,2,2) meets the square at t = 2, at (2,2,0).
  const Ray ray(Point(2, 2, 2), kDown);
  // TC01: the maximum distance is beyond the polygon (1 point)
  EXPECT_TRUE(hits(kSquare, ray, {Point(2, 2, 0)}, 3));
  // TC02: the maximum distance is before the polygon (0 points)
  EXPECT_TRUE(hits(kSquare, ray, {}, 1));
  // TC11: the maximum distance is exactly the polygon (inclusive: 1 point)
  EXPECT_TRUE(hits(kSquare, ray, {Point(2, 2, 0)}, 2));
}

}  // namespace
}  // namespace rt
