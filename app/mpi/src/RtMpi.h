#pragma once
// rt-mpi's command line, run by every rank of the job together.

#include <mpi.h>

#include <span>
#include <string>

#include "cli/Commands.h"

namespace rt::mpi {

/// Runs rt-mpi with rank 0's args (without the program's name) on every rank of comm; returns
/// the exit code, the same on every rank. Only rank 0 prints (io), "rt-mpi: " before each line.
/// threadsMayCallMpi: the MPI library gave MPI_THREAD_MULTIPLE (a rank's render threads then ask
/// for tiles themselves; without it, the ranks other than 0 render tiles with one thread).
int runRtMpi(std::span<const std::string> args, const cli::Io& io, MPI_Comm comm,
             bool threadsMayCallMpi);

}  // namespace rt::mpi
