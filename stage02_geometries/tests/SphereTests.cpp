// Stage 2: Sphere constructor validation and normal (catalogue SphereTests.getNormal).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometries/Sphere.h"

#include "ExpectVector.h"

namespace rt {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using test::expectVector;

TEST(SphereTests, constructor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a positive radius
  const Sphere s(Point(1, 2, 3), 4);
  EXPECT_EQ(s.center(), Point(1, 2, 3));
  EXPECT_EQ(s.radius(), 4.0);
  // TC02: a negative radius throws, naming the argument and the value
  EXPECT_THAT([] { Sphere(Point(0, 0, 0), -1); },
              ThrowsMessage<std::invalid_argument>(
                  AllOf(HasSubstr("Sphere"), HasSubstr("radius"), HasSubstr("-1"))));
  // TC03: a NaN radius throws
  EXPECT_THROW(Sphere(Point(0, 0, 0), std::nan("")), std::invalid_argument);
  // TC04: an infinite radius throws
  EXPECT_THROW(Sphere(Point(0, 0, 0), std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  // =============== Boundary Values Tests ==================
  // TC11: radius zero throws
  EXPECT_THAT([] { Sphere(Point(0, 0, 0), 0); },
              ThrowsMessage<std::invalid_argument>(AllOf(HasSubstr("radius"), HasSubstr("0"))));
  // TC12: a tiny positive radius is legal
  EXPECT_NO_THROW(Sphere(Point(0, 0, 0), 1e-9));
}

TEST(SphereTests, constructorNonFiniteCenter) {
  // =============== Boundary Values Tests ==================
  // TC11: a centre with a NaN coordinate is refused, naming the centre
  EXPECT_THAT([] { Sphere(Point(NAN, 0, 0), 1); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("Sphere: center must be finite, got (nan,0,0)")));
}

TEST(SphereTests, normal) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: course: centre (0,0,0) r=12, P=(0,0,12) -> (0,0,1)
  expectVector(Sphere(Point(0, 0, 0), 12).normal(Point(0, 0, 12)), 0, 0, 1);
  // TC02: centre (1,1,1) r=2, P=(3,1,1) -> (1,0,0), unit length
  const Vector n = Sphere(Point(1, 1, 1), 2).normal(Point(3, 1, 1));
  expectVector(n, 1, 0, 0);
  EXPECT_NEAR(n.length(), 1.0, 1e-12);
  // TC03: a general point: centre (1,2,3) r=3, P = centre + (1,2,2) -> (1,2,2)/3
  expectVector(Sphere(Point(1, 2, 3), 3).normal(Point(2, 4, 5)), 1.0 / 3, 2.0 / 3, 2.0 / 3);
  // TC04: a point on the lower hemisphere points down and outward
  expectVector(Sphere(Point(0, 0, 0), 5).normal(Point(0, -3, -4)), 0, -0.6, -0.8);
  // =============== Boundary Values Tests ==================
  // TC11: at the centre the normal is undefined: throws
  EXPECT_THROW((void)Sphere(Point(1, 1, 1), 2).normal(Point(1, 1, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace rt
