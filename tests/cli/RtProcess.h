#pragma once
// Runs the built `rt` program (RT_EXE) as a child process, as a user would, and captures its exit
// status and both streams. No shell is involved, so arguments need no quoting.

#include <sys/types.h>

#include <string>
#include <vector>

#include "TestFiles.h"  // readFile, which the tests that run rt read its files with

namespace rt::cli::test {

struct RtResult {
  int exitCode = -1;  ///< the exit code, or -1 when the process was killed by a signal
  std::string out;
  std::string err;
};

struct RtOptions {
  std::string cwd;              ///< working directory; empty: the test's
  bool asUnprivileged = false;  ///< when running as root, drop to nobody (65534) first
  std::string path;             ///< the child's PATH; empty: the test's
};

/// Runs RT_EXE with args and waits for it.
RtResult runRt(const std::vector<std::string>& args, const RtOptions& options = {});

/// Runs the program argv[0] (a path) with the arguments after it, and waits for it.
RtResult runProgram(const std::vector<std::string>& argv, const RtOptions& options = {});

/// A whole command line, program first: what RtChild runs instead of RT_EXE.
struct Program {
  std::vector<std::string> argv;
};

/// A running `rt` whose stderr the test reads line by line (to interrupt it at a known point).
class RtChild {
 public:
  explicit RtChild(const std::vector<std::string>& args);
  explicit RtChild(const Program& program);
  ~RtChild();
  RtChild(const RtChild&) = delete;
  RtChild& operator=(const RtChild&) = delete;

  /// Reads stderr until a line contains text; returns false at end of stream.
  bool waitForLine(const std::string& text);
  void signal(int sig);
  /// Waits for the process, drains stderr, returns the exit code (-1 if killed by a signal).
  int wait();
  pid_t pid() const { return pid_; }
  const std::string& err() const { return err_; }

 private:
  pid_t pid_ = -1;
  int errFd_ = -1;
  std::string err_;
  std::size_t scanned_ = 0;
};

/// A fresh, empty directory for one test, under the build tree's cli-test-output/: the absolute
/// path of freshTestDirectory(name) (TestFiles.h), for a child run in another directory.
std::string freshDirectory(const std::string& name);

}  // namespace rt::cli::test
