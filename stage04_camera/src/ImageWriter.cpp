#include "camera/ImageWriter.h"

// stb comes from Debian's libstb-dev: declarations only here, the implementation is in libstb.
#include <stb_image.h>
#include <stb_image_write.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "camera/AtomicFile.h"

namespace rt {

namespace {

/// Where stb_image_write sends the encoded bytes: the temporary file. A failed fwrite sets the
/// stream's error flag, which writeFileAtomically checks.
void writeToFile(void* context, void* data, int size) {
  if (size > 0)
    std::fwrite(data, 1, static_cast<std::size_t>(size), static_cast<std::FILE*>(context));
}

}  // namespace

void PngImageWriter::write(const Image& image, const std::string& path) const {
  const int nX = image.nX();
  const int nY = image.nY();
  if (nX < 1 || nY < 1) {
    throw std::invalid_argument("PngImageWriter: the image to write to '" + path + "' is empty (" +
                                std::to_string(nX) + "x" + std::to_string(nY) + ")");
  }

  // Clamp to 8 bits here, and only here: the image itself keeps the unbounded colours.
  std::vector<unsigned char> rgb(static_cast<std::size_t>(nX) * static_cast<std::size_t>(nY) * 3);
  std::size_t k = 0;
  for (int y = 0; y < nY; ++y) {
    for (int x = 0; x < nX; ++x) {
      for (std::uint8_t channel : image.pixel(x, y).toRgb8()) rgb[k++] = channel;
    }
  }

  // Encode into a temporary file beside path, then rename it over path: path holds either its
  // old content or the complete new image.
  writeFileAtomically(path, [&](std::FILE* file) -> std::string {
    return stbi_write_png_to_func(writeToFile, file, nX, nY, 3, rgb.data(), nX * 3)
               ? ""
               : "PNG encoding failed";
  });
}

std::array<unsigned char, 3> Rgb8Image::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= width || y >= height) {
    throw std::out_of_range("Rgb8Image::at: pixel (" + std::to_string(x) + "," + std::to_string(y) +
                            ") is outside the " + std::to_string(width) + "x" +
                            std::to_string(height) + " image");
  }
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)) *
                        3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

Rgb8Image readPng(const std::string& path) {
  int width = 0, height = 0, channelsInFile = 0;
  unsigned char* data = stbi_load(path.c_str(), &width, &height, &channelsInFile, 3);
  if (data == nullptr) {
    const char* reason = stbi_failure_reason();
    throw std::runtime_error("readPng: cannot read '" + path +
                             "' as an image: " + (reason != nullptr ? reason : "unknown error"));
  }
  Rgb8Image image;
  image.width = width;
  image.height = height;
  image.rgb.assign(data,
                   data + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  stbi_image_free(data);
  return image;
}

}  // namespace rt
