#pragma once
/// @file RenderCommand.h
/// The options of `rt render`, declared once: rt's render command and rt-mpi's (app/mpi) both
/// call addRenderOptions, so the two programs take the same options with the same checks and
/// the same help. The end of a render is shared too: the grid lines, the atomic write and the
/// summary line.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "cli/Registry.h"
#include "cli/RenderRequest.h"

namespace CLI {
class App;
}

namespace rt::cli {

/// rt render's arguments, as the command line binds them.
struct RenderArgs {
  SceneArguments scene;
  std::optional<std::string> output;
  std::optional<int> gridLines;  ///< --grid-lines N: overrides render.gridLines
  bool quiet = false;            ///< no header, no progress; the final timing line stays
  bool silent = false;           ///< nothing but errors
};

/// Adds SCENE and every option of rt render to command, bound to into: -o, the scene's
/// arguments and the stages' options (addSceneArguments), --grid-lines, -q and -s.
void addRenderOptions(CLI::App& command, RenderArgs& into);

/// Adds --grid-lines N (0..Image::MAX_SIDE) to command, bound to into.
void addGridLinesOption(CLI::App& command, std::optional<int>& into);

/// What `rt render --help` says after its options (the tracers of this build, the checks, the
/// progress, the atomic write).
std::string renderCommandDetails();

/// The grid lines every args.gridLines (or the scene's render.gridLines) pixels drawn on the
/// finished image of camera (the course's printGrid after renderImage: no ray changes), then the
/// image written to path as a PNG, atomically. @throws std::runtime_error naming path.
void finishImage(Camera& camera, const SceneDocument& doc, const std::optional<int>& gridLines,
                 const std::string& path);

/// The render's last line, without "PROGRAM: " and the newline: "wrote FILE: WxH, tracer T,
/// N primary rays (+M shadow) in 2.5 s on 2 threads (… primary rays/s, … rays/s)". where says
/// how it ran ("on 2 threads", "on 2 ranks x 1 thread"; empty: one thread).
std::string renderSummary(const std::string& output, int nX, int nY, const TracerKind& kind,
                          const RayCounts& counts, double seconds, const std::string& where);

}  // namespace rt::cli
