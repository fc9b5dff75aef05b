#pragma once
/// @file Scaling.h
/// The renders the benchmarks time, written once for mini2_render_bench and `rt bench
/// --scaling`: one image rendered `repeat` times on one or two thread counts, taken in turn so
/// that a change of the machine's load hits both alike (timeRenders); and one scene of a scaling
/// (the galaxy of n stars, the course's teapot of detail d) generated, built and rendered in a
/// process of its own, so that its peak memory is its own (measureGalaxy, measureTeapot). They
/// print nothing and assert nothing.

#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "benchmark/Measure.h"
#include "camera/RenderBlock.h"
#include "camera/SampleContext.h"
#include "parallel/TilePool.h"

namespace rt {

/// How the renders are run.
struct TimingOptions {
  /// The thread counts compared (one or two, TimedRenders::MAX_COUNTS), rendered alternately.
  std::vector<int> threads{1};
  int repeat = 1;  ///< renders per thread count, at least 1
  int tileSize = RenderOptions::DEFAULT_TILE_SIZE;
  /// When raised, the render in flight stops (the pool's stop) and no other is started.
  const std::atomic<bool>* stop = nullptr;
};

/// What the renders of one image on each thread count cost. Trivially copyable: a child process
/// sends it back as bytes.
struct TimedRenders {
  static constexpr int MAX_COUNTS = 2;
  int counts = 0;                ///< how many thread counts were compared
  int threads[MAX_COUNTS] = {};  ///< the threads that rendered (the pool's, never more than tiles)
  double wall[MAX_COUNTS] = {};  ///< median wall seconds
  double fastest[MAX_COUNTS] = {};  ///< fastest wall seconds
  double cpu[MAX_COUNTS] = {};      ///< median CPU seconds of the whole process
  RayCounts rays[MAX_COUNTS] = {};  ///< one render's rays (the same every repeat)
  bool sameImage = true;            ///< every thread count gave the same bits and ray counts
  bool interrupted = false;         ///< stopped: the figures are not to be used

  /// The first thread count's median wall time over the last's.
  double speedUp() const { return wall[0] / wall[counts - 1]; }
};

/// Renders context's image options.repeat times on each of options.threads, alternately.
/// @throws std::invalid_argument for no thread count or more than MAX_COUNTS, or repeat < 1;
///         what renderImage throws.
TimedRenders timeRenders(const RenderContext& context, const TimingOptions& options);

/// One scene of a scaling, generated, built and rendered in a process of its own.
struct ScalingMeasurement {
  std::uint64_t shapes = 0;          ///< the scene's shapes: stars, suns, core, box, frame, ...
  std::uint64_t triangles = 0;       ///< its meshes' triangles: the teapot's
  double generateSeconds = 0;        ///< the scene's generation: CPU time
  double buildSeconds = 0;           ///< the BVH's (or grid's) build: wall time
  std::uint64_t structureBytes = 0;  ///< the BVH's (or grid's) memory
  std::uint64_t meshBytes = 0;       ///< the meshes' arrays (vertices, indices, normals)
  TimedRenders renders;              ///< the scene's tracer through the structure, a ray per pixel
  std::int64_t peakBytes = 0;        ///< the child process's peak resident size (ru_maxrss)
};

/// Measures the galaxy of `stars` stars without diffusion at nX x nY, seen through the middle of
/// the reference report's view, with the beams tracer, in a child process of its own
/// (runInChildProcess): generated, its BVH (or grid) built, rendered by timeRenders.
/// @returns nothing when options.stop was raised (the child is killed, or its render stopped).
/// @throws std::runtime_error with the child's message when it failed (invalid parameters,
///         say); std::system_error when the process cannot be made.
std::optional<ScalingMeasurement> measureGalaxy(long stars, int nX, int nY,
                                                const TimingOptions& options,
                                                ScalingAccel accel = ScalingAccel::Bvh);

/// The same for the course's teapot of `detail` (TeapotRender: 64·d² − 8·d flat triangles, the
/// course's light and view, the Whitted tracer).
std::optional<ScalingMeasurement> measureTeapot(int detail, int nX, int nY,
                                                const TimingOptions& options,
                                                ScalingAccel accel = ScalingAccel::Bvh);

}  // namespace rt
