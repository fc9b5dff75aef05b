// mini2_render_bench: the tile pool's thread scaling, and the galaxy from 10^3 to 10^6 stars.
//
//   build/release/bin/mini2_render_bench [--no-scaling] [--stars 1000,10000,100000,1000000]
//                                        [--threads N] [--repeat R] [--tile S]
//
// 1. Thread scaling: the reference report's galaxy (mini1's galaxy()) rendered by the beams tracer
//    through the BVH, one camera ray per pixel, on 1 thread and on N threads (default 2)
//    alternately, R times each (default 5), so that both see the same load on a shared machine. It
//    prints the medians of the wall time and of the rays per second (every ray: camera, reflected
//    and refracted, shadow), the process's CPU seconds per wall second (how many cores the render
//    really got), the speed-up (the ratio of the median wall times), the rays per CPU second (the
//    same on 1 and N threads when the threads do not slow each other down), and whether the two
//    images are the same bits. Then the load balance, which the machine's load cannot blur: every
//    tile's cost measured alone, and the pool's schedule replayed with them (tileBalance). Without
//    diffusion at the reference report's 1280 x 720; with it (the glass's beams of 10 x 10 rays) at
//    256 x 144.
// 2. Stars: galaxies of n stars (GalaxyParams::stars), without diffusion, seen at 400 x 400 (the
//    middle of the reference report's view): the generation time of the scene and the build time
//    and size of its BVH (this thread's CPU time), the render's CPU time on 1 thread and its wall
//    time on 1 and N threads (medians of R renders, alternately), and the peak resident size of a
//    process that did only that (each galaxy is measured in a child process of its own:
//    benchmark/Scaling.h, which rt bench --scaling uses too).
// A timing is never a test: this prints figures, it asserts nothing.

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <queue>
#include <string>
#include <vector>

#include "benchmark/Measure.h"
#include "benchmark/Scaling.h"
#include "camera/Camera.h"
#include "parallel/TileGrid.h"
#include "parallel/TilePool.h"

namespace rt {
namespace {

/// The command line's choices.
struct BenchOptions {
  int threads = 2;  ///< compared with one thread
  int repeat = 5;   ///< renders per thread count
  int tileSize = RenderOptions::DEFAULT_TILE_SIZE;
};

/// The renders' options: 1 and o.threads threads, alternately.
TimingOptions timing(const BenchOptions& o) {
  return {.threads = {1, o.threads}, .repeat = o.repeat, .tileSize = o.tileSize};
}

/// The load balance of the pool, measured without the machine's load: every tile's cost is
/// measured alone (the thread's CPU time, one tile after the other), then the pool's schedule is
/// replayed with those costs: `threads` workers, each taking the next tile in the pool's order
/// when it is free. The predicted speed-up is the sum of the costs over the last worker's finish
/// time: what the pool would reach on idle cores if tiles cost the same on every thread (which
/// the rays per CPU second of the real runs check).
void tileBalance(const Camera& camera, const RayTracer& tracer, int threads) {
  const CenterSampler sampler;
  Image image(camera.nX(), camera.nY());
  std::printf("%8s %8s %14s %14s %22s\n", "tile", "tiles", "mean tile ms", "max tile ms",
              "predicted speed-up");
  for (const int side : {8, 16, 32, 64}) {
    const TileGrid grid(camera.nX(), camera.nY(), side);
    std::vector<double> cost(grid.size());
    for (std::uint64_t i = 0; i < grid.size(); ++i) {
      const double start = threadCpuSeconds();
      renderBlock({camera, tracer, sampler}, grid.tile(i), image);
      cost[i] = threadCpuSeconds() - start;
    }
    // The workers' next free times, earliest first.
    std::priority_queue<double, std::vector<double>, std::greater<>> free;
    for (int t = 0; t < threads; ++t) free.push(0);
    double total = 0, finish = 0;
    for (const double c : cost) {
      const double end = free.top() + c;
      free.pop();
      free.push(end);
      total += c;
      finish = std::max(finish, end);
    }
    std::printf("%8d %8zu %14.3f %14.3f %22.3f\n", side, cost.size(),
                1e3 * total / static_cast<double>(cost.size()),
                1e3 * *std::max_element(cost.begin(), cost.end()), total / finish);
  }
}

void scaling(const char* name, bool diffusion, int nX, int nY, const BenchOptions& o) {
  const GalaxyRender g(GalaxyParams{.diffusion = diffusion});
  const Camera camera = referenceView(g.setup, nX, nY);
  const CenterSampler sampler;
  const TimedRenders c = timeRenders({camera, *g.tracer, sampler}, timing(o));
  const RayCounts& rays = c.rays[0];
  std::printf(
      "\n%s, %d x %d, one camera ray per pixel: %llu rays per render (%llu camera, %llu "
      "reflected/refracted, %llu shadow); tiles of %d; %d renders each, alternately\n",
      name, nX, nY, static_cast<unsigned long long>(rays.total()),
      static_cast<unsigned long long>(rays.primary),
      static_cast<unsigned long long>(rays.secondary), static_cast<unsigned long long>(rays.shadow),
      o.tileSize, o.repeat);
  std::printf("%8s %14s %10s %14s %10s %9s %14s\n", "threads", "median wall s", "fastest s",
              "rays/s", "cpu/wall", "speed-up", "rays/cpu-s");
  const double total = static_cast<double>(rays.total());
  for (int k = 0; k < 2; ++k)
    std::printf("%8d %14.3f %10.3f %14.0f %10.2f %9.2f %14.0f\n", k == 0 ? 1 : o.threads, c.wall[k],
                c.fastest[k], total / c.wall[k], c.cpu[k] / c.wall[k], c.wall[0] / c.wall[k],
                total / c.cpu[k]);
  std::printf("images and ray counts on 1 and %d threads: %s\n", o.threads,
              c.sameImage ? "the same bits" : "DIFFERENT");
  std::printf("load balance on %d threads, from each tile's measured cost:\n", o.threads);
  tileBalance(camera, *g.tracer, o.threads);
}

void stars(const std::vector<long>& sizes, const BenchOptions& o) {
  std::printf(
      "\nGalaxies of n stars, no diffusion, 400 x 400, beams tracer through the BVH; render "
      "times are medians of %d, alternately on 1 and %d threads, tiles of %d; each galaxy in a "
      "process of its own (peak: its ru_maxrss)\n",
      o.repeat, o.threads, o.tileSize);
  std::printf("%8s %8s %10s %8s %7s %10s %10s %10s %9s %9s %8s\n", "stars", "shapes", "generate s",
              "build s", "BVH MB", "1 thr cpu", "1 thr wall", "N thr wall", "speed-up", "rays",
              "peak MB");
  for (const long n : sizes) {
    const ScalingMeasurement r = *measureGalaxy(n, 400, 400, timing(o));
    const TimedRenders& c = r.renders;
    std::printf("%8ld %8llu %10.3f %8.3f %7.1f %10.3f %10.3f %10.3f %9.2f %9llu %8.1f%s\n", n,
                static_cast<unsigned long long>(r.shapes), r.generateSeconds, r.buildSeconds,
                static_cast<double>(r.structureBytes) / 1e6, c.cpu[0], c.wall[0], c.wall[1],
                c.speedUp(), static_cast<unsigned long long>(c.rays[0].total()),
                static_cast<double>(r.peakBytes) / (1024.0 * 1024.0),
                c.sameImage ? "" : "  DIFFERENT IMAGES");
    std::fflush(stdout);
  }
}

/// "1000,10000" → {1000, 10000}.
std::vector<long> parseList(const std::string& list) {
  std::vector<long> values;
  std::size_t start = 0;
  while (start < list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    values.push_back(std::stol(list.substr(start, comma - start)));
    start = comma + 1;
  }
  return values;
}

}  // namespace
}  // namespace rt

int main(int argc, char** argv) {
  std::vector<long> sizes{1'000, 10'000, 100'000, 1'000'000};
  bool scaling = true;
  rt::BenchOptions options;
  for (int i = 1; i < argc; ++i) {
    const bool hasValue = i + 1 < argc;
    if (std::strcmp(argv[i], "--no-scaling") == 0) {
      scaling = false;
    } else if (std::strcmp(argv[i], "--stars") == 0 && hasValue) {
      sizes = rt::parseList(argv[++i]);
    } else if (std::strcmp(argv[i], "--threads") == 0 && hasValue) {
      options.threads = std::stoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--repeat") == 0 && hasValue) {
      options.repeat = std::max(1, std::stoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--tile") == 0 && hasValue) {
      options.tileSize = std::stoi(argv[++i]);
    } else {
      std::fprintf(stderr,
                   "usage: %s [--no-scaling] [--stars 1000,...] [--threads N] [--repeat R] "
                   "[--tile S]\n",
                   argv[0]);
      return 2;
    }
  }
  if (scaling) {
    rt::scaling("Galaxy without diffusion", false, 1280, 720, options);
    rt::scaling("Galaxy with diffusion (beams of 10 x 10 rays)", true, 256, 144, options);
  }
  if (!sizes.empty()) rt::stars(sizes, options);
  return 0;
}
