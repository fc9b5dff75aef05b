#pragma once
// The files and questions the tests of `rt` share: a fresh directory for a test's files under the
// build tree's cli-test-output/, a file written with given text and a file's bytes read back, and
// whether this build has the stage of a tracer (the tests of every course cut expect the answer
// of their own build).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include "scenefile/SceneFile.h"

namespace rt::cli::test {

/// cli-test-output/NAME, emptied (relative: the messages that quote it stay short).
inline std::string freshTestDirectory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path("cli-test-output") / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

/// Writes text to path, byte for byte; returns path.
inline std::string writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// The file's bytes, or "" when it does not exist.
inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// True when this build has the stage that adds the tracer (a tracer of the course).
inline bool hasTracer(std::string_view tracer) { return missingTracerStage(tracer).empty(); }

}  // namespace rt::cli::test
