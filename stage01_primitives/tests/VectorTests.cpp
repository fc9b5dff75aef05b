// Stage 1: Vector (catalogue VectorTests, the lecture's cross-product example) and the
// zero-vector rule: every operation whose result would be zero throws, naming the operation.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "primitives/Vector.h"

namespace rt {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const double kThreshold = std::ldexp(1.0, -40);

TEST(VectorTests, constructor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a non-zero vector is constructed with its components
  const Vector v(1, -2, 3);
  EXPECT_EQ(v.x(), 1.0);
  EXPECT_EQ(v.y(), -2.0);
  EXPECT_EQ(v.z(), 3.0);
  // TC02: from a Double3
  EXPECT_EQ(Vector(Double3(1, -2, 3)), v);
  // =============== Boundary Values Tests ==================
  // TC11: the zero vector throws, naming the operation
  EXPECT_THAT([] { Vector(0, 0, 0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("Vector constructor")));
  // TC12: the zero vector from Double3::ZERO throws
  EXPECT_THROW((void)Vector(Double3::ZERO), std::invalid_argument);
  // TC13: components all just below 2^-40 are zero: throws
  EXPECT_THROW(Vector(1e-13, -1e-13, 0), std::invalid_argument);
  // TC14: one component exactly 2^-40 is not zero: constructs
  EXPECT_NO_THROW(Vector(kThreshold, 0, 0));
  // TC15: the axis constants
  EXPECT_EQ(Vector::AXIS_X, Vector(1, 0, 0));
  EXPECT_EQ(Vector::AXIS_Y, Vector(0, 1, 0));
  EXPECT_EQ(Vector::AXIS_Z, Vector(0, 0, 1));
}

TEST(VectorTests, add) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: sum of two vectors
  EXPECT_EQ(Vector(1, 2, 3) + Vector(-2, -4, -6), Vector(-1, -2, -3));
  // =============== Boundary Values Tests ==================
  // TC11: a vector plus its opposite is zero: throws, naming the operation and both operands
  EXPECT_THAT([] { (void)(Vector(1, 2, 3) + Vector(-1, -2, -3)); },
              ThrowsMessage<std::invalid_argument>(AllOf(
                  HasSubstr("Vector addition"), HasSubstr("(1,2,3)"), HasSubstr("(-1,-2,-3)"))));
}

TEST(VectorTests, subtract) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: difference of two vectors
  EXPECT_EQ(Vector(1, 2, 3) - Vector(-2, -4, -6), Vector(3, 6, 9));
  // =============== Boundary Values Tests ==================
  // TC11: a vector minus itself is zero: throws, naming the operation
  const Vector v(1, 2, 3);
  EXPECT_THAT([&] { (void)(v - v); }, ThrowsMessage<std::invalid_argument>(AllOf(
                                          HasSubstr("Vector subtraction"), HasSubstr("(1,2,3)"))));
}

TEST(VectorTests, negate) {
  // TC01: the opposite vector
  EXPECT_EQ(-Vector(1, -2, 3), Vector(-1, 2, -3));
}

TEST(VectorTests, scale) {
  const Vector v(1, 2, 3);
  // ============ Equivalence Partitions Tests ==============
  // TC01: positive factor
  EXPECT_EQ(v * 2.0, Vector(2, 4, 6));
  EXPECT_EQ(2.0 * v, Vector(2, 4, 6));
  // TC02: negative factor flips the direction
  EXPECT_EQ(v * -1.0, Vector(-1, -2, -3));
  EXPECT_EQ(v * -0.5, Vector(-0.5, -1, -1.5));
  // =============== Boundary Values Tests ==================
  // TC11: scaling by zero throws, naming the operation
  EXPECT_THAT([&] { (void)(v * 0.0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("Vector scaling")));
  // TC12: scaling by a factor that makes every component isZero throws too
  EXPECT_THROW((void)(v * 1e-14), std::invalid_argument);
}

TEST(VectorTests, lengthSquaredAndLength) {
  // TC01: |(1,2,2)|^2 = 9 and |(1,2,2)| = 3
  EXPECT_NEAR(Vector(1, 2, 2).lengthSquared(), 9.0, 1e-12);
  EXPECT_NEAR(Vector(1, 2, 2).length(), 3.0, 1e-12);
  // TC02: a negative-component vector
  EXPECT_NEAR(Vector(0, -3, 4).length(), 5.0, 1e-12);
}

TEST(VectorTests, dotProduct) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the dot product of two non-orthogonal vectors
  EXPECT_NEAR(Vector(1, -2, 3).dot(Vector(-2, -4, -6)), -12.0, 1e-12);
  // =============== Boundary Values Tests ==================
  // TC11: orthogonal vectors
  EXPECT_EQ(Vector(1, 2, 3).dot(Vector(0, 3, -2)), 0.0);
  EXPECT_EQ(Vector(1, 0, 0).dot(Vector(0, 3, 2)), 0.0);
}

TEST(VectorTests, crossProduct) {
  const Vector v1(1, 2, 3);
  const Vector v3(0, 3, -2);
  const Vector vr = v1.cross(v3);
  // ============ Equivalence Partitions Tests ==============
  // TC01: for orthogonal operands the length of the result is the product of the lengths
  EXPECT_NEAR(vr.length(), v1.length() * v3.length(), 1e-9);
  // TC02: the result is orthogonal to both operands
  EXPECT_NEAR(vr.dot(v1), 0.0, 1e-12);
  EXPECT_NEAR(vr.dot(v3), 0.0, 1e-12);
  // TC03: the exact right-handed result (2*-2 - 3*3, 3*0 - 1*-2, 1*3 - 2*0)
  EXPECT_EQ(vr, Vector(-13, 2, 3));
  EXPECT_EQ(Vector::AXIS_X.cross(Vector::AXIS_Y), Vector::AXIS_Z);
  // =============== Boundary Values Tests ==================
  // TC11: parallel operands (opposite direction, different length) give zero: throws
  EXPECT_THAT([&] { (void)v1.cross(Vector(-2, -4, -6)); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("cross product")));
  // TC12: a vector crossed with itself throws
  EXPECT_THROW((void)v1.cross(v1), std::invalid_argument);
}

TEST(VectorTests, normalized) {
  const Vector v(1, 2, 3);
  const Vector u = v.normalized();
  // TC01: unit length
  EXPECT_NEAR(u.length(), 1.0, 1e-12);
  // TC02: same direction: the cross product with the original throws, the dot product is > 0
  EXPECT_THROW((void)v.cross(u), std::invalid_argument);
  EXPECT_GT(v.dot(u), 0.0);
  // TC03: exact components of a 3-4-5 vector
  EXPECT_EQ(Vector(0, 3, 4).normalized(), Vector(0, 0.6, 0.8));
  // TC11: a vector of length exactly 2^-40 still normalises to unit length
  EXPECT_NEAR(Vector(kThreshold, 0, 0).normalized().length(), 1.0, 1e-12);
  // TC12: components so large (1e200) that the squared length overflows to infinity still
  // normalise exactly (not to the zero vector)
  const Vector huge = Vector(1e200, -1e200, 0).normalized();
  EXPECT_DOUBLE_EQ(huge.x(), std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(huge.y(), -std::sqrt(0.5));
  EXPECT_EQ(huge.z(), 0.0);
  // TC13: components so small (1e-170, only reachable through Vector::unchecked) that the
  // squared length underflows to zero still normalise (not to NaN)
  const Vector tiny = Vector::unchecked(Double3(3e-170, 0, -4e-170)).normalized();
  EXPECT_DOUBLE_EQ(tiny.x(), 0.6);
  EXPECT_EQ(tiny.y(), 0.0);
  EXPECT_DOUBLE_EQ(tiny.z(), -0.8);
}

}  // namespace
}  // namespace rt
