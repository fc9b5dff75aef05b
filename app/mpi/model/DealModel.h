#pragma once
// A model of rt-mpi's dealing, for machines this project does not have: the units of a job
// (tiles, or whole frames) with their costs measured on one core, replayed on a cluster of
// machines as rt-mpi deals them (app/mpi/src/Distributed.h):
//
//     rank 0      one rank per machine; rank 0's render threads take units from the counter
//                 directly; its main thread (the dealer) answers the other ranks one message at
//                 a time, in the order the messages arrive, and writes a frame whose last pixels
//                 it received (a frame finished by one of rank 0's threads is written by it)
//     a request   a rank's thread sends its last result (header + pixels) as the request for
//                 the next unit; it waits for the answer, then renders the unit
//     the network each machine's link out, and rank 0's link in, carry one message at a time at
//                 the link's rate (FIFO); a message also takes the latency; answers are 8 bytes
//
// What it leaves out: rank 0's dealer competing with its render threads for the machine's cores
// (its busy share is reported), a machine's cores slowing each other down (shared caches and
// memory), and a slow or failed machine. Every figure is a function of its inputs: the replay
// is deterministic.

#include <cstdint>
#include <vector>

namespace rt::mpi::model {

/// One unit of work: what it costs one of the worker's threads and what its result weighs.
struct Unit {
  double seconds = 0;       ///< the worker's time to render it (a thread's, or a rank's pool's)
  std::uint64_t bytes = 0;  ///< the result's message: header and pixels
  int frame = 0;            ///< the frame it belongs to (units of a frame are consecutive)
};

struct Cluster {
  int machines = 1;           ///< one rank each; rank 0's machine is the first
  int workersPerMachine = 1;  ///< threads asking for units on each rank (frames mode: 1)
};

struct Network {
  double bytesPerSecond = 117.5e6;  ///< each link's rate (1 Gbit/s Ethernet, TCP's payload)
  double latency = 50e-6;           ///< one way, a message (MPI over TCP on a lab's switch)
};

struct Dealer {
  double perMessage = 10e-6;  ///< rank 0's main thread per message (receive, copy, answer)
  double idlePoll = 1e-3;     ///< its longest sleep when nothing came: an idle dealer answers
                              ///< half of it later (rt-mpi sleeps 50 µs, doubled up to 1 ms)
  double perFrameWrite = 0;   ///< finishing and writing one frame (PNG)
};

struct Outcome {
  double seconds = 0;          ///< the job's end: the last frame written
  double computeSeconds = 0;   ///< the units' costs, summed
  double dealerBusy = 0;       ///< the dealer's busy time (messages and the frames it wrote)
  double linkBusy = 0;         ///< rank 0's link in: the time it carried messages
  std::uint64_t messages = 0;  ///< messages rank 0 received and answered
  std::uint64_t bytes = 0;     ///< the bytes it received
  double lastUnitStart = 0;    ///< when the last unit was dealt
};

/// Replays units (in dealing order) on the cluster. headerBytes is a request without a result
/// (a thread's first). @throws std::invalid_argument for a cluster of no machine or no worker.
Outcome replay(const std::vector<Unit>& units, const Cluster& cluster, const Network& network,
               const Dealer& dealer, std::uint64_t headerBytes);

/// The side of the tiles rt-mpi deals for frames of nX x nY pixels to `threads` render threads
/// in all: 32 (the tile pool's), halved down to 8 while the job would have fewer than 8 tiles a
/// thread. The model's reason (docs/distributed.md): on the galaxy the costliest tile of 32 costs
/// 7 % of a machine's frame time, which caps a frame at about 11 machines' speed-up however
/// many there are; tiles of 16 and 8 cost a quarter and a sixteenth of that, for four and
/// sixteen times the messages. Any side gives the same image.
int dealtTileSide(int nX, int nY, std::uint64_t frames, long long threads);

/// The time `threads` threads of one rank's tile pool take for tiles costing seconds each, taken
/// in order by whichever thread is free first (the pool's schedule).
double poolSeconds(const std::vector<double>& seconds, int threads);

}  // namespace rt::mpi::model
