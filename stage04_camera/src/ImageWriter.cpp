#include "camera/ImageWriter.h"

// stb comes from Debian's libstb-dev: declarations only here, the implementation is in libstb.
#include <stb_image.h>
#include <stb_image_write.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

namespace rt {

namespace {

[[noreturn]] void throwWriteFailure(const std::string& path, const std::string& why) {
  throw std::runtime_error("PngImageWriter: cannot write '" + path + "': " + why);
}

std::string errnoMessage(int err) { return std::generic_category().message(err); }

/// Creates a new, empty file in the directory of path, with a name no other writer uses: the
/// "x" mode fails when the file exists, so two writers never share one.
/// @throws std::runtime_error naming path when the directory does not accept a new file.
std::FILE* createTemporaryBeside(const std::string& path, std::string& tmpPath) {
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::random_device random;
  for (int attempt = 0; attempt < 16; ++attempt) {
    char name[40];
    std::snprintf(name, sizeof name, ".rt-%08x%08x.tmp", random(), random());
    tmpPath = (dir / name).string();
    if (std::FILE* file = std::fopen(tmpPath.c_str(), "wbx")) return file;
    const int err = errno;
    if (err != EEXIST) {
      throwWriteFailure(path,
                        "cannot create the temporary file '" + tmpPath + "': " + errnoMessage(err));
    }
  }
  throwWriteFailure(path, "no free temporary file name in its directory");
}

/// Where stb_image_write sends the encoded bytes: the temporary file, remembering a failure.
struct FileSink {
  std::FILE* file;
  int error = 0;
};

void writeToSink(void* context, void* data, int size) {
  auto* sink = static_cast<FileSink*>(context);
  if (sink->error != 0 || size <= 0) return;
  if (std::fwrite(data, 1, static_cast<std::size_t>(size), sink->file) !=
      static_cast<std::size_t>(size)) {
    sink->error = errno != 0 ? errno : EIO;
  }
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

  // Encode into a temporary file beside path, then rename it over path: the rename is atomic
  // within a directory, so path holds either its old content or the complete new image.
  std::string tmpPath;
  FileSink sink{createTemporaryBeside(path, tmpPath)};
  errno = 0;
  const int encoded = stbi_write_png_to_func(writeToSink, &sink, nX, nY, 3, rgb.data(), nX * 3);
  const bool closed = std::fclose(sink.file) == 0;
  const int closeError = errno;
  if (!encoded || sink.error != 0 || !closed) {
    std::remove(tmpPath.c_str());
    const int err = sink.error != 0 ? sink.error : closeError;
    throwWriteFailure(path, !encoded ? std::string("PNG encoding failed")
                                     : "writing the temporary file '" + tmpPath +
                                           "' failed: " + errnoMessage(err != 0 ? err : EIO));
  }
  if (std::rename(tmpPath.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmpPath.c_str());
    throwWriteFailure(path, "cannot rename the temporary file over it: " + errnoMessage(err));
  }
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
