// Stage 1: Point (catalogue "Student unit tests in stage 1/2", PointTests).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(PointTests, distanceSquared) {
  const Point p1(1, 2, 5);
  const Point p2(3, 4, 5);
  // ============ Equivalence Partitions Tests ==============
  // TC01: distance squared between two different points, both directions
  EXPECT_NEAR(p1.distanceSquared(p2), 8.0, 1e-12);
  EXPECT_NEAR(p2.distanceSquared(p1), 8.0, 1e-12);
  // =============== Boundary Values Tests ==================
  // TC11: a point to itself
  EXPECT_EQ(p1.distanceSquared(p1), 0.0);
}

TEST(PointTests, distance) {
  const Point p1(1, 2, 5);
  const Point p2(3, 4, 5);
  // ============ Equivalence Partitions Tests ==============
  // TC01: distance between two different points, both directions
  EXPECT_NEAR(p1.distance(p2), std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(p2.distance(p1), std::sqrt(8.0), 1e-12);
  // =============== Boundary Values Tests ==================
  // TC11: a point to itself
  EXPECT_EQ(p1.distance(p1), 0.0);
}

TEST(PointTests, addVector) {
  const Point p1(1, 2, 5);
  // ============ Equivalence Partitions Tests ==============
  // TC01: adding a vector moves the point
  EXPECT_EQ(p1 + Vector(1, 2, 5), Point(2, 4, 10));
  // TC02: subtracting a vector moves it back
  EXPECT_EQ(Point(2, 4, 10) - Vector(1, 2, 5), p1);
  // =============== Boundary Values Tests ==================
  // TC11: adding the opposite of the point's own coordinates gives the origin
  EXPECT_EQ(p1 + Vector(-1, -2, -5), Point::ZERO);
}

TEST(PointTests, subtractPoint) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the vector between two different points
  EXPECT_EQ(Point(3, 4, 5) - Point(1, 2, 5), Vector(2, 2, 0));
  // =============== Boundary Values Tests ==================
  // TC11: a point minus itself would be the zero vector: throws, naming the operation and points
  const Point p(1, 2, 5);
  EXPECT_THAT([&] { (void)(p - p); }, ThrowsMessage<std::invalid_argument>(AllOf(
                                          HasSubstr("Point subtraction"), HasSubstr("(1,2,5)"))));
  // TC12: points closer than the zero threshold are the same point: throws
  EXPECT_THROW((void)(Point(1, 2, 5) - Point(1, 2, 5 + 1e-13)), std::invalid_argument);
}

TEST(PointTests, equality) {
  // TC01: equal and different points
  EXPECT_TRUE(Point(1, 2, 3) == Point(1, 2, 3));
  EXPECT_FALSE(Point(1, 2, 3) == Point(1, 2, 4));
  // TC11: a difference below the zero threshold is equality (course semantics)
  EXPECT_TRUE(Point(1, 2, 3) == Point(1, 2, 3 + 1e-13));
  // TC12: ZERO is the origin
  EXPECT_EQ(Point::ZERO, Point(0, 0, 0));
}

TEST(PointTests, accessorsAndPrinting) {
  // TC01: coordinates and the printed form
  const Point p(1, -2.5, 3);
  EXPECT_EQ(p.x(), 1.0);
  EXPECT_EQ(p.y(), -2.5);
  EXPECT_EQ(p.z(), 3.0);
  std::ostringstream os;
  os << p;
  EXPECT_EQ(os.str(), "(1,-2.5,3)");
}

}  // namespace
}  // namespace rt
