// Stage 3: ray-triangle intersections (catalogue TriangleTests).
// Triangle (-2,0,0),(2,0,0),(0,4,0); every ray goes along (0,0,-1).
#include <gtest/gtest.h>

#include "geometries/Triangle.h"
#include "intersections/Intersect.h"

#include "ExpectHits.h"

namespace rt {
namespace {

using test::hits;

const Triangle kTriangle(Point(-2, 0, 0), Point(2, 0, 0), Point(0, 4, 0));
const Vector kDown(0, 0, -1);

TEST(TriangleIntersectionTests, equivalencePartitions) {
  // TC01: the ray passes inside the triangle (1 point)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(1, 1, 1), kDown), {Point(1, 1, 0)}));
  // TC02: outside, against an edge (0 points)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(4, 4, 1), kDown), {}));
  // TC03: outside, against a vertex (0 points)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(-2.5, -0.5, 1), kDown), {}));
  // TC04: inside, from below going up (the other side of the plane)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(-1, 1, -2), Vector(0, 0, 1)), {Point(-1, 1, 0)}));
  // TC05: inside, oblique ray
  EXPECT_TRUE(hits(kTriangle, Ray(Point(0, 0, 1), Vector(0, 1, -1)), {Point(0, 1, 0)}));
  // TC06: the ray starts beyond the triangle (0 points)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(1, 1, -1), kDown), {}));
}

TEST(TriangleIntersectionTests, boundaryValues) {
  // TC11: the ray meets an edge (0 points)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(1, 0, 1), kDown), {}));
  // TC12: the ray meets a vertex (0 points)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(2, 0, 1), kDown), {}));
  // TC13: the ray meets an edge's continuation (0 points)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(3, 0, 1), kDown), {}));
  // TC14: 1e-6 inside the edge y=0 (1 point)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(1, 1e-6, 1), kDown), {Point(1, 1e-6, 0)}));
  // TC15: the ray lies in the triangle's plane (0 points)
  EXPECT_TRUE(hits(kTriangle, Ray(Point(-5, 1, 0), Vector(1, 0, 0)), {}));
}

TEST(TriangleIntersectionTests, maxDistance) {
  // The ray from (1,1,1) meets the triangle at t = 1, at (1,1,0).
  const Ray ray(Point(1, 1, 1), kDown);
  // TC01: the maximum distance is beyond the triangle (1 point)
  EXPECT_TRUE(hits(kTriangle, ray, {Point(1, 1, 0)}, 2));
  // TC02: the maximum distance is before the triangle (0 points)
  EXPECT_TRUE(hits(kTriangle, ray, {}, 0.5));
  // TC11: the maximum distance is exactly the triangle (inclusive: 1 point)
  EXPECT_TRUE(hits(kTriangle, ray, {Point(1, 1, 0)}, 1));
}

}  // namespace
}  // namespace rt
