// Stage 4: the difference of two 8-bit images (camera/ImageDiff.h): PSNR, the largest pixel
// difference and where it first is, the pixels beyond a tolerance, and the heat map's colours.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "camera/ImageDiff.h"

namespace rt {
namespace {

Rgb8Image image(int width, int height, std::vector<unsigned char> rgb) {
  Rgb8Image out;
  out.width = width;
  out.height = height;
  out.rgb = std::move(rgb);
  return out;
}

Rgb8Image black(int width, int height) {
  return image(width, height, std::vector<unsigned char>(3 * width * height, 0));
}

std::string invalidArgument(const auto& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

TEST(ImageDiffTests, compareImages) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: identical images: infinite PSNR, no difference, no pixel beyond tolerance 0
  const ImageDifference same = compareImages(black(3, 2), black(3, 2), 0);
  EXPECT_EQ(same.width, 3);
  EXPECT_EQ(same.height, 2);
  EXPECT_EQ(same.pixels, 6u);
  EXPECT_EQ(same.psnr, std::numeric_limits<double>::infinity());
  EXPECT_EQ(same.largest, 0);
  EXPECT_EQ(same.largestX, -1);
  EXPECT_EQ(same.largestY, -1);
  EXPECT_EQ(same.beyondTolerance, 0u);
  EXPECT_TRUE(same.withinTolerance());

  // TC02: one pixel off by (3, 0, 4) of two: the largest is its largest channel, 4; the MSE is
  // (9 + 16) / 6 channels
  const Rgb8Image a = black(2, 1);
  const Rgb8Image b = image(2, 1, {0, 0, 0, 3, 0, 4});
  const ImageDifference d = compareImages(a, b, 0);
  EXPECT_EQ(d.largest, 4);
  EXPECT_EQ(d.largestX, 1);
  EXPECT_EQ(d.largestY, 0);
  EXPECT_EQ(d.beyondTolerance, 1u);
  EXPECT_FALSE(d.withinTolerance());
  EXPECT_DOUBLE_EQ(d.psnr, 10 * std::log10(255.0 * 255.0 / (25.0 / 6.0)));
  // TC03: the order of the images does not matter
  EXPECT_DOUBLE_EQ(compareImages(b, a, 0).psnr, d.psnr);

  // TC04: the largest difference first in row order: (2, 0) before (1, 1)
  const Rgb8Image c = image(3, 2, {0, 0, 0, 0, 0, 0, 0, 9, 0, 0, 0, 0, 9, 0, 0, 0, 0, 0});
  const ImageDifference first = compareImages(black(3, 2), c, 0);
  EXPECT_EQ(first.largest, 9);
  EXPECT_EQ(first.largestX, 2);
  EXPECT_EQ(first.largestY, 0);
  EXPECT_EQ(first.beyondTolerance, 2u);

  // =============== Boundary Values Tests ==================
  // TC11: every channel off by 255: MSE = 255², PSNR exactly 0 dB
  EXPECT_EQ(compareImages(black(1, 1), image(1, 1, {255, 255, 255}), 0).psnr, 0.0);
  // TC12: a difference equal to the tolerance is within it; one above is beyond
  EXPECT_TRUE(compareImages(a, b, 4).withinTolerance());
  EXPECT_EQ(compareImages(a, b, 3).beyondTolerance, 1u);
  // TC13: the tolerance's ends 0 and 255 are accepted, -1 and 256 refused, naming the value
  EXPECT_TRUE(compareImages(a, b, 255).withinTolerance());
  EXPECT_EQ(invalidArgument([&] { (void)compareImages(a, b, -1); }),
            "compareImages: the tolerance must be from 0 to 255, got -1");
  EXPECT_EQ(invalidArgument([&] { (void)compareImages(a, b, 256); }),
            "compareImages: the tolerance must be from 0 to 255, got 256");
  // TC14: images of different sizes are refused, naming both
  EXPECT_EQ(invalidArgument([&] { (void)compareImages(black(2, 1), black(1, 2), 0); }),
            "compareImages: the images differ in size (2x1 and 1x2)");
}

TEST(ImageDiffTests, differenceColor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: no difference is black
  EXPECT_EQ(differenceColor(0, 8).rgb(), Double3(0, 0, 0));
  // TC02: the ramp's stops: cyan at 1/4, green at 1/2, yellow at 3/4, red at 1
  EXPECT_EQ(differenceColor(2, 8).rgb(), Double3(0, 255, 255));
  EXPECT_EQ(differenceColor(4, 8).rgb(), Double3(0, 255, 0));
  EXPECT_EQ(differenceColor(6, 8).rgb(), Double3(255, 255, 0));
  EXPECT_EQ(differenceColor(8, 8).rgb(), Double3(255, 0, 0));
  // TC03: linear between the stops: 1/8 is half way from blue to cyan, 5/8 from green to yellow
  EXPECT_EQ(differenceColor(1, 8).rgb(), Double3(0, 127.5, 255));
  EXPECT_EQ(differenceColor(5, 8).rgb(), Double3(127.5, 255, 0));

  // =============== Boundary Values Tests ==================
  // TC11: the smallest difference of a wide range is nearly blue, never black
  const double f = 1.0 / 255 * 4;  // t · 4 within the first segment
  EXPECT_EQ(differenceColor(1, 255).rgb(), Double3(0, 255 * f, 255));
  // TC12: a largest of 0 (identical images) keeps d = 0 black; d above largest is red
  EXPECT_EQ(differenceColor(0, 0).rgb(), Double3(0, 0, 0));
  EXPECT_EQ(differenceColor(9, 8).rgb(), Double3(255, 0, 0));
}

TEST(ImageDiffTests, differenceMap) {
  // TC01: every pixel its differenceColor against the image's largest difference (4): the
  // pixel off by 4 red, the one off by 2 green, the equal one black
  const Rgb8Image a = black(3, 1);
  const Rgb8Image b = image(3, 1, {0, 4, 0, 0, 0, 0, 2, 1, 0});
  const Image map = differenceMap(a, b);
  ASSERT_EQ(map.nX(), 3);
  ASSERT_EQ(map.nY(), 1);
  EXPECT_EQ(map.pixel(0, 0).rgb(), Double3(255, 0, 0));
  EXPECT_EQ(map.pixel(1, 0).rgb(), Double3(0, 0, 0));
  EXPECT_EQ(map.pixel(2, 0).rgb(), Double3(0, 255, 0));
  // TC02: identical images make a black map
  const Image none = differenceMap(a, a);
  for (int x = 0; x < 3; ++x) EXPECT_EQ(none.pixel(x, 0).rgb(), Double3(0, 0, 0));
  // TC03: images of different sizes are refused, naming both
  EXPECT_EQ(invalidArgument([&] { (void)differenceMap(black(2, 1), black(1, 2)); }),
            "differenceMap: the images differ in size (2x1 and 1x2)");
}

}  // namespace
}  // namespace rt
