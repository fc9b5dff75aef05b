#pragma once
/// @file Registry.h
/// What `rt` knows of each stage present in its build, registered by one part per stage
/// (src/parts/<stage folder>.cpp, called by a source CMake generates from the stages built): the
/// tracers, the built-in scenes, and how a render is sampled, accelerated and run. A course cut
/// after stage05_lighting has the ambient and Phong tracers and the scenes of stage04_camera and
/// stage05_lighting; nothing else exists in it, and there is no #if anywhere.
///
/// Which part supplies what: the tracers, scenes, commands and options add up, every part its
/// own. The three pieces a render has exactly one of are StagePieces, and the highest stage of
/// the build that supplies one wins, whatever the order the parts register in:
///
///     piece             supplied by                               in a cut after
///     makeSampler       stage04_camera (the centre ray)           stage04 .. stage07
///                       mini1_glossy (jittered, lens, adaptive)   mini1, mini2
///     render            stage04_camera (rows, calling thread)     stage04 .. mini1
///                       mini2_bvh (tiles on a pool of threads)    mini2
///     makeAccelerator   mini2_bvh (none, cbr, bvh[4], grid)       mini2 (before it: none)
///
/// Two parts of one stage supplying the same piece are refused (std::logic_error), and so is a
/// stage that is not one of the course's (the root CMakeLists.txt's RT_STAGES, in their order).
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "camera/Camera.h"
#include "camera/RayTracer.h"
#include "camera/RenderBlock.h"
#include "intersections/Intersectable.h"
#include "scenefile/SceneDocument.h"

namespace CLI {
class App;
}

namespace rt::cli {

class CommandLine;

struct TracerKind {
  std::string name;         ///< the value of --tracer and of a scene file's render.tracer
  std::string stage;        ///< the stage that adds it
  std::string description;  ///< one line
  /// Builds the tracer over doc's scene with doc.render's settings, intersecting accelerator
  /// instead of the scene's shapes when not null; doc and accelerator must outlive it.
  std::function<std::unique_ptr<RayTracer>(const SceneDocument& doc,
                                           const Intersectable* accelerator)>
      make;
  /// A debugging view (stage 4's rays, normals, hits): it shows what a stage computes, not the
  /// scene's light, so rt bench leaves it out of its table of the stages' tracers.
  bool debugView = false;
};

/// A parameter of a built-in scene (`rt render galaxy --param arms=12`).
struct SceneParam {
  std::string name;
  std::string defaultValue;
  std::string description;
};

/// The values given with --param, by name (checked against the scene's parameters).
using SceneParams = std::map<std::string, std::string>;

struct BuiltinScene {
  std::string name;                ///< kebab-case, unique
  std::string description;         ///< one line
  std::string stage;               ///< the stage folder that defines it, "stage05_lighting"
  std::string tracer;              ///< the tracer of that stage
  std::vector<SceneParam> params;  ///< empty for the course's fixed scenes
  /// Builds the scene as a document (scene, cameras, render settings with the tracer above).
  /// @throws UsageError naming a parameter whose value it refuses.
  std::function<SceneDocument(const SceneParams& params)> make;
};

/// One render: the image of the context's camera, every pixel by its sampler, traced by its
/// tracer.
struct RenderJob {
  RenderContext context;
  Image& image;
  int threads;                             ///< 0: every core (when the build has threads)
  const std::atomic<bool>* stop;           ///< raised to stop (Ctrl-C); may be null
  std::atomic<std::uint64_t>& donePixels;  ///< pixels finished, for the progress thread
  std::atomic<std::uint64_t>& doneRays;    ///< rays of every kind cast, for the progress thread
};

/// What the options a stage adds to render and probe set (unset: the scene's render settings).
struct SettingOverrides {
  std::optional<int> threads;        ///< --threads (mini project 2)
  std::optional<std::string> accel;  ///< --accel (mini project 2)
  std::optional<bool> lightBuffers;  ///< --light-buffers (mini project 2)
};

struct RenderOutcome {
  RayCounts counts;
  bool interrupted = false;
  int threads = 1;  ///< how many threads rendered
};

/// Where stage sits in the course (0: stage01_primitives, ... 8: mini2_bvh): its place in the
/// root CMakeLists.txt's RT_STAGES. @throws std::logic_error naming stage if it is not there.
int courseStageRank(std::string_view stage);

/// A piece of the render that one part of the build supplies (the sampler, the render loop, the
/// accelerator): each part that has one supplies it with its stage, and the highest stage wins,
/// whichever registers first. Called like the function it holds.
template <typename Signature>
class StagePiece;

template <typename Result, typename... Args>
class StagePiece<Result(Args...)> {
 public:
  using Function = std::function<Result(Args...)>;

  /// @param what the piece's name, for the messages ("makeSampler").
  explicit StagePiece(std::string what) : what_(std::move(what)) {}

  /// Offers stage's function; kept if stage is higher than the one that supplies it so far.
  /// @throws std::logic_error when stage already supplied it, or is not a course stage.
  void supply(std::string_view stage, Function function) {
    const int rank = courseStageRank(stage);
    if (rank == rank_)
      throw std::logic_error("the registry's " + what_ + ": supplied twice by " +
                             std::string(stage));
    if (rank < rank_) return;
    rank_ = rank;
    stage_ = stage;
    function_ = std::move(function);
  }

  /// The stage that supplies it, or "" when none does.
  const std::string& stage() const noexcept { return stage_; }
  explicit operator bool() const noexcept { return static_cast<bool>(function_); }
  /// Calls the highest stage's function. @throws std::bad_function_call when none supplies it.
  Result operator()(Args... args) const { return function_(std::forward<Args>(args)...); }

 private:
  std::string what_;
  std::string stage_;
  int rank_ = -1;
  Function function_;
};

struct CliRegistry {
  std::vector<TracerKind> tracers;   ///< in the course's order; the last is the default
  std::vector<BuiltinScene> scenes;  ///< stage by stage
  /// The sampler render settings ask for (stage 4: one ray through each pixel's centre; mini
  /// project 1: the render settings' samples, lens and adaptive sampling).
  StagePiece<std::unique_ptr<PixelSampler>(const RenderSettings&)> makeSampler{"makeSampler"};
  /// The acceleration structure render settings ask for, or null (no acceleration: the
  /// scene's own list). Supplied from mini project 2 on.
  StagePiece<std::unique_ptr<Intersectable>(const SceneDocument&)> makeAccelerator{
      "makeAccelerator"};
  /// Renders a job (stage 4: one row after another on the calling thread; mini project 2: tiles
  /// on a pool of threads).
  StagePiece<RenderOutcome(const RenderJob&)> render{"render"};
  /// Commands a stage adds to rt (mini project 2: bench).
  std::vector<std::function<void(CommandLine&)>> commands;
  /// Options a stage adds to render and probe (mini project 2: --threads, --accel), bound to
  /// the overrides.
  std::vector<std::function<void(CLI::App& command, SettingOverrides& into)>> sceneOptions;
};

/// The registry of this build: every present stage's part registered (on the first call).
/// @throws std::logic_error (at the first call) if two built-in scenes share a name.
const CliRegistry& cliRegistry();

}  // namespace rt::cli
