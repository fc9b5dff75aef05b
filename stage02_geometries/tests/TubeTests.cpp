// Stage 2: Tube constructor validation and normal (catalogue TubeTests.getNormal).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometries/Tube.h"

#include "ExpectVector.h"

namespace rt {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using test::expectVector;
using test::kZAxis;

TEST(TubeTests, constructor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a positive radius; the axis is kept (its direction normalised by Ray)
  const Tube t(2, Ray(Point(1, 1, 1), Vector(0, 0, 5)));
  EXPECT_EQ(t.radius(), 2.0);
  EXPECT_EQ(t.axis().head(), Point(1, 1, 1));
  EXPECT_EQ(t.axis().direction(), Vector(0, 0, 1));
  // TC02: a negative radius throws, naming the shape, the argument and the value
  EXPECT_THAT([] { Tube(-2.5, kZAxis); },
              ThrowsMessage<std::invalid_argument>(
                  AllOf(HasSubstr("Tube"), HasSubstr("radius"), HasSubstr("-2.5"))));
  // TC03: NaN and infinite radii throw
  EXPECT_THROW(Tube(std::nan(""), kZAxis), std::invalid_argument);
  EXPECT_THROW(Tube(std::numeric_limits<double>::infinity(), kZAxis), std::invalid_argument);
  // =============== Boundary Values Tests ==================
  // TC11: radius zero throws
  EXPECT_THROW(Tube(0, kZAxis), std::invalid_argument);
  // TC12: a tiny positive radius is legal
  EXPECT_NO_THROW(Tube(1e-9, kZAxis));
}

TEST(TubeTests, normal) {
  const Tube tube(10, kZAxis);
  // ============ Equivalence Partitions Tests ==============
  // TC01: course: r=10 around the z axis, P=(10,0,1) -> (1,0,0)
  expectVector(tube.normal(Point(10, 0, 1)), 1, 0, 0);
  // TC02: a tube of radius 1 along the x axis, P=(1,0,1) -> (0,0,1)
  expectVector(Tube(1, Ray(Point(0, 0, 0), Vector(1, 0, 0))).normal(Point(1, 0, 1)), 0, 0, 1);
  // TC03: a point behind the axis head (negative axial coordinate)
  expectVector(tube.normal(Point(0, 10, -5)), 0, 1, 0);
  // TC04: a general axis (head off the origin, non-unit direction) and a diagonal point
  const Tube shifted(2, Ray(Point(1, 1, 1), Vector(0, 0, 2)));
  const double k = 1 / std::sqrt(2.0);
  expectVector(shifted.normal(Point(1 + 2 * k, 1 - 2 * k, 5)), k, -k, 0);
  // TC05: a slanted axis: tube r=1 around the line through the origin along (1,1,0);
  // P = (2,2,0) + (0,0,1) is at distance 1 from the axis -> (0,0,1)
  expectVector(Tube(1, Ray(Point(0, 0, 0), Vector(1, 1, 0))).normal(Point(2, 2, 1)), 0, 0, 1);
  // =============== Boundary Values Tests ==================
  // TC11: P - P0 orthogonal to the axis (axial coordinate 0): P=(10,0,0) -> (1,0,0)
  expectVector(tube.normal(Point(10, 0, 0)), 1, 0, 0);
  // TC12: the course's point (0,10,0) level with the head -> (0,1,0)
  expectVector(tube.normal(Point(0, 10, 0)), 0, 1, 0);
  // TC13: a point on the axis has no normal: throws, naming the point
  EXPECT_THAT([&] { (void)tube.normal(Point(0, 0, 3)); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("(0,0,3)")));
}

}  // namespace
}  // namespace rt
