#include "camera/ImageDiff.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

void requireSameSize(const Rgb8Image& a, const Rgb8Image& b, const char* operation) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument(std::string(operation) + ": the images differ in size (" +
                                std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
                                std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
}

/// The largest of a pixel's three channel differences, and the sum of their squares.
struct PixelDifference {
  int largest = 0;
  std::uint64_t squares = 0;
};

PixelDifference pixelDifference(const Rgb8Image& a, const Rgb8Image& b, std::size_t pixel) {
  PixelDifference d;
  for (std::size_t c = 0; c < 3; ++c) {
    const int delta = std::abs(int{a.rgb[3 * pixel + c]} - int{b.rgb[3 * pixel + c]});
    d.largest = std::max(d.largest, delta);
    d.squares += static_cast<std::uint64_t>(delta * delta);
  }
  return d;
}

}  // namespace

ImageDifference compareImages(const Rgb8Image& a, const Rgb8Image& b, int tolerance) {
  requireSameSize(a, b, "compareImages");
  if (tolerance < 0 || tolerance > 255)
    throw std::invalid_argument("compareImages: the tolerance must be from 0 to 255, got " +
                                std::to_string(tolerance));
  ImageDifference out;
  out.width = a.width;
  out.height = a.height;
  out.pixels = static_cast<std::uint64_t>(a.width) * static_cast<std::uint64_t>(a.height);
  std::uint64_t squares = 0;
  for (std::size_t i = 0; i < out.pixels; ++i) {
    const PixelDifference d = pixelDifference(a, b, i);
    squares += d.squares;
    if (d.largest > tolerance) ++out.beyondTolerance;
    if (d.largest > out.largest) {
      out.largest = d.largest;
      out.largestX = static_cast<int>(i % static_cast<std::size_t>(a.width));
      out.largestY = static_cast<int>(i / static_cast<std::size_t>(a.width));
    }
  }
  // PSNR = 10·log10(255² / MSE), MSE over every channel of every pixel.
  const double mse = static_cast<double>(squares) / (3.0 * static_cast<double>(out.pixels));
  out.psnr =
      squares == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
  return out;
}

Color differenceColor(int d, int largest) {
  if (d <= 0) return Color::BLACK;
  // The ramp's five stops at t = 0, 1/4, 1/2, 3/4, 1: blue, cyan, green, yellow, red.
  static constexpr double STOPS[5][3] = {
      {0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}};
  const double t = std::clamp(static_cast<double>(d) / std::max(largest, 1), 0.0, 1.0);
  const int k = std::min(3, static_cast<int>(t * 4));  // the segment [k/4, (k+1)/4]
  const double f = t * 4 - k;
  const auto mix = [&](int c) { return STOPS[k][c] + (STOPS[k + 1][c] - STOPS[k][c]) * f; };
  return Color(mix(0), mix(1), mix(2));
}

Image differenceMap(const Rgb8Image& a, const Rgb8Image& b) {
  requireSameSize(a, b, "differenceMap");
  const std::size_t pixels = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
  int largest = 0;
  for (std::size_t i = 0; i < pixels; ++i)
    largest = std::max(largest, pixelDifference(a, b, i).largest);
  Image map(a.width, a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(a.width) + x;
      map.setPixel(x, y, differenceColor(pixelDifference(a, b, i).largest, largest));
    }
  return map;
}

}  // namespace rt
