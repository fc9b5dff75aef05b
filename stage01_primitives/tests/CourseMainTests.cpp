// Stage 1: every check of the lecturer's stage-1 test program (catalogue §2, "Lecturer's
// stage-1 test program"), one GoogleTest per group of checks, in the program's order.
// Data: p1=(1,2,3), p2=(2,4,6), p3=(2,4,5); v1=(1,2,3), v1Opposite=(-1,-2,-3), v2=(-2,-4,-6),
// v3=(0,3,-2), v4=(1,2,2).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "primitives/Double3.h"
#include "primitives/Point.h"
#include "primitives/Util.h"
#include "primitives/Vector.h"

namespace rt {
namespace {

class CourseMainTests : public ::testing::Test {
 protected:
  const Point p1{1, 2, 3};
  const Point p2{2, 4, 6};
  const Point p3{2, 4, 5};
  const Vector v1{1, 2, 3};
  const Vector v1Opposite{-1, -2, -3};
  const Vector v2{-2, -4, -6};
  const Vector v3{0, 3, -2};
  const Vector v4{1, 2, 2};
};

TEST_F(CourseMainTests, zeroVectorConstructors) {
  // TC01: new Vector(0,0,0) must throw
  EXPECT_THROW(Vector(0, 0, 0), std::invalid_argument);
  // TC02: new Vector(Double3.ZERO) must throw
  EXPECT_THROW((void)Vector(Double3::ZERO), std::invalid_argument);
}

TEST_F(CourseMainTests, pointOperations) {
  // TC01: p2 - p1 = v1
  EXPECT_EQ(p2 - p1, v1);
  // TC02: p1 - p1 throws (zero vector)
  EXPECT_THROW((void)(p1 - p1), std::invalid_argument);
  // TC03: p1 + v1 = p2
  EXPECT_EQ(p1 + v1, p2);
  // TC04: p1 + v1Opposite = ZERO
  EXPECT_EQ(p1 + v1Opposite, Point::ZERO);
}

TEST_F(CourseMainTests, distances) {
  // TC01: distanceSquared and distance of a point to itself are 0
  EXPECT_TRUE(isZero(p1.distanceSquared(p1)));
  EXPECT_TRUE(isZero(p1.distance(p1)));
  // TC02: distanceSquared(p1,p3) = 9 in both directions
  EXPECT_TRUE(isZero(p1.distanceSquared(p3) - 9));
  EXPECT_TRUE(isZero(p3.distanceSquared(p1) - 9));
  // TC03: distance(p1,p3) = 3 in both directions
  EXPECT_TRUE(isZero(p1.distance(p3) - 3));
  EXPECT_TRUE(isZero(p3.distance(p1) - 3));
}

TEST_F(CourseMainTests, vectorLengths) {
  // TC01: |v4|^2 = 9
  EXPECT_TRUE(isZero(v4.lengthSquared() - 9));
  // TC02: |v4| = 3
  EXPECT_TRUE(isZero(v4.length() - 3));
}

TEST_F(CourseMainTests, vectorAddSubtract) {
  // TC01: v1 + v1Opposite throws (zero vector)
  EXPECT_THROW((void)(v1 + v1Opposite), std::invalid_argument);
  // TC02: v1 - v1 throws (zero vector)
  EXPECT_THROW((void)(v1 - v1), std::invalid_argument);
  // TC03: v1 + v2 = v1Opposite
  EXPECT_EQ(v1 + v2, v1Opposite);
  // TC04: v1 - v2 = (3,6,9)
  EXPECT_EQ(v1 - v2, Vector(3, 6, 9));
}

TEST_F(CourseMainTests, dotProduct) {
  // TC01: v1 . v3 = 0 (orthogonal vectors)
  EXPECT_TRUE(isZero(v1.dot(v3)));
  // TC02: v1 . v2 = -28
  EXPECT_TRUE(isZero(v1.dot(v2) + 28));
}

TEST_F(CourseMainTests, crossProduct) {
  // TC01: v1 x v2 throws (parallel vectors)
  EXPECT_THROW((void)v1.cross(v2), std::invalid_argument);
  // TC02: |v1 x v3| = |v1|·|v3| for orthogonal operands
  const Vector vr = v1.cross(v3);
  EXPECT_TRUE(isZero(vr.length() - v1.length() * v3.length()));
  // TC03: v1 x v3 is orthogonal to v1 and to v3
  EXPECT_TRUE(isZero(vr.dot(v1)));
  EXPECT_TRUE(isZero(vr.dot(v3)));
}

TEST_F(CourseMainTests, normalize) {
  const Vector u = v1.normalized();
  // TC01: |normalize(v1)| = 1
  EXPECT_TRUE(isZero(u.length() - 1));
  // TC02: v1 x u throws (parallel: same direction)
  EXPECT_THROW((void)v1.cross(u), std::invalid_argument);
  // TC03: v1 . u > 0 (same direction, not opposite)
  EXPECT_GT(v1.dot(u), 0.0);
}

}  // namespace
}  // namespace rt
