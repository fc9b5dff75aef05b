// Stage 1: the course's numeric helpers (isZero, alignZero) and the Double3 triple.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "primitives/Double3.h"
#include "primitives/Util.h"

namespace rt {
namespace {

const double kThreshold = std::ldexp(1.0, -40);  // 2^-40, the course's "binary exponent < -40"
const double kJustBelow = std::nextafter(kThreshold, 0.0);

TEST(UtilTests, thresholdIsTwoToTheMinus40) {
  // TC01: the constant is exactly 2^-40 (about 9.09e-13)
  EXPECT_EQ(ZERO_THRESHOLD, kThreshold);
  EXPECT_NEAR(ZERO_THRESHOLD, 9.094947017729282e-13, 1e-27);
}

TEST(UtilTests, isZero) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an ordinary number is not zero
  EXPECT_FALSE(isZero(1.0));
  // TC02: a number far below the threshold is zero
  EXPECT_TRUE(isZero(1e-15));
  // TC03: a negative ordinary number is not zero
  EXPECT_FALSE(isZero(-0.5));
  // TC04: a negative tiny number is zero
  EXPECT_TRUE(isZero(-1e-15));

  // =============== Boundary Values Tests ==================
  // TC11: exactly zero
  EXPECT_TRUE(isZero(0.0));
  // TC12: negative zero
  EXPECT_TRUE(isZero(-0.0));
  // TC13: the largest double just below 2^-40 is zero
  EXPECT_TRUE(isZero(kJustBelow));
  // TC14: exactly 2^-40 is not zero (its binary exponent is -40, not below)
  EXPECT_FALSE(isZero(kThreshold));
  // TC15: the same two boundaries on the negative side
  EXPECT_TRUE(isZero(-kJustBelow));
  EXPECT_FALSE(isZero(-kThreshold));
  // TC16: the smallest positive (denormal) double is zero
  EXPECT_TRUE(isZero(std::numeric_limits<double>::denorm_min()));
}

TEST(UtilTests, alignZero) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an ordinary number is returned unchanged
  EXPECT_EQ(alignZero(3.25), 3.25);
  EXPECT_EQ(alignZero(-3.25), -3.25);
  // TC02: a tiny number becomes exactly 0
  EXPECT_EQ(alignZero(1e-14), 0.0);
  EXPECT_EQ(alignZero(-1e-14), 0.0);

  // =============== Boundary Values Tests ==================
  // TC11: just below the threshold becomes 0 (and never a negative zero's sign decides a test)
  EXPECT_EQ(alignZero(kJustBelow), 0.0);
  EXPECT_EQ(alignZero(-kJustBelow), 0.0);
  EXPECT_FALSE(alignZero(-kJustBelow) < 0);
  // TC12: exactly at the threshold the number is kept
  EXPECT_EQ(alignZero(kThreshold), kThreshold);
  EXPECT_EQ(alignZero(-kThreshold), -kThreshold);
}

TEST(Double3Tests, lowerThanNeedsAllThreeComponents) {
  // TC01: all three below the bound
  EXPECT_TRUE(Double3(0.1, 0.2, 0.3).lowerThan(0.5));
  // TC02: only one component below (course semantics: not lower)
  EXPECT_FALSE(Double3(0.1, 0.9, 0.9).lowerThan(0.5));
  // TC03: two below, one above
  EXPECT_FALSE(Double3(0.1, 0.1, 0.9).lowerThan(0.5));
  // TC11: a component equal to the bound is not lower
  EXPECT_FALSE(Double3(0.1, 0.1, 0.5).lowerThan(0.5));
}

TEST(Double3Tests, courseEquality) {
  // TC01: equal values
  EXPECT_TRUE(Double3(1, 2, 3) == Double3(1, 2, 3));
  // TC02: clearly different in one component
  EXPECT_FALSE(Double3(1, 2, 3) == Double3(1, 2, 3.001));
  // TC11: a difference just below 2^-40 in a component counts as equal
  EXPECT_TRUE(Double3(0, 0, 0) == Double3(0, kJustBelow, 0));
  // TC12: a difference of exactly 2^-40 does not
  EXPECT_FALSE(Double3(0, 0, 0) == Double3(0, kThreshold, 0));
}

TEST(Double3Tests, arithmetic) {
  // TC01: sum, difference, component-wise product, scaling, dot and cross
  EXPECT_EQ(Double3(1, 2, 3) + Double3(4, 5, 6), Double3(5, 7, 9));
  EXPECT_EQ(Double3(1, 2, 3) - Double3(4, 5, 6), Double3(-3, -3, -3));
  EXPECT_EQ(Double3(1, 2, 3) * Double3(4, 5, 6), Double3(4, 10, 18));
  EXPECT_EQ(Double3(1, 2, 3) * 2.0, Double3(2, 4, 6));
  EXPECT_EQ(2.0 * Double3(1, 2, 3), Double3(2, 4, 6));
  EXPECT_EQ(Double3(1, 2, 3) / 2.0, Double3(0.5, 1, 1.5));
  EXPECT_DOUBLE_EQ(Double3(1, 2, 3).dot(Double3(4, 5, 6)), 32.0);
  EXPECT_EQ(Double3(1, 0, 0).cross(Double3(0, 1, 0)), Double3(0, 0, 1));
  EXPECT_DOUBLE_EQ(Double3(1, 2, 2).lengthSquared(), 9.0);
  // TC02: the all-equal constructor
  EXPECT_EQ(Double3(0.25), Double3(0.25, 0.25, 0.25));
}

TEST(Double3Tests, isZeroAndIsFinite) {
  // TC01: the zero triple, and one whose components are all below the threshold
  EXPECT_TRUE(Double3::ZERO.isZero());
  EXPECT_TRUE(Double3(kJustBelow, -kJustBelow, 0).isZero());
  // TC11: one component at the threshold makes it non-zero
  EXPECT_FALSE(Double3(0, 0, kThreshold).isZero());
  // TC02: finite values; TC12: NaN and infinity are not finite
  EXPECT_TRUE(Double3(1, -2, 3).isFinite());
  EXPECT_FALSE(Double3(1, std::nan(""), 3).isFinite());
  EXPECT_FALSE(Double3(std::numeric_limits<double>::infinity(), 0, 0).isFinite());
}

TEST(Double3Tests, isExactlyZero) {
  // TC01: the zero triple, and one with negative zeros, are exactly zero
  EXPECT_TRUE(Double3::ZERO.isExactlyZero());
  EXPECT_TRUE(Double3(-0.0, 0, -0.0).isExactlyZero());
  // TC02: a triple that isZero (below the threshold) but is not exactly zero
  EXPECT_FALSE(Double3(0, kJustBelow, 0).isExactlyZero());
  // TC11: the smallest positive double in any one component is not zero
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_FALSE(Double3(tiny, 0, 0).isExactlyZero());
  EXPECT_FALSE(Double3(0, tiny, 0).isExactlyZero());
  EXPECT_FALSE(Double3(0, 0, -tiny).isExactlyZero());
  // TC12: NaN is not zero
  EXPECT_FALSE(Double3(0, 0, std::nan("")).isExactlyZero());
}

TEST(Double3Tests, formatting) {
  // TC01: the shortest round-trip form of each number
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(-2.0), "-2");
  EXPECT_EQ(formatNumber(1e-05), "1e-05");
  // TC02: a triple prints as (x,y,z)
  EXPECT_EQ(Double3(1, 2.5, -3).str(), "(1,2.5,-3)");
}

}  // namespace
}  // namespace rt
