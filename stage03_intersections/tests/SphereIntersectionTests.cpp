// Stage 3: ray-sphere intersections (the course's SphereTests, TC01-TC22, the 5785 variant and
// the maximum-distance cases). Sphere centre (1,0,0), radius 1.
#include <gtest/gtest.h>

#include <cmath>

#include "geometries/Sphere.h"
#include "intersections/Intersect.h"

#include "ExpectHits.h"

namespace rt {
namespace {

using test::hits;

const Sphere kSphere(Point(1, 0, 0), 1);
// The course's expected points for the ray from (-1,0,0) along (3,1,0):
// (x-1)² + y² = 1 with (x,y) = (-1+3s, s) gives 10s² - 12s + 3 = 0, s = (6 ∓ √6)/10.
const Point gp1(0.0651530771650466, 0.355051025721682, 0);
const Point gp2(1.53484692283495, 0.844948974278318, 0);

TEST(SphereIntersectionTests, courseExpectedPoints) {
  // TC00: the given points are the hand-derived roots (guards the constants above)
  const double s1 = (6 - std::sqrt(6.0)) / 10;
  const double s2 = (6 + std::sqrt(6.0)) / 10;
  EXPECT_TRUE(test::near(gp1, Point(-1 + 3 * s1, s1, 0), 1e-14));
  EXPECT_TRUE(test::near(gp2, Point(-1 + 3 * s2, s2, 0), 1e-14));
}

TEST(SphereIntersectionTests, equivalencePartitions) {
  // TC01: the line is outside the sphere (0 points)
  EXPECT_TRUE(hits(kSphere, Ray(Point(-1, 0, 0), Vector(1, 1, 0)), {}));
  // TC02: the ray starts before and crosses the sphere (2 points)
  EXPECT_TRUE(hits(kSphere, Ray(Point(-1, 0, 0), Vector(3, 1, 0)), {gp1, gp2}));
  // TC03: the ray starts inside the sphere (1 point)
  EXPECT_TRUE(hits(kSphere, Ray(Point(1, 0.5, 0), Vector(0, 1, 0)), {Point(1, 1, 0)}));
  EXPECT_TRUE(hits(kSphere, Ray(Point(0.5, 0, 0), Vector(1, 0, 0)), {Point(2, 0, 0)}));
  // TC04: the ray starts after the sphere (0 points)
  EXPECT_TRUE(hits(kSphere, Ray(Point(3, 0, 0), Vector(3, 1, 0)), {}));
}

TEST(SphereIntersectionTests, boundaryCrossesNotThroughCentre) {
  // **** Group: the ray's line crosses the sphere (but not the centre)
  // TC11: the ray starts at the sphere and goes inside (1 point)
  EXPECT_TRUE(hits(kSphere, Ray(gp1, Vector(3, 1, 0)), {gp2}));
  // TC12: the ray starts at the sphere and goes outside (0 points)
  EXPECT_TRUE(hits(kSphere, Ray(gp2, Vector(3, 1, 0)), {}));
}

TEST(SphereIntersectionTests, boundaryThroughCentre) {
  // **** Group: the ray's line goes through the centre
  const Vector dir(1, 0, 0);
  // TC13: the ray starts before the sphere (2 points)
  EXPECT_TRUE(hits(kSphere, Ray(Point(-1, 0, 0), dir), {Point(0, 0, 0), Point(2, 0, 0)}));
  // TC14: the ray starts at the sphere and goes inside (1 point)
  EXPECT_TRUE(hits(kSphere, Ray(Point(0, 0, 0), dir), {Point(2, 0, 0)}));
  // TC15: the ray starts inside (1 point)
  EXPECT_TRUE(hits(kSphere, Ray(Point(0.5, 0, 0), dir), {Point(2, 0, 0)}));
  // TC16: the ray starts at the centre (1 point)
  EXPECT_TRUE(hits(kSphere, Ray(Point(1, 0, 0), dir), {Point(2, 0, 0)}));
  EXPECT_TRUE(hits(kSphere, Ray(Point(1, 0, 0), Vector(0, 3, 4)), {Point(1, 0.6, 0.8)}));
  // TC17: the ray starts at the sphere and goes outside (0 points)
  EXPECT_TRUE(hits(kSphere, Ray(Point(2, 0, 0), dir), {}));
  // TC18: the ray starts after the sphere (0 points)
  EXPECT_TRUE(hits(kSphere, Ray(Point(3, 0, 0), dir), {}));
}

TEST(SphereIntersectionTests, boundaryTangent) {
  // **** Group: the ray's line is tangent to the sphere (all tests 0 points)
  const Vector dir(0, 1, 0);
  // TC19: the ray starts before the tangent point
  EXPECT_TRUE(hits(kSphere, Ray(Point(0, -1, 0), dir), {}));
  // TC20: the ray starts at the tangent point
  EXPECT_TRUE(hits(kSphere, Ray(Point(0, 0, 0), dir), {}));
  // TC21: the ray starts after the tangent point
  EXPECT_TRUE(hits(kSphere, Ray(Point(0, 1, 0), dir), {}));
}

TEST(SphereIntersectionTests, boundarySpecial) {
  // **** Group: special cases
  // TC22: the ray's line is outside, orthogonal to the line from the head to the centre
  EXPECT_TRUE(hits(kSphere, Ray(Point(3, 0, 0), Vector(0, 1, 0)), {}));
  EXPECT_TRUE(hits(kSphere, Ray(Point(-1, 1, 0), Vector(1, 0, 0)), {}));
  // TC23 (5785 variant): the ray starts inside, orthogonal to the line from the head to the
  // centre: y² + 0.5² = 1 gives (0.5, √3/2, 0)
  EXPECT_TRUE(
      hits(kSphere, Ray(Point(0.5, 0, 0), Vector(0, 1, 0)), {Point(0.5, std::sqrt(0.75), 0)}));
  // TC24: the line passes just inside the tangent (1e-6 inside): two points close together
  const double y = std::sqrt(1 - (1 - 1e-6) * (1 - 1e-6));
  EXPECT_TRUE(hits(kSphere, Ray(Point(1e-6, -1, 0), Vector(0, 1, 0)),
                   {Point(1e-6, -y, 0), Point(1e-6, y, 0)}));
  // TC25: the line passes just outside the tangent (1e-6 outside): 0 points
  EXPECT_TRUE(hits(kSphere, Ray(Point(-1e-6, -1, 0), Vector(0, 1, 0)), {}));
}

TEST(SphereIntersectionTests, maxDistance) {
  // The ray from (-1,0,0) along (1,0,0) meets the sphere at t = 1 (0,0,0) and t = 3 (2,0,0).
  const Ray ray(Point(-1, 0, 0), Vector(1, 0, 0));
  // ============ Equivalence Partitions Tests ==============
  // TC01: the maximum distance is before the sphere (0 points)
  EXPECT_TRUE(hits(kSphere, ray, {}, 0.5));
  // TC02: the maximum distance is beyond the sphere (2 points)
  EXPECT_TRUE(hits(kSphere, ray, {Point(0, 0, 0), Point(2, 0, 0)}, 5));
  // TC03: the maximum distance is between the two points (1 point)
  EXPECT_TRUE(hits(kSphere, ray, {Point(0, 0, 0)}, 2));
  // =============== Boundary Values Tests ==================
  // TC11: the maximum distance is exactly the near point (inclusive: 1 point)
  EXPECT_TRUE(hits(kSphere, ray, {Point(0, 0, 0)}, 1));
  // TC12: the maximum distance is exactly the far point (inclusive: 2 points)
  EXPECT_TRUE(hits(kSphere, ray, {Point(0, 0, 0), Point(2, 0, 0)}, 3));
  // TC13: just short of the near point by 1e-9 (0 points)
  EXPECT_TRUE(hits(kSphere, ray, {}, 1 - 1e-9));
}

TEST(SphereIntersectionTests, bareDataSolver) {
  // intersectSphereRoots(centre, radius, ray) is the solver intersectRoots(Sphere) runs, on the
  // bare data of a sphere (a structure storing spheres compactly calls it): its roots are the
  // distances along the ray, t = tm ± th with tm = v·(O − P0) and th = √(r² − d²).
  const Double3 centre = kSphere.center().xyz();
  // ============ Equivalence Partitions Tests ==============
  // TC01: a ray crossing the sphere twice: v = (3,1,0)/√10, tm = 6/√10, d² = 4 − 3.6 = 0.4,
  // th = √0.6; the roots lead to the course's gp1 and gp2
  const Ray crossing(Point(-1, 0, 0), Vector(3, 1, 0));
  const Roots two = intersectSphereRoots(centre, 1, crossing);
  ASSERT_EQ(two.size(), 2);
  EXPECT_NEAR(two[0], 6 / std::sqrt(10.0) - std::sqrt(0.6), 1e-14);
  EXPECT_NEAR(two[1], 6 / std::sqrt(10.0) + std::sqrt(0.6), 1e-14);
  EXPECT_TRUE(crossing.point(two[0]) == Point(0.0651530771650466, 0.355051025721682, 0));
  EXPECT_TRUE(crossing.point(two[1]) == Point(1.53484692283495, 0.844948974278318, 0));
  // TC02: a ray from inside (one root): tm = −0.5, d = 0, th = 1, so t = 0.5 only (the other
  // root, −1.5, is behind the origin), to the top of the sphere (1, 1, 0)
  const Ray inside(Point(1, 0.5, 0), Vector(0, 1, 0));
  const Roots one = intersectSphereRoots(centre, 1, inside);
  ASSERT_EQ(one.size(), 1);
  EXPECT_EQ(one[0], 0.5);
  // TC03: a ray that misses (no root)
  const Ray missing(Point(-1, 0, 0), Vector(1, 1, 0));
  EXPECT_TRUE(intersectSphereRoots(centre, 1, missing).empty());
  // TC11: a ray from the centre (the one root r)
  const Ray fromCentre(Point(1, 0, 0), Vector(0, 0, 1));
  ASSERT_EQ(intersectSphereRoots(centre, 1, fromCentre).size(), 1);
  EXPECT_EQ(intersectSphereRoots(centre, 1, fromCentre)[0], 1.0);
}

}  // namespace
}  // namespace rt
