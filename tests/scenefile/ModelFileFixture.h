#pragma once
// The fixture of the tests that read model files: skipped in a build without Assimp, each test
// given a fresh temporary directory (removed after it) for the files it writes.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <system_error>

#include "scenefile/ModelFile.h"

namespace rt::testing {

class ModelFileFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!modelFilesSupported())
      GTEST_SKIP() << "reading model files needs Assimp: install libassimp-dev (scripts/deps.sh "
                      "installs it)";
    std::random_device rd;
    dir_ = std::filesystem::temp_directory_path() / ("rt-model-tests-" + std::to_string(rd()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) std::filesystem::remove_all(dir_, ec);
  }

  /// Writes bytes to dir/name (its folders made) and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& bytes) const {
    const std::filesystem::path p = dir_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p;
  }

  std::filesystem::path dir_;
};

}  // namespace rt::testing
