#pragma once
/// @file MeshDocument.h
/// What a document keeps about its meshes beyond their triangles, for builds that have
/// mini2_bvh (the format's `mesh` geometry is mini 2's): where each came from, so that an export
/// writes a model file's entry as the file's path, transform and shading again rather than as
/// its triangles, and the names the file gave them. Kept as a part of the document
/// (SceneDocument::part), as stage 5 keeps its named materials.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenefile/ModelFile.h"
#include "scenefile/SceneDocument.h"

namespace rt {

/// One `mesh` entry of a scene file, and the meshes of the scene it made.
struct MeshEntry {
  /// An entry that names a model file.
  struct ModelSource {
    std::string file;                 ///< the path as the entry gave it
    std::filesystem::path absolute;   ///< where it was read from (the scene file's folder
                                      ///< joined, made absolute), for a relative export
    ModelTransform transform;         ///< scale, rotation, translation
    bool smooth = true;               ///< shading "smooth" or "flat"
    std::vector<std::string> groups;  ///< per mesh: the file's material group (may be "")
    std::vector<bool> mapped;         ///< per mesh: its group's material came from
                                      ///< "materials", not from the entry's "material"
  };

  std::uint32_t firstMesh = 0;       ///< its first mesh in the scene's geometries.meshes()
  std::uint32_t meshCount = 1;       ///< one per material group of a model file; 1 for inline
  std::string name;                  ///< the entry's "name"; "" for none
  std::optional<ModelSource> model;  ///< none: the mesh was given inline
};

/// The mesh entries of a document, in the order of their meshes. A mesh that no entry covers
/// (one a built-in scene made in code) is written inline.
struct MeshEntries {
  std::vector<MeshEntry> entries;

  /// The entry whose meshes include mesh, or nullptr.
  const MeshEntry* entryOf(std::uint32_t mesh) const {
    for (const MeshEntry& e : entries)
      if (mesh >= e.firstMesh && mesh - e.firstMesh < e.meshCount) return &e;
    return nullptr;
  }
};

/// The document's mesh entries (none for a built-in scene).
inline const MeshEntries& meshEntries(const SceneDocument& doc) {
  static const MeshEntries none;
  const MeshEntries* m = doc.findPart<MeshEntries>();
  return m ? *m : none;
}

/// The name the file gave the entry of mesh `mesh`, or nullptr when it gave none.
inline const std::string* meshName(const SceneDocument& doc, std::uint32_t mesh) {
  const MeshEntry* e = meshEntries(doc).entryOf(mesh);
  return e && !e->name.empty() ? &e->name : nullptr;
}

}  // namespace rt
