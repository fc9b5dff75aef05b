// Stage 2: the finite, closed Cylinder: constructor validation and normals on the side, the
// bases, their centres and their rims (catalogue CylinderTests; bottom base -> -axis).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometries/Cylinder.h"

#include "ExpectVector.h"

namespace rt {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using test::expectVector;
using test::kZAxis;

TEST(CylinderTests, constructor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: positive radius and height; accessors
  const Cylinder c(1, kZAxis, 2);
  EXPECT_EQ(c.radius(), 1.0);
  EXPECT_EQ(c.height(), 2.0);
  EXPECT_EQ(c.axis(), kZAxis);
  EXPECT_EQ(c.tube().radius(), 1.0);
  EXPECT_EQ(c.tube().axis(), kZAxis);
  // TC02: negative height throws, naming the shape, the argument and the value
  EXPECT_THAT([] { Cylinder(1, kZAxis, -3); },
              ThrowsMessage<std::invalid_argument>(
                  AllOf(HasSubstr("Cylinder"), HasSubstr("height"), HasSubstr("-3"))));
  // TC03: negative radius throws, naming the radius
  EXPECT_THAT([] { Cylinder(-1, kZAxis, 2); },
              ThrowsMessage<std::invalid_argument>(AllOf(HasSubstr("radius"), HasSubstr("-1"))));
  // TC04: NaN and infinite height or radius throw
  EXPECT_THROW(Cylinder(1, kZAxis, std::nan("")), std::invalid_argument);
  EXPECT_THROW(Cylinder(1, kZAxis, std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(Cylinder(std::nan(""), kZAxis, 2), std::invalid_argument);
  // =============== Boundary Values Tests ==================
  // TC11: height zero throws
  EXPECT_THAT([] { Cylinder(1, kZAxis, 0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("height")));
  // TC12: radius zero throws
  EXPECT_THAT([] { Cylinder(0, kZAxis, 2); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("radius")));
  // TC13: tiny positive radius and height are legal
  EXPECT_NO_THROW(Cylinder(1e-9, kZAxis, 1e-9));
}

TEST(CylinderTests, normal) {
  const Cylinder c(1, kZAxis, 2);
  // ============ Equivalence Partitions Tests ==============
  // TC01: a point on the side -> the tube's normal
  expectVector(c.normal(Point(1, 0, 1.5)), 1, 0, 0);
  expectVector(c.normal(Point(0, -1, 0.5)), 0, -1, 0);
  // TC02: a point inside the bottom base -> -axis
  expectVector(c.normal(Point(0.5, 0.5, 0)), 0, 0, -1);
  // TC03: a point inside the top base -> +axis
  expectVector(c.normal(Point(0.5, 0.5, 2)), 0, 0, 1);
  // =============== Boundary Values Tests ==================
  // TC11: the centre of the bottom base -> -axis
  expectVector(c.normal(Point(0, 0, 0)), 0, 0, -1);
  // TC12: the centre of the top base -> +axis
  expectVector(c.normal(Point(0, 0, 2)), 0, 0, 1);
  // TC13: a point on the bottom rim -> -axis (the base wins over the side)
  expectVector(c.normal(Point(1, 0, 0)), 0, 0, -1);
  // TC14: a point on the top rim -> +axis
  expectVector(c.normal(Point(1, 0, 2)), 0, 0, 1);
  // TC15: axial coordinate 1e-13 (isZero) is still the bottom base
  expectVector(c.normal(Point(0.5, 0, 1e-13)), 0, 0, -1);
  // TC16: a side point just above the bottom rim (axial coordinate 1e-9) is the side
  expectVector(c.normal(Point(1, 0, 1e-9)), 1, 0, 0);
  // TC17: a side point just below the top rim
  expectVector(c.normal(Point(0, 1, 2 - 1e-9)), 0, 1, 0);
}

TEST(CylinderTests, normalWithGeneralAxis) {
  // A cylinder of radius 2 and height 4 along +x from (1,2,3), the axis given unnormalised.
  const Cylinder c(2, Ray(Point(1, 2, 3), Vector(3, 0, 0)), 4);
  // TC01: a side point -> (0,1,0)
  expectVector(c.normal(Point(3, 4, 3)), 0, 1, 0);
  // TC02: on the bottom base (x = 1) -> -axis = (-1,0,0)
  expectVector(c.normal(Point(1, 3, 3)), -1, 0, 0);
  // TC03: on the top base (x = 5) -> +axis
  expectVector(c.normal(Point(5, 2, 4)), 1, 0, 0);
  // TC11: on the top rim -> +axis
  expectVector(c.normal(Point(5, 2, 5)), 1, 0, 0);
}

}  // namespace
}  // namespace rt
