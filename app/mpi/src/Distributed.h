#pragma once
// The distributed render: frames (one for rt-mpi render, a camera path's for rt-mpi animate) cut
// into units of work that rank 0 deals on demand, each rank rendering with its own threads.
//
//     units      tiles mode: every frame's tiles (TileGrid's order), frame after frame
//                frames mode: whole frames (rt-mpi animate with at least as many frames as
//                ranks): a rank renders a frame with all its threads
//     rank 0     deals: one atomic counter, read by its own render threads and, for the other
//                ranks, by its main thread, which answers each request (MPI_Iprobe, then a
//                sleep of 50 µs to 1 ms when nothing came) with the next unit, or "no more"
//                assembles: each result's pixels go into the frame's image; a frame complete is
//                finished (grid lines) and written atomically, then freed
//     rank r > 0 each render thread (tiles) or the main thread (frames): send the last result
//                (it is the request for the next unit), receive the next unit, render it
//
// Each unit's pixels travel as the doubles of its colours, so rank 0 writes the image rt render
// would: every pixel is a function of (scene, options, pixel) only. A failure on any rank (an
// exception while rendering, a signal) stops the dealing: every thread is answered "stop", no
// image is written, and rank 0 reports the first failure with its rank and host.

#include <mpi.h>

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "Wire.h"
#include "camera/CameraSpec.h"
#include "camera/RayTracer.h"
#include "camera/RenderBlock.h"
#include "cli/Commands.h"
#include "scenefile/SceneDocument.h"

namespace rt::mpi {

/// What every rank renders: the same on every rank, but for the outputs (rank 0's).
struct JobSpec {
  const SceneDocument& doc;
  const RayTracer& tracer;
  const PixelSampler& sampler;
  std::vector<CameraSpec> cameras;   ///< the frames to render, in order
  std::vector<std::string> outputs;  ///< rank 0: frame i's path (same length as cameras)
  std::optional<int> gridLines;      ///< --grid-lines, over the scene's render.gridLines
  bool wholeFrames = false;          ///< deal frames, not tiles
  int tileSize = 32;                 ///< the tiles' side (tiles mode; RtMpi: dealtTileSide)
  int threads = 1;                   ///< this rank's render threads (>= 1)
};

/// What the job did, as rank 0 knows it.
struct JobOutcome {
  RayCounts counts;                        ///< every rank's rays
  std::optional<RankFailure> failure;      ///< the first failure, if any
  bool interrupted = false;                ///< a rank was stopped by a signal
  std::uint64_t units = 0;                 ///< units dealt
  std::vector<std::uint64_t> unitsByRank;  ///< units each rank rendered (index: rank)
  std::uint64_t messages = 0;              ///< messages rank 0 received and sent
  std::uint64_t bytes = 0;                 ///< their bytes
  int framesWritten = 0;                   ///< frames complete and written
};

/// Raised by a signal (SIGINT, SIGTERM) on this rank: its threads stop at the next row.
std::atomic<bool>& stopFlag();

/// Rank 0's part. hosts: every rank's host name; threads: every rank's render threads.
/// donePixels and doneRays are added to as results come, for the progress display.
JobOutcome runDealer(const JobSpec& spec, const std::vector<std::string>& hosts,
                     const std::vector<int>& threads, std::atomic<std::uint64_t>& donePixels,
                     std::atomic<std::uint64_t>& doneRays, MPI_Comm comm);

/// The part of a rank other than 0: it returns when rank 0 says there is nothing more (or to
/// stop).
void runWorker(const JobSpec& spec, MPI_Comm comm);

}  // namespace rt::mpi
