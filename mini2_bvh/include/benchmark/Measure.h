#pragma once
/// @file Measure.h
/// What the benchmarks measure with (mini2_render_bench, and `rt bench` in the command-line
/// program): the CPU clocks, the median, the reference report's galaxy and the course's teapot
/// ready to render with their generation and their BVH's (or grid's) build timed, and a
/// configuration's peak memory measured in a process of its own. A timing is never a test: these
/// print figures, they assert nothing.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "bvh/Bvh.h"
#include "bvh/WideBvh.h"
#include "camera/Camera.h"
#include "glossy/BeamTracer.h"
#include "glossy/Galaxy.h"
#include "grid/Grid.h"
#include "reflections/WhittedTracer.h"
#include "scenes/Teapot.h"

namespace rt {

/// The CPU time of the calling thread, in seconds: a piece of work's cost, whatever else the
/// machine runs.
double threadCpuSeconds();

/// The CPU time of the whole process (every thread), user and system, in seconds.
double processCpuSeconds();

/// The median of values (the mean of the middle two for an even count).
/// @throws std::invalid_argument when values is empty.
double median(std::vector<double> values);

/// The structure the scalings compare.
enum class ScalingAccel { Bvh, Grid };

/// A BVH (the default one: wide, WideBvh.h) or a grid over a scene's primitives, its build
/// timed (the binary build and the collapse). The scene must outlive it.
struct TimedStructure {
  std::unique_ptr<WideBvh> bvh;  ///< null for ScalingAccel::Grid
  std::unique_ptr<Grid> grid;    ///< null for ScalingAccel::Bvh
  /// The build's wall time (the BVH's on every core, the grid's on one).
  double buildSeconds = 0;

  /// The structure, as a tracer takes it (null before one is built).
  const Intersectable* get() const noexcept;
  /// The bytes the structure holds on the heap.
  std::size_t memoryBytes() const noexcept;
};

/// Builds accel's structure over geometries' primitives (shapes and mesh triangles), timed.
TimedStructure buildTimed(const Geometries& geometries, ScalingAccel accel);

/// A galaxy ready to render: the scene, its BVH (or its grid), the beams tracer through it. Not
/// movable: the structure and the tracer refer to the scene.
struct GalaxyRender {
  GalaxySetup setup;
  double generateSeconds = 0;  ///< galaxy(params): this thread's CPU time
  TimedStructure structure;
  std::unique_ptr<BeamTracer> tracer;

  /// @throws std::invalid_argument for invalid parameters (GalaxyParams::validate).
  explicit GalaxyRender(const GalaxyParams& params, ScalingAccel accel = ScalingAccel::Bvh);
  GalaxyRender(const GalaxyRender&) = delete;
  GalaxyRender& operator=(const GalaxyRender&) = delete;
};

/// The course's teapot (scenes/Teapot.h, flat, without bubbles) ready to render: the scene, its
/// BVH (or its grid), the Whitted tracer through it (the course's SimpleRayTracer). Not movable.
struct TeapotRender {
  SceneSetup<LitScene> setup;
  double generateSeconds = 0;  ///< the tessellation and its placement: this thread's CPU time
  TimedStructure structure;
  std::unique_ptr<WhittedTracer> tracer;

  /// @throws std::invalid_argument naming the detail outside 1..kUtahTeapotMaxDetail.
  explicit TeapotRender(int detail, ScalingAccel accel = ScalingAccel::Bvh);
  TeapotRender(const TeapotRender&) = delete;
  TeapotRender& operator=(const TeapotRender&) = delete;
};

/// The camera spec at nX x nY pixels; an image of another shape than the spec's view plane shows
/// the middle of it (the view plane cut to the image's shape, so that pixels stay square).
Camera middleView(CameraSpec spec, int nX, int nY);

/// The reference report's view of g at nX x nY pixels (middleView): a square image shows the
/// galaxy's middle, where the stars are.
Camera referenceView(const GalaxySetup& g, int nX, int nY);

/// What work in a child process returned, and the child's peak resident size.
template <typename T>
struct ChildMeasurement {
  T value;
  std::int64_t peakBytes = 0;  ///< the child's getrusage ru_maxrss, in bytes
};

/// Runs work in a child process of its own (fork), so that its peak resident size is its own:
/// the child's ru_maxrss, read by wait4, starts from what the child shares with this process at
/// the fork (measure an empty child, runInChildProcess with a work that does nothing, for that
/// baseline). work fills result (the child's copy), which is sent back through a pipe.
///
/// - The calling process must have no other thread running work that holds a lock (the child
///   has only the calling thread; it may start threads of its own).
/// - stop: polled every 50 ms while the child works; when raised, the child is killed
///   (SIGKILL) and waited for, and nothing is returned. The child's own copy of the flag is
///   raised only by a signal the child receives (Ctrl-C on a terminal reaches both).
/// - The child ends with _exit: nothing of this process's (buffers, atexit handlers) runs
///   twice. It never outlives this process: Linux's PR_SET_PDEATHSIG kills it when the thread
///   that forked it ends (a second Ctrl-C, say), so call this from a thread that waits for it.
/// @returns the child's peak resident size in bytes; nullopt when stopped.
/// @throws std::runtime_error with the child's exception's message when work threw, or naming
///         the signal or exit status when the child ended otherwise; std::system_error when the
///         pipe or the process cannot be made.
std::optional<std::int64_t> runInChildProcess(const std::function<void(std::span<std::byte>)>& work,
                                              std::span<std::byte> result,
                                              const std::atomic<bool>* stop = nullptr);

/// runInChildProcess for a work that returns a value that can be copied as bytes.
template <typename T>
requires std::is_trivially_copyable_v<T> && std::is_default_constructible_v<T>
    std::optional<ChildMeasurement<T>> measureInChildProcess(
        const std::function<T()>& work, const std::atomic<bool>* stop = nullptr) {
  ChildMeasurement<T> m{};
  const std::optional<std::int64_t> peak = runInChildProcess(
      [&work](std::span<std::byte> out) {
        const T value = work();
        std::memcpy(out.data(), &value, sizeof(T));
      },
      std::as_writable_bytes(std::span<T, 1>(&m.value, 1)), stop);
  if (!peak) return std::nullopt;
  m.peakBytes = *peak;
  return m;
}

}  // namespace rt
