#pragma once
/// @file BuiltinScenes.h
/// The scenes `rt` knows by name: the course scenes of every stage present, registered by each
/// stage's part from the stage's own tables (so a name or a description is written once, beside
/// the scene it describes), and the galaxy with its parameters from mini project 1 on.

#include <span>
#include <string_view>

#include "cli/Registry.h"

namespace rt::cli {

/// Every built-in scene of this build, stage by stage in the stages' order.
std::span<const BuiltinScene> builtinScenes();

/// The built-in scene called name, or nullptr.
const BuiltinScene* findBuiltinScene(std::string_view name);

/// The document of built-in scene `scene` with the --param values given as "NAME=VALUE" (each a
/// parameter of the scene, each given once).
/// @throws UsageError naming the bad parameter (unknown: with the nearest name; given twice;
///         without '='), or what the scene's make refuses: its own UsageError, or its
///         std::invalid_argument after the --param values given ("--param floor=-1: ...").
SceneDocument makeBuiltinScene(const BuiltinScene& scene, std::span<const std::string> params);

}  // namespace rt::cli
