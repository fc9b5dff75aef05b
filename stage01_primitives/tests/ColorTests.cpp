// Stage 1: Color on the 0-255 scale, unbounded above, never negative, clamped only when written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "primitives/Color.h"

namespace rt {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using Rgb8 = std::array<std::uint8_t, 3>;

void expectColor(const Color& c, double r, double g, double b) {
  EXPECT_NEAR(c.r(), r, 1e-12);
  EXPECT_NEAR(c.g(), g, 1e-12);
  EXPECT_NEAR(c.b(), b, 1e-12);
}

TEST(ColorTests, constructor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an ordinary colour
  expectColor(Color(10, 20, 30), 10, 20, 30);
  // TC02: unbounded above: the course's scene colours (300,20,20) and (35,120,280) are legal
  expectColor(Color(300, 20, 20), 300, 20, 20);
  expectColor(Color(35, 120, 280), 35, 120, 280);
  // TC03: a negative component is rejected, naming the class and the value
  EXPECT_THAT([] { Color(-1, 0, 0); }, ThrowsMessage<std::invalid_argument>(HasSubstr("Color")));
  EXPECT_THAT([] { Color(0, 0, -5); }, ThrowsMessage<std::invalid_argument>(HasSubstr("-5")));
  EXPECT_THROW(Color(Double3(1, -2, 3)), std::invalid_argument);
  // TC04: a non-finite component is rejected
  EXPECT_THROW(Color(std::nan(""), 0, 0), std::invalid_argument);
  EXPECT_THROW(Color(0, std::numeric_limits<double>::infinity(), 0), std::invalid_argument);
  // =============== Boundary Values Tests ==================
  // TC11: all zero (black) is legal, also the default
  expectColor(Color(0, 0, 0), 0, 0, 0);
  expectColor(Color(), 0, 0, 0);
  // TC12: the smallest negative number is rejected
  EXPECT_THROW(Color(0, -std::numeric_limits<double>::denorm_min(), 0), std::invalid_argument);
  // TC13: a huge component is legal (no upper bound)
  expectColor(Color(1e6, 0, 0), 1e6, 0, 0);
}

TEST(ColorTests, constants) {
  // TC01: the named colours on the 0-255 scale
  expectColor(Color::BLACK, 0, 0, 0);
  expectColor(Color::WHITE, 255, 255, 255);
  expectColor(Color::RED, 255, 0, 0);
  expectColor(Color::GREEN, 0, 255, 0);
  expectColor(Color::BLUE, 0, 0, 255);
  expectColor(Color::YELLOW, 255, 255, 0);
}

TEST(ColorTests, add) {
  // TC01: component-wise sum
  expectColor(Color(1, 2, 3) + Color(4, 5, 6), 5, 7, 9);
  // TC02: the sum may exceed 255 (no clamping before writing)
  expectColor(Color::WHITE + Color::WHITE, 510, 510, 510);
  // TC03: compound addition
  Color c(1, 1, 1);
  c += Color(2, 3, 4);
  expectColor(c, 3, 4, 5);
  // TC11: adding black changes nothing
  expectColor(Color(7, 8, 9) + Color::BLACK, 7, 8, 9);
}

TEST(ColorTests, scale) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: by a positive factor
  expectColor(Color(10, 20, 30) * 1.5, 15, 30, 45);
  // TC02: per channel by a Double3 of coefficients (kD, kS...)
  expectColor(Color(10, 20, 30) * Double3(0.5, 1, 2), 5, 20, 60);
  // TC03: a negative factor is rejected, naming the operation
  EXPECT_THAT([] { (void)(Color(1, 1, 1) * -0.5); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("scal")));
  EXPECT_THAT([] { (void)(Color(1, 1, 1) * Double3(1, -1, 1)); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("scal")));
  // TC04: a non-finite factor is rejected
  EXPECT_THROW((void)(Color(1, 1, 1) * std::nan("")), std::invalid_argument);
  // =============== Boundary Values Tests ==================
  // TC11: by zero gives black (legal for colours)
  expectColor(Color(10, 20, 30) * 0.0, 0, 0, 0);
  expectColor(Color(10, 20, 30) * Double3(0, 0, 0), 0, 0, 0);
  // TC12: by one changes nothing
  expectColor(Color(10, 20, 30) * 1.0, 10, 20, 30);
}

TEST(ColorTests, reduce) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: division by a count (averaging samples)
  expectColor(Color(10, 20, 30) / 4, 2.5, 5, 7.5);
  // TC02: a negative divisor is rejected, naming the operation
  EXPECT_THAT([] { (void)(Color(1, 1, 1) / -2); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("reduce")));
  // =============== Boundary Values Tests ==================
  // TC11: division by zero is rejected
  EXPECT_THAT([] { (void)(Color(1, 1, 1) / 0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("reduce")));
  // TC12: division by one changes nothing
  expectColor(Color(10, 20, 30) / 1, 10, 20, 30);
  // TC13: a factor between 0 and 1 brightens
  expectColor(Color(10, 20, 30) / 0.5, 20, 40, 60);
}

TEST(ColorTests, equality) {
  // TC01: equal and different colours
  EXPECT_TRUE(Color(1, 2, 3) == Color(1, 2, 3));
  EXPECT_FALSE(Color(1, 2, 3) == Color(1, 2, 4));
  // TC11: a difference below the zero threshold is equality
  EXPECT_TRUE(Color(1, 2, 3) == Color(1, 2, 3 + 1e-13));
}

TEST(ColorTests, toRgb8) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: in range values are rounded to the nearest integer
  EXPECT_EQ(Color(10.2, 20.7, 30).toRgb8(), (Rgb8{10, 21, 30}));
  // TC02: above 255 is clamped to 255
  EXPECT_EQ(Color(300, 20, 1000).toRgb8(), (Rgb8{255, 20, 255}));
  // =============== Boundary Values Tests ==================
  // TC11: a half rounds up (127.5 -> 128)
  EXPECT_EQ(Color(127.5, 0.5, 254.5).toRgb8(), (Rgb8{128, 1, 255}));
  // TC12: just below a half rounds down
  EXPECT_EQ(Color(127.49, 0.49, 254.49).toRgb8(), (Rgb8{127, 0, 254}));
  // TC13: exactly 0 and exactly 255
  EXPECT_EQ(Color(0, 255, 0).toRgb8(), (Rgb8{0, 255, 0}));
  // TC14: just above 255 is 255
  EXPECT_EQ(Color(255.0001, 255.6, 256).toRgb8(), (Rgb8{255, 255, 255}));
}

}  // namespace
}  // namespace rt
