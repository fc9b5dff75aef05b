#pragma once
// Runs rt in the test's process (runRt: main without the process) and captures its exit code and
// both streams; a fresh directory for a test's files under the build tree's cli-test-output/.

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/Commands.h"

namespace rt::cli::test {

struct Outcome {
  int code;
  std::string out, err;
};

inline Outcome run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = runRt(args, Io{out, err});
  return {code, out.str(), err.str()};
}

/// cli-test-output/NAME, emptied (relative: the messages that quote it stay short).
inline std::string freshTestDirectory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path("cli-test-output") / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace rt::cli::test
