#include "DealModel.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>

namespace rt::mpi::model {

namespace {

enum class Kind { READY, ARRIVED };

/// A worker ready at `time` with the result of unit `done` (-1: none yet), or its message
/// arrived at rank 0. Earliest first; ties by worker, so the replay is deterministic.
struct Event {
  double time;
  Kind kind;
  int worker;
  long long done;
  bool operator>(const Event& o) const {
    return std::tie(time, worker) > std::tie(o.time, o.worker);
  }
};

}  // namespace

int dealtTileSide(int nX, int nY, std::uint64_t frames, long long threads) {
  int side = 32;
  const auto tiles = [&](int s) {
    return static_cast<unsigned long long>((nX + s - 1) / s) *
           static_cast<unsigned long long>((nY + s - 1) / s) * frames;
  };
  while (side > 8 && tiles(side) < 8ULL * static_cast<unsigned long long>(std::max(threads, 1LL)))
    side /= 2;
  return side;
}

double poolSeconds(const std::vector<double>& seconds, int threads) {
  if (threads < 1)
    throw std::invalid_argument("poolSeconds: threads is " + std::to_string(threads));
  std::priority_queue<double, std::vector<double>, std::greater<>> free;
  for (int t = 0; t < threads; ++t) free.push(0);
  double finish = 0;
  for (const double c : seconds) {
    const double end = free.top() + c;
    free.pop();
    free.push(end);
    finish = std::max(finish, end);
  }
  return finish;
}

Outcome replay(const std::vector<Unit>& units, const Cluster& cluster, const Network& network,
               const Dealer& dealer, std::uint64_t headerBytes) {
  if (cluster.machines < 1 || cluster.workersPerMachine < 1)
    throw std::invalid_argument("replay: a cluster of " + std::to_string(cluster.machines) +
                                " machines of " + std::to_string(cluster.workersPerMachine) +
                                " workers");
  Outcome out;
  for (const Unit& u : units) out.computeSeconds += u.seconds;
  // Units left per frame: the one that brings a frame to zero has it written.
  std::vector<long long> left;
  for (const Unit& u : units) {
    if (u.frame >= static_cast<int>(left.size()))
      left.resize(static_cast<std::size_t>(u.frame) + 1, 0);
    ++left[static_cast<std::size_t>(u.frame)];
  }
  const int workers = cluster.machines * cluster.workersPerMachine;
  std::vector<double> linkOut(static_cast<std::size_t>(cluster.machines), 0);
  double linkIn = 0, dealerFree = 0;
  std::size_t next = 0;  // the dealing counter
  std::priority_queue<Event, std::vector<Event>, std::greater<>> events;
  for (int w = 0; w < workers; ++w) events.push({0, Kind::READY, w, -1});

  const auto written = [&](long long done) {
    return done >= 0 &&
           --left[static_cast<std::size_t>(units[static_cast<std::size_t>(done)].frame)] == 0;
  };
  while (!events.empty()) {
    const Event e = events.top();
    events.pop();
    const int machine = e.worker / cluster.workersPerMachine;
    if (machine == 0 && e.kind == Kind::READY) {
      // Rank 0's own thread: it writes the frame it finished, then takes the next unit.
      double t = e.time;
      if (written(e.done)) t += dealer.perFrameWrite;
      out.seconds = std::max(out.seconds, t);
      if (next == units.size()) continue;
      out.lastUnitStart = std::max(out.lastUnitStart, t);
      const long long u = static_cast<long long>(next++);
      events.push({t + units[static_cast<std::size_t>(u)].seconds, Kind::READY, e.worker, u});
    } else if (e.kind == Kind::READY) {
      // Through its machine's link, then rank 0's (one message at a time each).
      const std::uint64_t bytes =
          e.done < 0 ? headerBytes : units[static_cast<std::size_t>(e.done)].bytes;
      const double transfer = static_cast<double>(bytes) / network.bytesPerSecond;
      double& up = linkOut[static_cast<std::size_t>(machine)];
      const double sent = std::max(e.time, up) + transfer;
      up = sent;
      const double arrived = std::max(sent + network.latency, linkIn + transfer);
      out.linkBusy += transfer;
      linkIn = arrived;
      out.bytes += bytes;
      events.push({arrived, Kind::ARRIVED, e.worker, e.done});
    } else {
      // The dealer, in arrival order: asleep when nothing had come, it wakes at its next poll.
      double t = e.time >= dealerFree ? e.time + dealer.idlePoll / 2 : dealerFree;
      t += dealer.perMessage;
      out.dealerBusy += dealer.perMessage;
      if (written(e.done)) {
        t += dealer.perFrameWrite;
        out.dealerBusy += dealer.perFrameWrite;
      }
      dealerFree = t;
      out.messages += 2;  // the request and its answer
      out.bytes += 8;
      out.seconds = std::max(out.seconds, t);
      if (next == units.size()) continue;
      out.lastUnitStart = std::max(out.lastUnitStart, t);
      const long long u = static_cast<long long>(next++);
      events.push({t + network.latency + units[static_cast<std::size_t>(u)].seconds, Kind::READY,
                   e.worker, u});
    }
  }
  return out;
}

}  // namespace rt::mpi::model
