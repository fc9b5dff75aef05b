// Stage 2: Plane from three points and from point + normal (catalogue PlaneTests).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geometries/Plane.h"

#include "ExpectVector.h"

namespace rt {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using test::expectVector;

TEST(PlaneTests, constructorThreePoints) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: three points in general position; normal = normalize((p2-p1) x (p3-p1)) = (0,0,1)
  const Plane plane(Point(2, 3, 5), Point(5, 3, 5), Point(4, 5, 5));
  expectVector(plane.normal(), 0, 0, 1);
  EXPECT_EQ(plane.point(), Point(2, 3, 5));
  // =============== Boundary Values Tests ==================
  // TC11: three collinear points throw, naming the points
  EXPECT_THAT([] { Plane(Point(3, 4, 4), Point(5, 4, 4), Point(7, 4, 4)); },
              ThrowsMessage<std::invalid_argument>(
                  AllOf(HasSubstr("Plane"), HasSubstr("(3,4,4)"), HasSubstr("(7,4,4)"))));
  // TC12: p1 == p2 throws
  EXPECT_THROW(Plane(Point(3, 4, 4), Point(3, 4, 4), Point(7, 4, 4)), std::invalid_argument);
  // TC13: p1 == p3 throws
  EXPECT_THROW(Plane(Point(3, 4, 4), Point(7, 4, 4), Point(3, 4, 4)), std::invalid_argument);
  // TC14: p2 == p3 throws
  EXPECT_THROW(Plane(Point(7, 4, 4), Point(3, 4, 4), Point(3, 4, 4)), std::invalid_argument);
  // TC15: all three equal throws
  EXPECT_THROW(Plane(Point(3, 4, 4), Point(3, 4, 4), Point(3, 4, 4)), std::invalid_argument);
  // TC16: almost collinear (the third point off the line by 1e-3) is a plane
  EXPECT_NO_THROW(Plane(Point(3, 4, 4), Point(5, 4, 4), Point(7, 4.001, 4)));
}

TEST(PlaneTests, constructorPointNormal) {
  // TC01: the normal is stored normalised, the point as given
  const Plane plane(Point(1, 2, 3), Vector(0, 3, 4));
  expectVector(plane.normal(), 0, 0.6, 0.8);
  EXPECT_EQ(plane.point(), Point(1, 2, 3));
  // TC02: an already unit normal is unchanged, its sign kept
  expectVector(Plane(Point(0, 0, 0), Vector(0, 0, -1)).normal(), 0, 0, -1);
}

TEST(PlaneTests, constructorNonFinite) {
  // =============== Boundary Values Tests ==================
  // TC11: coordinates so large (1e200) that the cross product overflows: the normal would be
  // NaN, so the constructor refuses it
  EXPECT_THAT([] { Plane(Point(0, 0, 0), Point(1e200, 0, 0), Point(0, 1e200, 0)); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("Plane: the normal of the points (0,0,0), (1e+200,0,0), (0,1e+200,0) "
                            "overflows (coordinates too large)")));
  // TC12: a point at infinity
  EXPECT_THAT([] { Plane(Point(INFINITY, 0, 0), Vector(0, 0, 1)); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("Plane: point must be finite, got (inf,0,0)")));
  // TC14: a finite normal whose squared length overflows is still normalised correctly
  expectVector(Plane(Point(0, 0, 0), Vector(1e200, 0, 1e200)).normal(), std::sqrt(0.5), 0,
               std::sqrt(0.5));
}

TEST(PlaneTests, normal) {
  const Point p1(1, 0, 0);
  const Point p2(1, 1, 0);
  const Point p3(0, 0, 0);
  const Plane plane(p1, p2, p3);
  // TC01: the plane z=0 through (1,0,0),(1,1,0),(0,0,0): (0,1,0) x (-1,0,0) = (0,0,1)
  const Vector n = plane.normal(Point(5, 5, 0));
  expectVector(n, 0, 0, 1);
  // TC02: unit length and orthogonal to both edges
  EXPECT_NEAR(n.length(), 1.0, 1e-12);
  EXPECT_NEAR(n.dot(p2 - p1), 0.0, 1e-12);
  EXPECT_NEAR(n.dot(p3 - p1), 0.0, 1e-12);
  // TC03: the normal is the same at every point (the point is ignored)
  EXPECT_EQ(plane.normal(Point(-7, 3, 0)), plane.normal());
  // TC04: a tilted plane x+y+z=1: normal (1,1,1)/sqrt(3) up to the winding's sign
  const Plane tilted(Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1));
  const double k = 1 / std::sqrt(3.0);
  expectVector(tilted.normal(), k, k, k);
  // TC05: swapping two points flips the normal
  expectVector(Plane(p1, p3, p2).normal(), 0, 0, -1);
}

}  // namespace
}  // namespace rt
