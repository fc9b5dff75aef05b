#pragma once
/// @file LitScene.h

#include <cstdint>
#include <memory>
#include <vector>

#include "camera/Scene.h"
#include "lighting/LightSource.h"
#include "lighting/Material.h"
#include "primitives/Color.h"

namespace rt {

/// How a shape looks: what it emits and what it is made of.
struct Appearance {
  Color emission = Color::BLACK;
  Material material;
};

/// A scene with light sources, and how every shape looks.
///
/// Looks are kept in a table: appearances holds each distinct look once, and appearanceIndex[i]
/// is the row of geometries[i]. A million stars of one material then cost 4 bytes each for their
/// looks, not the size of an Appearance (184 bytes). add(shape, emission, material) makes a new
/// row for each shape (what the course's scenes do); a scene with many shapes of few looks adds
/// the rows once with addAppearance and the shapes with add(shape, row).
///
/// A triangle mesh has one row for all its triangles (meshAppearance, per mesh of the geometries,
/// in their order); addMesh adds both.
///
/// The lists are public, as the course's are; validate() checks that they fit together, and
/// every tracer calls it once when it is constructed, so that nothing is checked per ray.
struct LitScene : Scene {
  std::vector<Appearance> appearances;
  std::vector<std::uint32_t> appearanceIndex;  ///< per shape: its row of appearances
  std::vector<std::uint32_t> meshAppearance;   ///< per mesh of geometries: its row
  std::vector<LightSource> lights;

  LitScene() = default;
  /// An unlit scene (stage 4) as a lit one: every shape gets one default Appearance (row 0; no
  /// row at all for a scene without shapes).
  explicit LitScene(const Scene& base);

  /// Adds a row to the table and returns its index.
  /// @throws std::invalid_argument for an invalid material (see Material::validate).
  std::uint32_t addAppearance(const Color& emission, const Material& material = {});
  /// Adds a shape that looks like row `appearance` and returns its index.
  /// @throws std::out_of_range when there is no such row.
  std::uint32_t add(Geometry shape, std::uint32_t appearance);
  /// Adds a shape with a look of its own (a new row) and returns its index.
  /// @throws std::invalid_argument for an invalid material; nothing is added then.
  std::uint32_t add(Geometry shape, const Color& emission = Color::BLACK,
                    const Material& material = {});
  /// Adds a triangle mesh that looks like row `appearance` (every triangle alike) and returns
  /// the mesh's index in geometries.
  /// @throws std::out_of_range when there is no such row (nothing is added then), and what
  ///         Geometries::addMesh throws.
  std::uint32_t addMesh(std::shared_ptr<const TriangleMesh> mesh, std::uint32_t appearance);
  /// @throws std::invalid_argument for an invalid light (see validate(LightSource)).
  LitScene& addLight(LightSource light);

  /// The row of a hit's primitive (a Hit's geometry: a shape, or a mesh triangle, whose row is
  /// its mesh's). Not checked (per-ray code; see validate()).
  std::uint32_t rowOf(std::uint32_t primitive) const noexcept {
    return primitive < appearanceIndex.size()
               ? appearanceIndex[primitive]
               : meshAppearance[geometries.primitives().meshTriangle(primitive).mesh];
  }
  /// The look of primitive `geometry` (a shape or a mesh triangle). Not checked (per-ray code).
  const Appearance& appearanceOf(std::uint32_t geometry) const noexcept {
    return appearances[rowOf(geometry)];
  }
  Appearance& appearanceOf(std::uint32_t geometry) noexcept { return appearances[rowOf(geometry)]; }

  /// Checks that the lists fit together: one appearance row per shape and one per mesh, every
  /// row index within the table, every material and light valid.
  /// @throws std::logic_error naming both sizes when the shapes and their rows differ in number,
  ///         or the shape and the index when a row does not exist; std::invalid_argument naming
  ///         appearances[i] or lights[i] and the field for an invalid material or light.
  void validate() const;
};

}  // namespace rt
