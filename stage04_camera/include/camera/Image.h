#pragma once
/// @file Image.h

#include <vector>

#include "primitives/Color.h"

namespace rt {

/// nX x nY unclamped colours, row-major, (0,0) top-left: x = column, y = row.
class Image {
 public:
  Image() = default;
  /// @throws std::invalid_argument unless 1 <= nX, nY <= MAX_SIDE.
  Image(int nX, int nY);

  int nX() const { return nX_; }
  int nY() const { return nY_; }
  const Color& pixel(int x, int y) const { return pixels_[index(x, y)]; }
  void setPixel(int x, int y, const Color& c) { pixels_[index(x, y)] = c; }

  /// The largest accepted side: 2^15 pixels.
  static constexpr int MAX_SIDE = 1 << 15;
  /// @throws std::invalid_argument, naming the operation, the side and its value, unless
  ///         1 <= nX, nY <= MAX_SIDE. Shared by the Image constructor and Camera::Builder.
  static void checkSize(int nX, int nY, const char* operation);

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * nX_ + x; }
  int nX_ = 0, nY_ = 0;
  std::vector<Color> pixels_;
};

}  // namespace rt
