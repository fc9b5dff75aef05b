#pragma once
/// @file ImageWriter.h

#include <array>
#include <string>
#include <vector>

#include "camera/Image.h"

namespace rt {

/// Writes an image to a file. Colours are clamped to 255 per channel here and nowhere else.
class ImageWriter {
 public:
  virtual ~ImageWriter() = default;
  /// @throws std::runtime_error naming the path when the file cannot be written; an existing
  ///         file at path is then left untouched.
  virtual void write(const Image& image, const std::string& path) const = 0;
};

/// PNG through stb_image_write, written with writeFileAtomically (camera/AtomicFile.h): a failed
/// write never leaves a half-written image.
class PngImageWriter final : public ImageWriter {
 public:
  void write(const Image& image, const std::string& path) const override;
};

/// 8-bit RGB pixels read back from a PNG (for tests and tools).
struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  ///< row-major, 3 bytes per pixel
  /// {r, g, b} of pixel (x, y).
  std::array<unsigned char, 3> at(int x, int y) const;
};

/// @throws std::runtime_error naming the path when it cannot be read as an image.
Rgb8Image readPng(const std::string& path);

}  // namespace rt
