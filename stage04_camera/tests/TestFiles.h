#pragma once
// Files for stage 4's tests (images, atomic writes): a fresh directory per test under the build
// directory (the tests' working directory), in test-images/stage04/, and reading back.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace rt::test {

/// A fresh, empty directory for one test: test-images/stage04/NAME.
inline std::filesystem::path testDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path("test-images") / "stage04" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The file's bytes, or "" when it cannot be read.
inline std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// How many entries a directory has (to see that no temporary file is left behind).
inline std::size_t entries(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir),
                                                std::filesystem::directory_iterator{}));
}

}  // namespace rt::test
