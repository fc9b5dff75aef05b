#pragma once
/// @file ImageDiff.h
/// How far two 8-bit images of the same size are apart, pixel by pixel: what `rt compare` prints
/// and draws, so that a render can be checked against a reference image exactly or within a
/// stated tolerance.
///
/// The measures, over the 8-bit channels as the PNG files hold them (readPng):
/// - the difference of a pixel is the largest of its three channels' absolute differences, 0..255;
/// - PSNR = 10·log10(255² / MSE) dB, where MSE is the mean of the squared channel differences
///   over every channel of every pixel; identical images have MSE = 0 and an infinite PSNR;
/// - a pixel is beyond tolerance T when its difference exceeds T; the images are the same within
///   T when no pixel is (T = 0: identical).

#include <cstdint>

#include "camera/Image.h"
#include "camera/ImageWriter.h"
#include "primitives/Color.h"

namespace rt {

/// How two images of the same size differ.
struct ImageDifference {
  int width = 0, height = 0;
  double psnr = 0;    ///< in dB; +infinity when the images are identical
  int largest = 0;    ///< the largest difference of a pixel, 0..255
  int largestX = -1;  ///< the first pixel (in row order) with the largest difference;
  int largestY = -1;  ///< -1 when the images are identical
  std::uint64_t beyondTolerance = 0;  ///< pixels whose difference exceeds the tolerance
  std::uint64_t pixels = 0;           ///< width × height

  /// True when no pixel's difference exceeds the tolerance.
  bool withinTolerance() const { return beyondTolerance == 0; }
};

/// The difference of a and b with tolerance (0..255).
/// @throws std::invalid_argument when the sizes differ or the tolerance is outside 0..255.
ImageDifference compareImages(const Rgb8Image& a, const Rgb8Image& b, int tolerance);

/// The colour of the heat map for a pixel whose difference is d, in an image whose largest is
/// largest (0 <= d <= largest): black for d = 0; otherwise a ramp over t = d / largest through
/// blue (t → 0), cyan (1/4), green (1/2), yellow (3/4) to red (t = 1), linear between them, so
/// that every differing pixel shows, the worst ones red.
Color differenceColor(int d, int largest);

/// The heat map of a and b (same size): differenceColor of every pixel.
/// @throws std::invalid_argument when the sizes differ.
Image differenceMap(const Rgb8Image& a, const Rgb8Image& b);

}  // namespace rt
