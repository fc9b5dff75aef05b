// Stage 3: ray intersections with the finite, closed cylinder (side and both caps).
// Our own EP/BVA set; every expected point computed by hand.
//
// Cylinder radius 1 around the z axis from the bottom base z=0 to the top base z=2:
//
//        z=2  +-----+   top cap (rim: the circle x²+y²=1, z=2)
//             |     |
//             |     |   side: x²+y²=1, 0<z<2
//        z=0  +-----+   bottom cap
//            x=-1  x=1
//
// The course's boundary rule, as for the sphere and the polygons: a ray that only touches the
// surface without entering the solid (tangent to the side, grazing a rim, running along the
// side or the cap) does not intersect it. A ray entering or leaving through a rim meets the
// surface there once.
#include <gtest/gtest.h>

#include <cmath>

#include "geometries/Cylinder.h"
#include "intersections/Intersect.h"

#include "ExpectHits.h"

namespace rt {
namespace {

using test::hits;

const Cylinder kCylinder(1, Ray(Point(0, 0, 0), Vector(0, 0, 1)), 2);

TEST(CylinderIntersectionTests, equivalencePartitionsFromOutside) {
  // TC01: through both caps, oblique: (-0.5+s, 0, -1+4s) meets z=0 at s=1/4, z=2 at s=3/4
  EXPECT_TRUE(hits(kCylinder, Ray(Point(-0.5, 0, -1), Vector(1, 0, 4)),
                   {Point(-0.25, 0, 0), Point(0.25, 0, 2)}));
  // TC02: through the bottom cap and the side: (s, 0, -1+2s) meets z=0 at x=0.5, x=1 at z=1
  EXPECT_TRUE(
      hits(kCylinder, Ray(Point(0, 0, -1), Vector(1, 0, 2)), {Point(0.5, 0, 0), Point(1, 0, 1)}));
  // TC03: through the side and the top cap: (2-s, 0, s) meets x=1 at z=1, z=2 at x=0
  EXPECT_TRUE(
      hits(kCylinder, Ray(Point(2, 0, 0), Vector(-1, 0, 1)), {Point(1, 0, 1), Point(0, 0, 2)}));
  // TC04: through the side twice, perpendicular to the axis
  EXPECT_TRUE(
      hits(kCylinder, Ray(Point(-2, 0, 1), Vector(1, 0, 0)), {Point(-1, 0, 1), Point(1, 0, 1)}));
  // TC05: through the side twice, oblique: (-2+4s, 0, 0.5+s) meets x=-1 at z=0.75, x=1 at 1.25
  EXPECT_TRUE(hits(kCylinder, Ray(Point(-2, 0, 0.5), Vector(4, 0, 1)),
                   {Point(-1, 0, 0.75), Point(1, 0, 1.25)}));
  // TC06: the line crosses the infinite tube above the top base only (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(-2, 0, 3), Vector(1, 0, 0)), {}));
  // TC07: the line crosses the tube below the bottom and the top plane outside the cap
  EXPECT_TRUE(hits(kCylinder, Ray(Point(-2, 0, -1), Vector(1, 0, 0.1)), {}));
  // TC08: perpendicular to the axis, missing (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(-2, 2, 1), Vector(1, 0, 0)), {}));
  // TC09: the cylinder is behind the ray (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(-2, 0, 1), Vector(-1, 0, 0)), {}));
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0, 3), Vector(0, 0, 1)), {}));
}

TEST(CylinderIntersectionTests, equivalencePartitionsFromInside) {
  // TC10: from inside, out through the side (1 point)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0, 1), Vector(1, 0, 0)), {Point(1, 0, 1)}));
  // TC11: from inside, out through the top cap: (s, 0, 1+2s) meets z=2 at x=0.5
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0, 1), Vector(1, 0, 2)), {Point(0.5, 0, 2)}));
  // TC12: from inside, out through the bottom cap along the axis direction
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0.5, 0, 1), Vector(0, 0, -1)), {Point(0.5, 0, 0)}));
}

TEST(CylinderIntersectionTests, parallelToAxis) {
  // TC13: inside, through both caps (2 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0.5, 0, -1), Vector(0, 0, 1)),
                   {Point(0.5, 0, 0), Point(0.5, 0, 2)}));
  // TC14: on the axis, through both base centres (2 points)
  EXPECT_TRUE(
      hits(kCylinder, Ray(Point(0, 0, -1), Vector(0, 0, 1)), {Point(0, 0, 0), Point(0, 0, 2)}));
  // TC15: inside, from above going down (2 points, top first)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0.5, 5), Vector(0, 0, -1)),
                   {Point(0, 0.5, 2), Point(0, 0.5, 0)}));
  // TC16: outside the cylinder (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(2, 0, -1), Vector(0, 0, 1)), {}));
  // TC17 (BVA): on the side surface, touching only the two rims (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(1, 0, -1), Vector(0, 0, 1)), {}));
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, -1, 5), Vector(0, 0, -1)), {}));
  // TC18 (BVA): 1e-6 inside the side surface (2 points, on the caps next to the rims)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(1 - 1e-6, 0, -1), Vector(0, 0, 1)),
                   {Point(1 - 1e-6, 0, 0), Point(1 - 1e-6, 0, 2)}));
}

TEST(CylinderIntersectionTests, boundaryTouching) {
  // TC21: tangent to the side (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(-2, 1, 1), Vector(1, 0, 0)), {}));
  // TC22: grazing the top rim: (2-s, 0, 1+s) touches only (1,0,2), outside before, above after
  EXPECT_TRUE(hits(kCylinder, Ray(Point(2, 0, 1), Vector(-1, 0, 1)), {}));
  // TC23: grazing the bottom rim from below: (-s, 0, -1+s) touches only (-1,0,0), below the
  // bottom before, outside the side after
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0, -1), Vector(-1, 0, 1)), {}));
  // TC24: lying in the plane of the top cap, crossing the rim circle twice (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(-2, 0, 2), Vector(1, 0, 0)), {}));
  // TC25: lying in the plane of the bottom cap, starting inside the disc (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0, 0), Vector(0, 1, 0)), {}));
}

TEST(CylinderIntersectionTests, boundaryThroughRims) {
  // TC26: entering through the top rim and leaving through the bottom rim:
  // (2-s, 0, 3-s) is at (1,0,2) for s=1 and at (-1,0,0) for s=3; each met once
  EXPECT_TRUE(
      hits(kCylinder, Ray(Point(2, 0, 3), Vector(-1, 0, -1)), {Point(1, 0, 2), Point(-1, 0, 0)}));
  // TC27: starting on the top rim going in: leaves through the opposite bottom rim (1 point)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(1, 0, 2), Vector(-1, 0, -1)), {Point(-1, 0, 0)}));
  // TC28: from inside, out through the top rim (1 point)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0, 1), Vector(1, 0, 1)), {Point(1, 0, 2)}));
}

TEST(CylinderIntersectionTests, boundaryStartingOnTheSurface) {
  // TC31: on the top cap going out, along the axis and obliquely (0 points)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0.5, 0, 2), Vector(0, 0, 1)), {}));
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0.5, 0, 2), Vector(1, 0, 1)), {}));
  // TC32: on the top cap going in, along the axis: out through the bottom cap (1 point)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0.5, 0, 2), Vector(0, 0, -1)), {Point(0.5, 0, 0)}));
  // TC33: on the top cap's centre going in obliquely: (s, 0, 2-s) leaves the side at (1,0,1)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0, 2), Vector(1, 0, -1)), {Point(1, 0, 1)}));
  // TC34: at the bottom cap's centre going in along the axis (1 point)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(0, 0, 0), Vector(0, 0, 1)), {Point(0, 0, 2)}));
  // TC35: on the side going out (0 points) and going in (1 point)
  EXPECT_TRUE(hits(kCylinder, Ray(Point(1, 0, 1), Vector(1, 0, 0)), {}));
  EXPECT_TRUE(hits(kCylinder, Ray(Point(1, 0, 1), Vector(-1, 0, 0)), {Point(-1, 0, 1)}));
}

TEST(CylinderIntersectionTests, maxDistance) {
  // Through the side: from (-2,0,1) along +x, hits at t = 1 and t = 3.
  const Ray side(Point(-2, 0, 1), Vector(1, 0, 0));
  // TC01: the maximum distance cuts between the two hits (1 point)
  EXPECT_TRUE(hits(kCylinder, side, {Point(-1, 0, 1)}, 1.5));
  // TC02: before the cylinder (0 points)
  EXPECT_TRUE(hits(kCylinder, side, {}, 0.5));
  // TC03: beyond the cylinder (2 points)
  EXPECT_TRUE(hits(kCylinder, side, {Point(-1, 0, 1), Point(1, 0, 1)}, 10));
  // TC11: exactly the near hit (inclusive: 1 point)
  EXPECT_TRUE(hits(kCylinder, side, {Point(-1, 0, 1)}, 1));
  // TC12: exactly the far hit (inclusive: 2 points)
  EXPECT_TRUE(hits(kCylinder, side, {Point(-1, 0, 1), Point(1, 0, 1)}, 3));
  // Through both caps: from (0.5,0,-1) along +z, hits at t = 1 and t = 3.
  const Ray caps(Point(0.5, 0, -1), Vector(0, 0, 1));
  // TC04: between the caps (1 point)
  EXPECT_TRUE(hits(kCylinder, caps, {Point(0.5, 0, 0)}, 2));
  // TC13: exactly the top cap (inclusive: 2 points)
  EXPECT_TRUE(hits(kCylinder, caps, {Point(0.5, 0, 0), Point(0.5, 0, 2)}, 3));
}

TEST(CylinderIntersectionTests, generalAxis) {
  // Radius 2, height 4 along +x from (1,2,3): the solid 1 <= x <= 5, (y-2)²+(z-3)² <= 4.
  const Cylinder c(2, Ray(Point(1, 2, 3), Vector(5, 0, 0)), 4);
  // TC01: along the axis through both base centres
  EXPECT_TRUE(hits(c, Ray(Point(0, 2, 3), Vector(1, 0, 0)), {Point(1, 2, 3), Point(5, 2, 3)}));
  // TC02: across the axis through the side twice
  EXPECT_TRUE(hits(c, Ray(Point(3, 2, 10), Vector(0, 0, -1)), {Point(3, 2, 5), Point(3, 2, 1)}));
  // TC03: beside the cylinder, beyond the top base's plane (0 points)
  EXPECT_TRUE(hits(c, Ray(Point(6, 2, 10), Vector(0, 0, -1)), {}));
  // TC04: through the top cap then the side: (6-s, 2, 3+s) meets x=5 at z=4, z=5 at x=4
  EXPECT_TRUE(hits(c, Ray(Point(6, 2, 3), Vector(-1, 0, 1)), {Point(5, 2, 4), Point(4, 2, 5)}));
}

}  // namespace
}  // namespace rt
