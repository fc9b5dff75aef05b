#pragma once
/// @file SceneDocument.h
/// Everything a scene file (or a built-in scene) describes: the scene, its camera, the render
/// settings, and the names the file gave to shapes and materials.

#include <cstdint>
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
  /// The names the file gave to shapes, by geometry index: only the named ones (a generated
  /// scene of a million unnamed stars keeps none).
  std::map<std::uint32_t, std::string> geometryNames;
  /// Named materials of the "materials" object, and, per row of the scene's appearance table,
  /// the name of the material that row uses when the file gave it by name (so an export keeps
  /// the file's structure). Rows beyond the list's end use no named material.
  std::map<std::string, Material> materials;
  std::vector<std::optional<std::string>> appearanceMaterialNames;

  /// Geometry i's name, or nullptr when it has none.
  const std::string* geometryName(std::uint32_t i) const {
    const auto it = geometryNames.find(i);
    return it == geometryNames.end() ? nullptr : &it->second;
  }
  /// The named material that geometry i uses, or nullptr when its material is inline.
  const std::string* materialNameOf(std::uint32_t i) const {
    const std::uint32_t row = scene.appearanceIndex[i];
    if (row >= appearanceMaterialNames.size() || !appearanceMaterialNames[row]) return nullptr;
    return &*appearanceMaterialNames[row];
  }
};

}  // namespace rt
