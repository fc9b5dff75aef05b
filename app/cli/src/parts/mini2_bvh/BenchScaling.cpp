// rt bench --scaling: the galaxy without diffusion at 10^3 to 10^6 stars (--stars), each
// measured through the BVH and through the grid, each in a process of its own (mini2's
// benchmark/GalaxyScaling.h, which mini2_render_bench uses too): the structure's build, the
// render's wall time, the peak resident size, the bytes per star, the nodes (cells) per ray.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "Bench.h"
#include "BenchOutput.h"
#include "BenchTable.h"
#include "benchmark/GalaxyScaling.h"
#include "benchmark/Measure.h"
#include "cli/Values.h"
#include "common/Integers.h"

namespace rt::cli {

std::string starsError(const std::string& list, std::vector<long>* stars) {
  constexpr int maxStars = static_cast<int>(GalaxyParams::MAX_STARS);
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    const std::optional<int> value = integerInText(item, 1, maxStars);
    if (!value) return integerError(item, 1, maxStars);
    if (stars) stars->push_back(*value);
    if (comma == list.size()) return {};
    start = comma + 1;
  }
}

namespace {

/// The scaling's image: the middle of the reference report's view, as mini2_render_bench's.
constexpr int SCALING_SIDE = 400;

}  // namespace

int benchScaling(const BenchArgs& args, const Destinations& to, const Io& io) {
  // The scaling renders the galaxy of --stars stars, without diffusion, with the beams tracer:
  // the options that would choose another scene or render are refused, by name.
  const SceneArguments& s = args.scene;
  if (!s.argument.empty() && s.argument != "galaxy")
    throw UsageError("--scaling: renders the built-in galaxy only, got '" + s.argument + "'");
  const char* refused = !s.params.empty() ? "--param"
                        : s.view          ? "--view"
                        : s.tracer        ? "--tracer"
                        : s.seed          ? "--seed"
                        : args.full       ? "--full"
                                          : nullptr;
  if (refused)
    throw UsageError(std::string(refused) +
                     ": not with --scaling (it renders the galaxy of --stars stars without "
                     "diffusion, beams tracer, BVH and grid)");
  std::vector<long> stars;
  starsError(args.stars.value_or(DEFAULT_STARS), &stars);  // checked when parsed
  // A side given alone makes the image square too.
  const int nX = s.width.value_or(s.height.value_or(SCALING_SIDE));
  const int nY = s.height.value_or(s.width.value_or(SCALING_SIDE));
  checkImageFits(nX, nY);
  const int threads = benchThreads(args);

  ScalingTable table{.width = nX,
                     .height = nY,
                     .threads = threads,
                     .machine = machineName(),
                     .repeat = args.repeat};
  // The baseline: what a child shares with this process at the fork, and its own start.
  const std::optional<std::int64_t> baseline =
      runInChildProcess([](std::span<std::byte>) {}, {}, io.stop);
  if (!baseline) return benchInterrupted("the start", args, io);
  table.baselineBytes = *baseline;
  for (std::size_t i = 0; i < stars.size(); ++i) {
    const long n = stars[i];
    const std::string where = "galaxy " + std::to_string(i + 1) + " of " +
                              std::to_string(stars.size()) + " (" + std::to_string(n) + " stars)";
    io.err << "rt bench: galaxy " << i + 1 << "/" << stars.size() << ": " << n << " stars, " << nX
           << "x" << nY << ", " << threadsText(threads) << std::endl;
    ScalingRow row{.stars = n, .shapes = 0, .bvh = {}, .grid = {}};
    for (const GalaxyAccel accel : {GalaxyAccel::Bvh, GalaxyAccel::Grid}) {
      const std::optional<GalaxyMeasurement> m = measureGalaxy(
          n, nX, nY, {.threads = {threads}, .repeat = args.repeat, .stop = io.stop}, accel);
      if (!m) return benchInterrupted(where, args, io);
      const std::int64_t grown = std::max<std::int64_t>(0, m->peakBytes - *baseline);
      const RayCounts& rays = m->renders.rays[0];
      row.shapes = m->shapes;
      (accel == GalaxyAccel::Bvh ? row.bvh : row.grid) = ScalingFigures{
          .buildSeconds = m->buildSeconds,
          .renderSeconds = m->renders.wall[0],
          .peakBytes = m->peakBytes,
          .bytesPerStar = std::llround(static_cast<double>(grown) / static_cast<double>(n)),
          .nodesPerRay = rays.total() > 0 ? static_cast<double>(rays.queries.nodesVisited) /
                                                static_cast<double>(rays.total())
                                          : 0};
    }
    table.rows.push_back(row);
  }
  emit(
      to, [&table](TableFormat f) { return formatScalingTable(table, f); }, io);
  return EXIT_OK;
}

}  // namespace rt::cli
