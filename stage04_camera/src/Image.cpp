#include "camera/Image.h"

#include <stdexcept>
#include <string>

namespace rt {

namespace {
void checkSide(int n, const char* operation, const char* side) {
  if (n < 1 || n > Image::MAX_SIDE) {
    throw std::invalid_argument(std::string(operation) + ": " + side + " must be in [1, " +
                                std::to_string(Image::MAX_SIDE) + "], got " + std::to_string(n));
  }
}
}  // namespace

void Image::checkSize(int nX, int nY, const char* operation) {
  checkSide(nX, operation, "nX");
  checkSide(nY, operation, "nY");
}

namespace {
/// nX·nY, after checking the size: the buffer is never allocated for a bad size.
std::size_t checkedPixelCount(int nX, int nY) {
  Image::checkSize(nX, nY, "Image");
  return static_cast<std::size_t>(nX) * static_cast<std::size_t>(nY);
}
}  // namespace

Image::Image(int nX, int nY) : nX_(nX), nY_(nY), pixels_(checkedPixelCount(nX, nY)) {}

}  // namespace rt
