// mpi_deal_model: rt-mpi's dealing modelled for clusters this project does not have, from the
// tile costs of a real render measured on this machine (a benchmark: it prints figures).
//
//   build/release/bin/mpi_deal_model [SCENE] [--width W] [--cores C] [--machines 1,4,16,64]
//                                    [--frames F] [--gbit G] [--tile 32]
//
// 1. Every 8 x 8 tile of SCENE (default: the galaxy) rendered alone, as `rt render SCENE`
//    renders it (at the scene's own size, the galaxy's 1280 x 720 the README's main image;
//    --width W as rt's), its cost the thread's CPU time; tiles of 16, 32 and 64 cost the sum
//    of their 8 x 8 tiles. Finishing and writing the frame (its PNG) is timed too.
// 2. One frame: the tiles dealt to machines of C cores (default 8; one rank per machine, C
//    threads each) over links of G Gbit/s (default 1), replayed (app/mpi/model/DealModel.h), for
//    tiles of 8, 16, 32 and 64: the predicted time, the speed-up over one machine and over one
//    core, and the bounds that stop it: the compute spread over every core, rank 0's link
//    (every pixel's 24 bytes through it), the costliest tile, and rank 0's dealer (its time
//    answering messages and writing the frame).
// 3. An orbit of F frames (default 360), dealt as whole frames (rt-mpi animate with at least as
//    many frames as ranks), each frame costing the measured one on a rank's pool of C threads;
//    then the same if a frame travelled as its 8-bit pixels (3 bytes a pixel, not 24).
// 4. This machine: 1 rank x 2 threads and 2 ranks x 1 thread through shared memory, to hold
//    against the measured runs (docs/distributed.md).
// Nothing here needs MPI: the model is built with or without it.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "DealModel.h"
#include "benchmark/Measure.h"
#include "camera/Camera.h"
#include "cli/RenderCommand.h"
#include "cli/RenderRequest.h"
#include "parallel/TileGrid.h"

namespace rt::mpi::model {
namespace {

constexpr std::uint64_t HEADER_BYTES = 40;  // rt-mpi's WorkHeader
constexpr std::uint64_t PIXEL_BYTES = 24;   // three doubles

struct Options {
  std::string scene = "galaxy";
  std::optional<int> width;  ///< the scene's own when not given, as rt render
  int cores = 8;
  std::vector<int> machines{1, 4, 16, 64};
  int frames = 360;
  double gbit = 1;
  int tile = 32;
};

std::vector<int> parseList(const std::string& text, const char* option) {
  std::vector<int> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    char* end = nullptr;
    const long v = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || v < 1 || v > 100000)
      throw std::invalid_argument(std::string(option) +
                                  ": expected counts from 1 to 100000, got '" + item + "'");
    out.push_back(static_cast<int>(v));
    start = comma + 1;
  }
  return out;
}

double parseNumber(const std::string& text, const char* option, double lo, double hi) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(v >= lo && v <= hi))
    throw std::invalid_argument(std::string(option) + ": expected a number from " +
                                std::to_string(lo) + " to " + std::to_string(hi) + ", got '" +
                                text + "'");
  return v;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + ": expected a value after it");
      return argv[++i];
    };
    if (a == "--width")
      o.width = static_cast<int>(parseNumber(value(), "--width", 16, 16384));
    else if (a == "--cores")
      o.cores = static_cast<int>(parseNumber(value(), "--cores", 1, 1024));
    else if (a == "--machines")
      o.machines = parseList(value(), "--machines");
    else if (a == "--frames")
      o.frames = static_cast<int>(parseNumber(value(), "--frames", 1, 100000));
    else if (a == "--gbit")
      o.gbit = parseNumber(value(), "--gbit", 0.001, 1000);
    else if (a == "--tile")
      o.tile = static_cast<int>(parseNumber(value(), "--tile", 8, 64));
    else if (!a.empty() && a[0] == '-')
      throw std::invalid_argument("unknown option '" + a + "'");
    else
      o.scene = a;
  }
  if (o.tile % 8 != 0) throw std::invalid_argument("--tile: expected a multiple of 8 from 8 to 64");
  return o;
}

/// Tiles of `side` (a multiple of 8) in TileGrid's order, each costing the sum of its 8 x 8
/// tiles.
std::vector<Unit> tilesOf(const TileGrid& fine, const std::vector<double>& fineCost, int nX, int nY,
                          int side) {
  const TileGrid grid(nX, nY, side);
  std::map<std::pair<int, int>, std::size_t> index;  // a tile's corner -> its dealing index
  for (std::uint64_t i = 0; i < grid.size(); ++i) index[{grid.tile(i).x0, grid.tile(i).y0}] = i;
  std::vector<Unit> units(grid.size());
  for (std::uint64_t i = 0; i < grid.size(); ++i)
    units[i].bytes = HEADER_BYTES + grid.tile(i).pixels() * PIXEL_BYTES;
  for (std::uint64_t i = 0; i < fine.size(); ++i) {
    const PixelBlock b = fine.tile(i);
    units[index.at({b.x0 / side * side, b.y0 / side * side})].seconds += fineCost[i];
  }
  return units;
}

double maxSeconds(const std::vector<Unit>& units) {
  double m = 0;
  for (const Unit& u : units) m = std::max(m, u.seconds);
  return m;
}

/// The largest of the lower bounds of a frame's time.
const char* limitName(double compute, double link, double last, double dealer) {
  const double top = std::max({compute, link, last, dealer});
  if (top == link) return "rank 0's link";
  if (top == dealer) return "rank 0's dealer";
  if (top == last) return "the costliest tile";
  return "compute";
}

void oneFrame(const std::vector<double>& fineCost, const TileGrid& fine, int nX, int nY,
              const Options& o, const Network& net, const Dealer& dealer) {
  std::printf(
      "\nOne frame, %d x %d, on machines of %d cores (one rank of %d threads each), links "
      "of %.3g Gbit/s:\n",
      nX, nY, o.cores, o.cores, o.gbit);
  std::printf("%5s %9s %6s %12s %11s %10s %9s %11s %10s %10s %12s  %s\n", "tile", "machines",
              "cores", "predicted s", "vs 1 mach.", "vs 1 core", "effic.", "compute s", "link s",
              "max tile", "rank 0 busy", "bound");
  for (const int side : {8, 16, 32, 64}) {
    const std::vector<Unit> units = tilesOf(fine, fineCost, nX, nY, side);
    const double single = replay(units, {1, o.cores}, net, dealer, HEADER_BYTES).seconds;
    for (const int m : o.machines) {
      const Outcome r = replay(units, {m, o.cores}, net, dealer, HEADER_BYTES);
      const int cores = m * o.cores;
      const double compute = r.computeSeconds / cores;
      // Every remote pixel crosses rank 0's link; rank 0's own share (1/m) does not.
      const double link =
          static_cast<double>(nX) * nY * PIXEL_BYTES * (m - 1) / m / net.bytesPerSecond;
      const double last = maxSeconds(units);
      std::printf("%5d %9d %6d %12.3f %11.2f %10.1f %8.0f%% %11.3f %10.3f %10.3f %12.3f  %s\n",
                  side, m, cores, r.seconds, single / r.seconds, r.computeSeconds / r.seconds,
                  100 * r.computeSeconds / r.seconds / cores, compute, link, last, r.dealerBusy,
                  limitName(compute, link, last, r.dealerBusy));
    }
  }
}

void orbit(const std::vector<Unit>& tiles, int nX, int nY, const Options& o, const Network& net,
           const Dealer& dealer, std::uint64_t pixelBytes) {
  std::vector<double> costs;
  for (const Unit& u : tiles) costs.push_back(u.seconds);
  const double frameOnRank = poolSeconds(costs, o.cores);
  const std::uint64_t frameBytes = HEADER_BYTES + static_cast<std::uint64_t>(nX) * nY * pixelBytes;
  std::vector<Unit> frames(static_cast<std::size_t>(o.frames));
  for (int f = 0; f < o.frames; ++f)
    frames[static_cast<std::size_t>(f)] = Unit{frameOnRank, frameBytes, f};
  std::printf(
      "\nAn orbit of %d frames dealt as whole frames, each %.3f s on a rank's %d threads "
      "(tiles of %d), %.1f MB per frame (%llu bytes a pixel):\n",
      o.frames, frameOnRank, o.cores, o.tile, static_cast<double>(frameBytes) / 1e6,
      static_cast<unsigned long long>(pixelBytes));
  std::printf("%9s %6s %12s %11s %11s %10s %14s  %s\n", "machines", "cores", "predicted s",
              "vs 1 mach.", "compute s", "link s", "rank 0 busy s", "bound");
  const double single = replay(frames, {1, 1}, net, dealer, HEADER_BYTES).seconds;
  for (const int m : o.machines) {
    const Outcome r = replay(frames, {m, 1}, net, dealer, HEADER_BYTES);
    const double compute = r.computeSeconds / m;
    const double link = r.linkBusy;
    // Rank 0's main thread answers every message and writes every frame another rank sent.
    const double busy = r.dealerBusy;
    const char* bound = link >= compute && link >= busy ? "rank 0's link"
                        : busy >= compute               ? "rank 0's writing"
                                                        : "compute";
    std::printf("%9d %6d %12.1f %11.2f %11.1f %10.1f %14.1f  %s\n", m, m * o.cores, r.seconds,
                single / r.seconds, compute, link, busy, bound);
  }
}

int run(int argc, char** argv) {
  const Options o = parse(argc, argv);
  cli::SceneArguments args;
  args.argument = o.scene;
  args.width = o.width;
  const cli::RenderRequest request = cli::resolveRenderRequest(args, {.writesImage = false});
  cli::RenderSetup setup = request.build();
  const int nX = setup.camera.nX(), nY = setup.camera.nY();
  const TileGrid fine(nX, nY, 8);
  std::vector<double> cost(fine.size());
  std::printf("%s at %d x %d (tracer %s): every 8 x 8 tile rendered alone on one thread...\n",
              o.scene.c_str(), nX, nY, request.tracer->name.c_str());
  std::fflush(stdout);
  const auto wall0 = std::chrono::steady_clock::now();
  for (std::uint64_t i = 0; i < fine.size(); ++i) {
    const double start = threadCpuSeconds();
    renderBlock(setup.context(), fine.tile(i), setup.camera.image());
    cost[i] = threadCpuSeconds() - start;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  double total = 0;
  for (const double c : cost) total += c;
  // Finishing and writing the frame, as rank 0 does for each frame (median of 3).
  const std::filesystem::path png =
      std::filesystem::temp_directory_path() / "mpi-deal-model-frame.png";
  std::vector<double> writes;
  for (int k = 0; k < 3; ++k) {
    const double start = threadCpuSeconds();
    cli::finishImage(setup.camera, request.doc, std::nullopt, png.string());
    writes.push_back(threadCpuSeconds() - start);
  }
  std::filesystem::remove(png);
  Dealer dealer;
  dealer.perFrameWrite = median(writes);
  std::printf(
      "%zu tiles: %.3f CPU s in all (%.3f s wall), the costliest %.4f s; finishing and "
      "writing the frame %.4f s\n",
      cost.size(), total, wall, *std::max_element(cost.begin(), cost.end()), dealer.perFrameWrite);

  Network net;
  net.bytesPerSecond = o.gbit * 117.5e6;
  oneFrame(cost, fine, nX, nY, o, net, dealer);
  const std::vector<Unit> tiles = tilesOf(fine, cost, nX, nY, o.tile);
  orbit(tiles, nX, nY, o, net, dealer, PIXEL_BYTES);
  orbit(tiles, nX, nY, o, net, dealer, 3);

  // This machine: ranks through shared memory (GB/s, a microsecond), tiles of o.tile.
  Network local;
  local.bytesPerSecond = 4e9;
  local.latency = 1e-6;
  const Outcome oneRank = replay(tiles, {1, 2}, local, dealer, HEADER_BYTES);
  const Outcome twoRanks = replay(tiles, {2, 1}, local, dealer, HEADER_BYTES);
  std::printf(
      "\nThis machine, tiles of %d: 1 rank x 2 threads %.3f s; 2 ranks x 1 thread %.3f s "
      "(%llu messages, %.3f MiB through rank 0)\n",
      o.tile, oneRank.seconds, twoRanks.seconds, static_cast<unsigned long long>(twoRanks.messages),
      static_cast<double>(twoRanks.bytes) / (1 << 20));
  return 0;
}

}  // namespace
}  // namespace rt::mpi::model

int main(int argc, char** argv) {
  try {
    return rt::mpi::model::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mpi_deal_model: %s\n", e.what());
    return 2;
  }
}
