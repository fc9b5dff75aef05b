#pragma once
// Internal to rt_cli: the commands' specs and entry points, gathered in one table by Commands.cpp.

#include "cli/ArgParser.h"
#include "cli/Commands.h"

namespace rt::cli {

struct Command {
  CommandSpec spec;
  int (*run)(const ParsedArgs& args, const Io& io);
};

Command listCommand();
Command renderCommand();
Command probeCommand();
Command exportCommand();

struct BuiltinScene;
/// The built-in scene called name. @throws UsageError "unknown scene 'x'; did you mean 'y'?
/// (hint)".
const BuiltinScene& requireBuiltinScene(std::string_view name, std::string_view hint);

/// The options shared by render and probe that change the scene: --width, --height, --tracer.
/// Applies them to doc and checks the result (resolution within Image::MAX_SIDE, known tracer).
/// @throws UsageError.
void applySceneOverrides(const ParsedArgs& args, SceneDocument& doc);

}  // namespace rt::cli
