#pragma once
/// @file LitDocument.h
/// Typed access to a document's stage-5 part, for builds that have stage05_lighting (the format's
/// stage-5 part makes every document's scene a LitScene).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lighting/LitScene.h"
#include "lighting/Material.h"
#include "scenefile/SceneDocument.h"

namespace rt {

/// The named materials of the "materials" object, and, per row of the scene's appearance table,
/// the name of the material that row uses when the file gave it by name (so an export keeps the
/// file's structure). Rows beyond the list's end use no named material.
struct NamedMaterials {
  std::map<std::string, Material> materials;
  std::vector<std::optional<std::string>> rowNames;
};

/// The document's scene as the LitScene it is from stage 5 on.
/// @throws std::logic_error when it is not one (a document made without the stage-5 part).
LitScene& litScene(SceneDocument& doc);
const LitScene& litScene(const SceneDocument& doc);

/// The document's named materials (an empty set when it has none).
NamedMaterials& namedMaterials(SceneDocument& doc);
const NamedMaterials& namedMaterials(const SceneDocument& doc);

/// The named material that geometry i uses, or nullptr when its material is inline.
const std::string* materialNameOf(const SceneDocument& doc, std::uint32_t i);
/// The named material that row `row` of the appearance table uses (the geometries and meshes of
/// that row), or nullptr when its material is inline.
const std::string* materialNameOfRow(const SceneDocument& doc, std::uint32_t row);

/// A document for a lit scene (what a built-in scene of stage 5 or later is). Pass the scene with
/// std::move when it is not needed again: a galaxy of 10^6 stars is 130 MB, not to be copied.
SceneDocument litDocument(LitScene scene, const CameraSpec& camera);

}  // namespace rt
