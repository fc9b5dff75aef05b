// The `rt-mpi` executable: MPI's start and end around rt::mpi::runRtMpi, and the signals.
#include <mpi.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <iostream>
#include <streambuf>
#include <string>
#include <vector>

#include "Distributed.h"
#include "RtMpi.h"
#include "common/Heap.h"

namespace {

// SIGINT (Ctrl-C) and SIGTERM (what mpirun sends every rank when it is interrupted) raise the
// stop flag: the render threads stop within a row, rank 0 writes nothing. A second signal ends
// the process at once.
extern "C" void onStop(int sig) {
  rt::mpi::stopFlag().store(true);
  std::signal(sig, SIG_DFL);
}

#if defined(__SANITIZE_ADDRESS__)
// Under AddressSanitizer (the asan preset): LeakSanitizer's suppressions of OpenMPI's own
// allocations (cmake/lsan.supp) match a frame of libmpi or libopen-rte in the allocation's
// stack, but OpenMPI's libraries have no frame pointers, so the fast unwinder stops in them
// before reaching one: rt-mpi unwinds the slow way (ASAN_OPTIONS can still say otherwise).
extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0"; }
#endif

/// Where the ranks other than 0 print: nowhere (rank 0 speaks for the job).
class NullBuffer final : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

}  // namespace

int main(int argc, char** argv) {
  rt::keepLargeBlocksOutOfTheHeap();
  int provided = MPI_THREAD_SINGLE;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided) != MPI_SUCCESS) {
    std::cerr << "rt-mpi: MPI could not be started (is this run by mpirun or srun?)\n";
    return 1;
  }
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::signal(SIGINT, onStop);
  std::signal(SIGTERM, onStop);
  const std::vector<std::string> args(argv + 1, argv + argc);
  NullBuffer nothing;
  std::ostream silent(&nothing);
  const rt::cli::Io io = rank == 0 ? rt::cli::Io{std::cout, std::cerr, ::isatty(STDERR_FILENO) == 1,
                                                 &rt::mpi::stopFlag()}
                                   : rt::cli::Io{silent, silent, false, &rt::mpi::stopFlag()};
  const int code = rt::mpi::runRtMpi(args, io, MPI_COMM_WORLD, provided >= MPI_THREAD_MULTIPLE);
  std::cout.flush();
  MPI_Finalize();
  return code;
}
