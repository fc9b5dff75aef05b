// The one rule for integers (common/Integers.h): scene-file values and option values alike.
#include <gtest/gtest.h>

#include <climits>
#include <optional>

#include "common/Integers.h"

namespace rt {
namespace {

using Json = nlohmann::ordered_json;

TEST(IntegersTests, integerInText) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a plain integer
  EXPECT_EQ(integerInText("100", 1, 32768), 100);
  // TC02: exponent form
  EXPECT_EQ(integerInText("1e2", 1, 32768), 100);
  EXPECT_EQ(integerInText("1.5E2", 1, 32768), 150);
  // TC03: an integral decimal
  EXPECT_EQ(integerInText("100.0", 1, 32768), 100);
  // TC04: a negative integer in a range that holds it
  EXPECT_EQ(integerInText("-3", -5, 5), -3);
  // TC05: a fraction, in either form
  EXPECT_EQ(integerInText("100.5", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("1.005e2", 1, 32768), std::nullopt);
  // TC06: not a number, or a number followed by more
  EXPECT_EQ(integerInText("wide", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("64x", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("1,2", 1, 32768), std::nullopt);
  // TC07: forms JSON does not have: a plus sign, a leading zero, hex, a bare dot
  EXPECT_EQ(integerInText("+100", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("0100", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("0x64", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("100.", 1, 32768), std::nullopt);
  // TC08: JSON that is not a number
  EXPECT_EQ(integerInText("\"100\"", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("[100]", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("true", 0, 1), std::nullopt);

  // =============== Boundary Values Tests ==================
  // TC11: both ends of the range
  EXPECT_EQ(integerInText("1", 1, 32768), 1);
  EXPECT_EQ(integerInText("32768", 1, 32768), 32768);
  EXPECT_EQ(integerInText("3.2768e4", 1, 32768), 32768);
  // TC12: one beyond either end
  EXPECT_EQ(integerInText("0", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("32769", 1, 32768), std::nullopt);
  // TC13: far beyond int, and beyond a double
  EXPECT_EQ(integerInText("4294967297", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("18446744073709551616", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("1e400", 1, 32768), std::nullopt);
  // TC14: empty text, and white space around a number
  EXPECT_EQ(integerInText("", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText(" 100", 1, 32768), std::nullopt);
  EXPECT_EQ(integerInText("100\n", 1, 32768), std::nullopt);
  // TC15: minus zero is zero
  EXPECT_EQ(integerInText("-0", 0, 5), 0);
  EXPECT_EQ(integerInText("-0.0", 0, 5), 0);
  // TC16: the whole range of int
  EXPECT_EQ(integerInText("2147483647", 0, INT_MAX), INT_MAX);
  EXPECT_EQ(integerInText("-2147483648", INT_MIN, 0), INT_MIN);
}

TEST(IntegersTests, integerInJson) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the three kinds of JSON number nlohmann keeps: unsigned, signed, double
  EXPECT_EQ(integerIn(Json(7u), 0, 10), 7);
  EXPECT_EQ(integerIn(Json(-7), -10, 10), -7);
  EXPECT_EQ(integerIn(Json(7.0), 0, 10), 7);
  // TC02: not a number
  EXPECT_EQ(integerIn(Json("7"), 0, 10), std::nullopt);
  EXPECT_EQ(integerIn(Json(nullptr), 0, 10), std::nullopt);
  // =============== Boundary Values Tests ==================
  // TC11: an unsigned value above a negative upper end
  EXPECT_EQ(integerIn(Json(0u), -5, -1), std::nullopt);
  // TC12: a negative value below a lower end of 0
  EXPECT_EQ(integerIn(Json(-1), 0, 10), std::nullopt);
  // TC13: a double just off an integer
  EXPECT_EQ(integerIn(Json(7.000000000000001), 0, 10), std::nullopt);
}

TEST(IntegersTests, integerDescription) {
  // TC01: a bounded range
  EXPECT_EQ(integerDescription(1, 32768), "an integer from 1 to 32768");
  // TC02: from zero up: int's largest value named, since a larger one is refused
  EXPECT_EQ(integerDescription(0), "an integer from 0 to 2147483647");
  // TC03: from another lower end up
  EXPECT_EQ(integerDescription(5), "an integer from 5 to 2147483647");
}

}  // namespace
}  // namespace rt
