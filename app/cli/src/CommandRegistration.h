#pragma once
// Internal to rt_cli: the commands' registration functions (each adds its command to rt's command
// line; Commands.cpp gathers them) and the pieces they share: the scene arguments, the image-size
// check, the scene warnings.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/CommandLine.h"
#include "cli/Commands.h"
#include "cli/Registry.h"
#include "cli/RenderRequest.h"

namespace rt::cli {

void addListCommand(CommandLine& rt);
void addRenderCommand(CommandLine& rt);
void addAnimateCommand(CommandLine& rt);
void addProbeCommand(CommandLine& rt);
void addExportCommand(CommandLine& rt);
void addCompareCommand(CommandLine& rt);

struct BuiltinScene;
/// The built-in scene called name. @throws UsageError "unknown scene 'x'; did you mean 'y'?
/// (hint)".
const BuiltinScene& requireBuiltinScene(std::string_view name, std::string_view hint);

/// Adds --param NAME=VALUE (repeatable, one value each) to command, bound to into.
CLI::Option* addParamOption(CLI::App& command, std::vector<std::string>& into);

/// Adds SCENE, --param NAME=VALUE (repeatable), --view NAME, --width W and --height H (integers,
/// 1..Image::MAX_SIDE), --tracer T (a tracer of this build) and --seed N to command, bound to
/// into; the help texts of the size and the tracer are the command's own.
void addSceneArguments(CLI::App& command, SceneArguments& into, const std::string& widthHelp,
                       const std::string& heightHelp, const std::string& tracerHelp);

}  // namespace rt::cli
