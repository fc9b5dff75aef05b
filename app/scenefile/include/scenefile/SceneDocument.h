#pragma once
/// @file SceneDocument.h
/// Everything a scene file (or a built-in scene) describes: the scene, its camera, the render
/// settings, and the names the file gave to shapes and materials.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "camera/CameraSpec.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"

namespace rt {

/// The `render` object of a scene file. Mini projects add their settings here.
struct RenderSettings {
  std::string tracer = "whitted";  ///< ambient | phong | shadow | whitted
  int maxLevel = 10;               ///< recursion depth of the Whitted tracer
  double minK = 0.001;             ///< cut-off of the path weight
};

struct SceneDocument {
  LitScene scene;
  CameraSpec camera;
  RenderSettings render;
  /// names[i] is geometry i's optional "name" (empty when none).
  std::vector<std::string> geometryNames;
  /// Named materials of the "materials" object, and which one each geometry used (if any), so
  /// an export keeps the file's structure.
  std::map<std::string, Material> materials;
  std::vector<std::optional<std::string>> geometryMaterialNames;
};

}  // namespace rt
