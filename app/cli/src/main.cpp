// The `rt` executable: the process around rt::cli::runRt (arguments, streams, Ctrl-C).
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "cli/Commands.h"
#include "common/Heap.h"

namespace {

// Raised by Ctrl-C; the render checks it once per row. A lock-free atomic is the one kind of
// shared state a signal handler may touch.
std::atomic<bool> gStop{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void onInterrupt(int) {
  gStop.store(true);
  // A second Ctrl-C ends the process at once, as if rt had no handler.
  std::signal(SIGINT, SIG_DFL);
}

}  // namespace

int main(int argc, char** argv) {
  rt::keepLargeBlocksOutOfTheHeap();
  const std::vector<std::string> args(argv + 1, argv + argc);
  // Only the commands that render (rt render, rt animate, and mini project 2's rt bench) are
  // worth stopping gracefully; the other commands end at once, as usual.
  if (!args.empty() &&
      (args.front() == "render" || args.front() == "animate" || args.front() == "bench"))
    std::signal(SIGINT, onInterrupt);
  const rt::cli::Io io{std::cout, std::cerr, ::isatty(STDERR_FILENO) == 1, &gStop};
  const int code = rt::cli::runRt(args, io);
  std::cout.flush();
  // A full disk, or a file system that refused: what was printed did not all arrive (rt export's
  // scene, rt probe's JSON), so the command failed, whatever it returned. (The reason, errno,
  // is that of the first write that failed, long overwritten by now: not shown.)
  if (!std::cout) {
    std::cerr << "rt: cannot write standard output: what was printed is incomplete\n";
    // rt compare's 1 says that the images differ: its answer lost is its 2, the code of an
    // answer it could not give (an image it cannot read), so that no script reads "different".
    if (!args.empty() && args.front() == "compare") return rt::cli::EXIT_BAD_INPUT;
    return code == 0 ? 1 : code;
  }
  return code;
}
