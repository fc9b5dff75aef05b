// Stage 2: Triangle constructor and normal (catalogue TriangleTests).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "geometries/Triangle.h"
#include "support/SameBits.h"

#include "ExpectVector.h"

namespace rt {
namespace {

using test::expectVector;
using test::sameBits;

TEST(TriangleTests, constructor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: three points in general position, kept in order
  const Triangle t(Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0));
  EXPECT_EQ(t.vertices()[0], Point(0, 0, 1));
  EXPECT_EQ(t.vertices()[1], Point(1, 0, 0));
  EXPECT_EQ(t.vertices()[2], Point(0, 1, 0));
  // =============== Boundary Values Tests ==================
  // TC11: collinear vertices throw, named as the triangle's
  try {
    (void)Triangle(Point(0, 0, 0), Point(1, 1, 1), Point(2, 2, 2));
    ADD_FAILURE() << "collinear vertices accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "Triangle: the points (0,0,0), (1,1,1), (2,2,2) do not define a plane (two "
                 "coincide or all are collinear)");
  }
  // TC12: two coincident vertices throw
  EXPECT_THROW(Triangle(Point(0, 0, 0), Point(0, 0, 0), Point(2, 2, 2)), std::invalid_argument);
  EXPECT_THROW(Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(1, 0, 0)), std::invalid_argument);
}

TEST(TriangleTests, normal) {
  // TC01: (1,0,0),(1,1,0),(0,0,0): normalize((0,1,0) x (-1,0,0)) = (0,0,1)
  const Triangle t(Point(1, 0, 0), Point(1, 1, 0), Point(0, 0, 0));
  expectVector(t.normal(Point(0.5, 0.25, 0)), 0, 0, 1);
  // TC02: (0,0,1),(1,0,0),(0,1,0): (1,0,-1) x (0,1,-1) = (1,1,1) -> (1,1,1)/sqrt(3)
  const Triangle t2(Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0));
  const Vector n = t2.normal(Point(1.0 / 3, 1.0 / 3, 1.0 / 3));
  const double k = 1 / std::sqrt(3.0);
  expectVector(n, k, k, k);
  // TC03: unit length, orthogonal to every edge, equal to the plane's normal
  EXPECT_NEAR(n.length(), 1.0, 1e-12);
  EXPECT_NEAR(n.dot(Point(1, 0, 0) - Point(0, 0, 1)), 0.0, 1e-12);
  EXPECT_NEAR(n.dot(Point(0, 1, 0) - Point(1, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(n.dot(Point(0, 0, 1) - Point(0, 1, 0)), 0.0, 1e-12);
  EXPECT_EQ(n, t2.plane().normal());
}

TEST(TriangleTests, planeIsTheVerticesPlaneBitForBit) {
  // The triangle keeps only its plane's unit normal and makes the plane from it: the same bits
  // as the Plane of its three vertices, whose normalisation rounds (1,2,2)/3 and (1,1,1)/√3.
  // TC01: a normal of length 3 before normalisation; TC02: one of length √3
  for (const auto& [p1, p2, p3] : {std::array{Point(0, 0, 0), Point(2, -1, 0), Point(2, 0, -1)},
                                   std::array{Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0)}}) {
    const Triangle t(p1, p2, p3);
    const Plane expected(p1, p2, p3);
    EXPECT_TRUE(sameBits(t.plane().point(), p1));
    EXPECT_TRUE(sameBits(t.plane().normal(), expected.normal()));
    EXPECT_TRUE(sameBits(t.normal(), expected.normal()));
  }
  // TC03: the triangle is its three points and a normal, no more (the variant's size)
  EXPECT_EQ(4 * sizeof(Point), sizeof(Triangle));
}

}  // namespace
}  // namespace rt
