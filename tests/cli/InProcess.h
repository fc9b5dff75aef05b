#pragma once
// Runs `rt` in the test's own process (rt::cli::runRt: the executable's code without the process)
// and captures its exit code and both streams (and, from TestFiles.h, a fresh directory for a
// test's files under the build tree's cli-test-output/). The tests of every course cut and of the
// whole course share it.

#include <atomic>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "TestFiles.h"
#include "cli/Commands.h"

namespace rt::cli::test {

struct Outcome {
  int code;
  std::string out, err;
};

/// rt with args (without the program's name); stop, when given, is the Ctrl-C flag.
inline Outcome run(const std::vector<std::string>& args, const std::atomic<bool>* stop = nullptr) {
  std::ostringstream out, err;
  const int code = runRt(args, Io{out, err, false, stop});
  return {code, out.str(), err.str()};
}

/// text's lines, without their line breaks.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

}  // namespace rt::cli::test
