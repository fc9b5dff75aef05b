// Stage 1: the shared argument checks (primitives/Checks.h): what each accepts, and the message
// naming the operation, the argument and the value of what it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "primitives/Checks.h"

namespace rt {
namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

/// The message of the std::invalid_argument that f throws ("" when it throws none).
template <typename F>
std::string messageOf(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ChecksTests, requirePositive) {
  // TC01: a positive number is returned
  EXPECT_EQ(2.5, requirePositive(2.5, "Sphere", "radius"));
  // TC02: a negative number names the operation, the argument and the value
  EXPECT_EQ("Sphere: radius must be a positive finite number, got -2",
            messageOf([] { requirePositive(-2, "Sphere", "radius"); }));
  // TC11: zero, infinity and NaN are refused
  EXPECT_THROW(requirePositive(0, "Sphere", "radius"), std::invalid_argument);
  EXPECT_THROW(requirePositive(INF, "Sphere", "radius"), std::invalid_argument);
  EXPECT_THROW(requirePositive(std::nan(""), "Sphere", "radius"), std::invalid_argument);
}

TEST(ChecksTests, requireNonNegative) {
  // TC01: a positive number is returned
  EXPECT_EQ(0.5, requireNonNegative(0.5, "PointLight", "kL"));
  // TC02: a negative number names the operation, the argument and the value
  EXPECT_EQ("PointLight: kL must be a non-negative finite number, got -0.5",
            messageOf([] { requireNonNegative(-0.5, "PointLight", "kL"); }));
  // TC11: zero is accepted; infinity and NaN are refused
  EXPECT_EQ(0.0, requireNonNegative(0, "PointLight", "kL"));
  EXPECT_THROW(requireNonNegative(INF, "PointLight", "kL"), std::invalid_argument);
  EXPECT_THROW(requireNonNegative(std::nan(""), "PointLight", "kL"), std::invalid_argument);
}

TEST(ChecksTests, requireBetween) {
  // TC01: a value inside the range is returned
  EXPECT_EQ(5, requireBetween(5, 1, 10, "JitteredSampler", "grid"));
  // TC02: a value above the range names the operation, the argument, the range and the value
  EXPECT_EQ("JitteredSampler: grid must be between 1 and 10, got 11",
            messageOf([] { requireBetween(11, 1, 10, "JitteredSampler", "grid"); }));
  // TC03: a value below the range
  EXPECT_EQ("galaxy: stars must be between 0 and 10, got -1",
            messageOf([] { requireBetween(-1, 0, 10, "galaxy", "stars"); }));
  // TC11: both ends of the range are accepted
  EXPECT_EQ(1, requireBetween(1, 1, 10, "JitteredSampler", "grid"));
  EXPECT_EQ(10, requireBetween(10, 1, 10, "JitteredSampler", "grid"));
}

TEST(ChecksTests, requireFinite) {
  // TC01: a finite triple is returned (the same object)
  const Double3 v(1, -2, 3);
  EXPECT_EQ(&v, &requireFinite(v, "Plane", "point"));
  // TC02: an infinite component names the operation, the argument and the value
  EXPECT_EQ("Plane: point must be finite, got (inf,0,0)",
            messageOf([] { requireFinite(Double3(INF, 0, 0), "Plane", "point"); }));
  // TC11: a NaN in the last component is refused
  EXPECT_THROW(requireFinite(Double3(0, 0, std::nan("")), "Plane", "point"), std::invalid_argument);
}

}  // namespace
}  // namespace rt
