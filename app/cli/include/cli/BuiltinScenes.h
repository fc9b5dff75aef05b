#pragma once
/// @file BuiltinScenes.h
/// The scenes `rt` knows by name: every course scene of every stage, gathered from the stages'
/// own tables (so a name or a description is written once, beside the scene it describes).

#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "scenefile/SceneDocument.h"

namespace rt::cli {

struct BuiltinScene {
  std::string name;         ///< kebab-case, unique
  std::string description;  ///< one line
  std::string stage;        ///< the stage folder that defines it, "stage05_lighting"
  std::string tracer;       ///< the tracer of that stage: ambient, phong, shadow or whitted
  /// Builds the scene as a document (scene, camera, render settings with the tracer above).
  std::function<SceneDocument()> make;
};

/// Every built-in scene, stage by stage in the stages' order.
/// @throws std::logic_error (once, at the first call) if two stages use the same name.
std::span<const BuiltinScene> builtinScenes();

/// The built-in scene called name, or nullptr.
const BuiltinScene* findBuiltinScene(std::string_view name);

/// A ready-made scene as a document with the given default tracer: no geometry or material
/// names, the default render settings otherwise.
SceneDocument toDocument(const SceneSetup<LitScene>& setup, std::string_view tracer);

}  // namespace rt::cli
