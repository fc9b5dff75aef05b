#pragma once
/// @file RenderRequest.h
/// A render request resolved in one step: the scene argument and the options turned into
/// everything a render needs, every check done before the first ray. `rt render`, `rt probe`,
/// `rt bench` and a distributed renderer take the result; resolving prints nothing (the
/// caller prints the warnings it returns).
///
///     resolveRenderRequest(arguments, needs)
///       doc     = the scene (a built-in's name with --param, or a .json file), with --view,
///                 --width/--height, --tracer, --seed and the stages' options (--threads,
///                 --accel) applied and checked
///       tracer  = the tracer kind doc.render.tracer names
///       output  = -o or the default path, checked writable and   (when the command writes one)
///                 no file the scene reads
///       the image's size checked against the memory             (when the command makes one)
///       warnings = the scene file's, and the ambient tracer's on a scene without ambient light
///     request.build()
///       the accelerator, the tracer, the sampler and the camera: the render's RenderContext
///       (request.buildTracer(): the first two only, for one ray)

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "camera/Camera.h"
#include "camera/RayTracer.h"
#include "camera/RenderBlock.h"
#include "cli/Registry.h"
#include "intersections/Intersectable.h"
#include "scenefile/SceneDocument.h"

namespace rt::cli {

struct SceneFileInput;

/// The scene argument and the options that change the scene, which render, probe and bench
/// share.
struct SceneArguments {
  std::string argument;  ///< SCENE as given: a built-in scene's name or a .json scene file
  std::vector<std::string> params;  ///< --param NAME=VALUE, for a built-in scene's parameters
  std::optional<std::string> view;  ///< --view NAME: one of the scene's views
  std::optional<int> width, height;
  std::optional<std::string> tracer;
  std::optional<int> seed;
  SettingOverrides settings;  ///< the options stages add (--threads, --accel)
  /// A scene file's text and models given instead of the disk (rt-mpi); null: the disk.
  const SceneFileInput* fileInput = nullptr;
};

/// What the command does with the request, which decides what is checked.
struct RequestNeeds {
  /// It writes the image: to *output (-o) when given, else to defaultOutputPath(SCENE).
  bool writesImage = false;
  std::optional<std::string> output{};
  /// It makes the camera's image (render, bench, probe --pixel): the size must fit in memory.
  bool makesImage = true;
  /// It renders (not probe): the ambient tracer's warning about a black scene applies.
  bool renders = true;
};

/// The tracer of a request over the build's accelerator (null without one), which it holds.
struct TracerSetup {
  std::unique_ptr<Intersectable> accelerator;
  std::unique_ptr<RayTracer> tracer;
};

/// What a render builds from its request, before the first ray: the accelerator (null without
/// one), the tracer over it, the sampler, and the camera with its image (the one rendered into
/// and written).
struct RenderSetup {
  std::unique_ptr<Intersectable> accelerator;
  std::unique_ptr<RayTracer> tracer;
  std::unique_ptr<PixelSampler> sampler;
  Camera camera;

  /// The camera, the tracer and the sampler, as every block of the render shares them.
  RenderContext context() const noexcept { return {camera, *tracer, *sampler}; }
};

/// A render request, resolved and checked.
struct RenderRequest {
  SceneDocument doc;         ///< the scene with every option applied
  const TracerKind* tracer;  ///< the tracer kind doc.render.tracer names (never null)
  std::string output;        ///< where the image goes ("" when the command writes none)
  /// What the render should be told, one line each ("warning: ..."; the caller adds "rt: ").
  std::vector<std::string> warnings;

  /// Builds the build's accelerator (the registry's makeAccelerator, if any) and the tracer over
  /// it. doc must outlive the result.
  TracerSetup buildTracer() const;
  /// Builds the accelerator, the tracer, the sampler (the registry's makeSampler) and the camera
  /// with its image. doc must outlive the result.
  RenderSetup build() const;
};

/// Resolves arguments for a command that needs what needs says, in this order: the scene and
/// the options (sceneFromArguments), the output path (checkOutputWritable, origin "-o" or "the
/// default output"; checkOutputIsNoInput: not the scene file or a model file), the image's size
/// (checkImageFits), then the warnings.
/// @throws UsageError, SceneError naming the value and where it came from.
RenderRequest resolveRenderRequest(const SceneArguments& arguments, const RequestNeeds& needs);

/// The scene (loadSceneArgument) with the options applied, and the result checked: the view
/// known; the resolution within Image::MAX_SIDE (one of width and height given: the other keeps
/// the scene's aspect ratio; both given with another aspect: the view plane's height follows,
/// so pixels stay square); the tracer known. @throws UsageError, SceneError.
SceneDocument sceneFromArguments(const SceneArguments& arguments);

/// --width and --height applied to camera as sceneFromArguments does (one given: the other
/// keeps the camera's aspect ratio; both with another aspect: the view plane's height follows).
/// @throws UsageError for a resolution outside 1..Image::MAX_SIDE per side.
void applyResolution(CameraSpec& camera, const std::optional<int>& width,
                     const std::optional<int>& height);

/// Where a resolution came from, for the messages: "from --width and --height", "from --width,
/// the height keeping the scene's aspect ratio" (or --height's), or "the scene's resolution".
std::string resolutionOrigin(const std::optional<int>& width, const std::optional<int>& height);

/// Refuses an nX x nY image that cannot fit in this machine's memory.
/// @throws UsageError naming the size, where it came from (origin, resolutionOrigin's words) and
/// the memory.
void checkImageFits(int nX, int nY, std::string_view origin);

/// The warnings about doc, one line each without "rt: ": those the scene file's reader left in
/// doc.warnings (stage 7: glass faces wound both ways) and, when rendering, one for a render by
/// the ambient tracer of a scene whose ambient light is zero (every shape would be black).
std::vector<std::string> sceneWarnings(const SceneDocument& doc, const SceneArguments& arguments,
                                       bool rendering);

}  // namespace rt::cli
