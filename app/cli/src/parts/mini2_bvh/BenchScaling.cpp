// rt bench --scaling: the galaxy without diffusion at 10^3 to 10^6 stars (--stars), or the course's
// teapot at about 10^3 to 10^6 triangles (SCENE teapot, --details), each measured through the BVH
// and through the grid, each in a process of its own (mini2's benchmark/Scaling.h, which
// mini2_render_bench uses too): the structure's build, the render's wall time, the peak resident
// size, the bytes per star (per triangle), the nodes (cells) per ray.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "Bench.h"
#include "BenchOutput.h"
#include "BenchTable.h"
#include "benchmark/Measure.h"
#include "benchmark/Scaling.h"
#include "cli/Values.h"
#include "common/Integers.h"
#include "geometries/UtahTeapot.h"

namespace rt::cli {

std::string integerListError(const std::string& list, int lo, int hi, std::vector<long>* values) {
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    const std::optional<int> value = integerInText(item, lo, hi);
    if (!value) return integerError(item, lo, hi);
    if (values) values->push_back(*value);
    if (comma == list.size()) return {};
    start = comma + 1;
  }
}

namespace {

/// The scaling's image: the middle of the reference report's view, as mini2_render_bench's (the
/// teapot's: the course's whole square view).
constexpr int SCALING_SIDE = 400;

/// What the scaling of SCENE renders, and what it refuses.
struct ScalingPlan {
  const ScalingKind* kind;
  const char* renders;  ///< for the refusals: "the galaxy of --stars stars without diffusion, ..."
  const char* listOption;  ///< the option of its sizes
  const char* unit;        ///< "stars", for the progress line ("1000 stars")
};

const ScalingPlan GALAXY_PLAN{
    &GALAXY_SCALING,
    "the galaxy of --stars stars without diffusion, beams tracer, BVH and "
    "grid",
    "--stars", "stars"};
const ScalingPlan TEAPOT_PLAN{&TEAPOT_SCALING,
                              "the teapot of --details details, flat, Whitted tracer, BVH and grid",
                              "--details", "detail"};

}  // namespace

int benchScaling(const BenchArgs& args, const Destinations& to, const Io& io) {
  // The scaling renders the galaxy (or the teapot) of the sizes asked for, with its tracer: the
  // options that would choose another scene or render are refused, by name.
  const SceneArguments& s = args.scene;
  if (!s.argument.empty() && s.argument != "galaxy" && s.argument != "teapot")
    throw UsageError("--scaling: renders the built-in galaxy or teapot only, got '" + s.argument +
                     "'");
  const ScalingPlan& plan = s.argument == "teapot" ? TEAPOT_PLAN : GALAXY_PLAN;
  const bool teapot = &plan == &TEAPOT_PLAN;
  const char* refused = !s.params.empty()         ? "--param"
                        : s.view                  ? "--view"
                        : s.tracer                ? "--tracer"
                        : s.seed                  ? "--seed"
                        : args.full               ? "--full"
                        : teapot && args.stars    ? "--stars"
                        : !teapot && args.details ? "--details"
                                                  : nullptr;
  if (refused)
    throw UsageError(std::string(refused) + ": not with --scaling" + (teapot ? " teapot" : "") +
                     " (it renders " + plan.renders + ")");
  std::vector<long> sizes;  // checked when parsed
  if (teapot)
    integerListError(args.details.value_or(DEFAULT_DETAILS), 1, kUtahTeapotMaxDetail, &sizes);
  else
    integerListError(args.stars.value_or(DEFAULT_STARS), 1,
                     static_cast<int>(GalaxyParams::MAX_STARS), &sizes);
  // A side given alone makes the image square too.
  const int nX = s.width.value_or(s.height.value_or(SCALING_SIDE));
  const int nY = s.height.value_or(s.width.value_or(SCALING_SIDE));
  checkImageFits(nX, nY,
                 s.width || s.height ? "from --width and --height (one alone: a square)"
                                     : "rt bench --scaling's own size");
  const int threads = benchThreads(args);

  ScalingTable table{.kind = *plan.kind,
                     .width = nX,
                     .height = nY,
                     .threads = threads,
                     .machine = machineName(),
                     .repeat = args.repeat};
  // The baseline: what a child shares with this process at the fork, and its own start.
  const std::optional<std::int64_t> baseline =
      runInChildProcess([](std::span<std::byte>) {}, {}, io.stop);
  if (!baseline) return benchInterrupted("the start", args, io);
  table.baselineBytes = *baseline;
  const std::string scene(plan.kind->scene);
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const long n = sizes[i];
    // "1000 stars", "detail 4 (992 triangles)"
    const std::string size =
        teapot ? "detail " + std::to_string(n) + " (" +
                     std::to_string(utahTeapotTriangleCount(static_cast<int>(n))) + " triangles)"
               : std::to_string(n) + " " + plan.unit;
    const std::string where = scene + " " + std::to_string(i + 1) + " of " +
                              std::to_string(sizes.size()) + " (" + size + ")";
    io.err << "rt bench: " << scene << " " << i + 1 << "/" << sizes.size() << ": " << size << ", "
           << nX << "x" << nY << ", " << threadsText(threads) << std::endl;
    ScalingRow row{.size = n, .count = 0, .bvh = {}, .grid = {}};
    for (const ScalingAccel accel : {ScalingAccel::Bvh, ScalingAccel::Grid}) {
      const TimingOptions timing{.threads = {threads}, .repeat = args.repeat, .stop = io.stop};
      const std::optional<ScalingMeasurement> m =
          teapot ? measureTeapot(static_cast<int>(n), nX, nY, timing, accel)
                 : measureGalaxy(n, nX, nY, timing, accel);
      if (!m) return benchInterrupted(where, args, io);
      const std::int64_t grown = std::max<std::int64_t>(0, m->peakBytes - *baseline);
      const RayCounts& rays = m->renders.rays[0];
      row.count = teapot ? m->triangles : m->shapes;
      // Bytes per star (the galaxy's parameter) or per triangle.
      const double per = static_cast<double>(teapot ? m->triangles : static_cast<std::uint64_t>(n));
      (accel == ScalingAccel::Bvh ? row.bvh : row.grid) = ScalingFigures{
          .buildSeconds = m->buildSeconds,
          .renderSeconds = m->renders.wall[0],
          .peakBytes = m->peakBytes,
          .bytesPer = std::llround(static_cast<double>(grown) / per),
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
