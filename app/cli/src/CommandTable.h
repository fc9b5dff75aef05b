#pragma once
// Internal to rt_cli: each command adds itself to rt's command line (Commands.cpp gathers them).

#include <optional>
#include <string>
#include <string_view>

#include "cli/CommandLine.h"
#include "cli/Commands.h"

namespace rt::cli {

void addListCommand(CommandLine& rt);
void addRenderCommand(CommandLine& rt);
void addProbeCommand(CommandLine& rt);
void addExportCommand(CommandLine& rt);

struct BuiltinScene;
/// The built-in scene called name. @throws UsageError "unknown scene 'x'; did you mean 'y'?
/// (hint)".
const BuiltinScene& requireBuiltinScene(std::string_view name, std::string_view hint);

/// The options render and probe share that change the scene: --width, --height, --tracer.
struct SceneOverrides {
  std::optional<int> width, height;
  std::optional<std::string> tracer;
};

/// Adds --width W and --height H (integers, 1..Image::MAX_SIDE) and --tracer T (a known
/// tracer's name) to command, bound to into; the help texts are the command's own.
void addSceneOverrideOptions(CLI::App& command, SceneOverrides& into, const std::string& widthHelp,
                             const std::string& heightHelp, const std::string& tracerHelp);

/// Applies the overrides to doc and checks the result (a scene file's resolution within
/// Image::MAX_SIDE, its tracer known). @throws UsageError.
void applySceneOverrides(const SceneOverrides& overrides, SceneDocument& doc);

}  // namespace rt::cli
