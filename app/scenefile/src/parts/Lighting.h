#pragma once
/// @file Lighting.h
/// What the stage-5 part offers the parts above it: the fields of its objects, for the parts
/// that add keys to them (mini 1: a light's radius and shadow samples), and the appearance rows
/// of geometries that are not shapes, read and written as a shape's (mini 2: the meshes).

#include <cstdint>
#include <optional>
#include <string>

#include "../Format.h"
#include "primitives/Color.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"
#include "scenefile/SceneDocument.h"

namespace rt::scenefile {

/// The row of the scene's appearance table for the emission and material the geometry's keys
/// gave (stage 5's "emission" and "material" of every geometry; read already), shared with every
/// geometry that looks the same: what the triangles of a mesh look like. node is the geometry.
std::uint32_t appearanceRowOf(const Node& node, GeometryFields& fields);

/// The same, with the material given at node material instead of the geometry's: a material
/// object or the name of one in "materials", read as a geometry's "material" is (mini 2: a
/// model file's material group given a material of the scene).
std::uint32_t appearanceRowWith(const Node& material, const GeometryFields& fields);

/// Writes the look of appearance row `row` into the geometry object g, as a shape's is written:
/// "emission" unless black, "material" by the name the file gave it or inline unless it is the
/// default. what names the geometry in the messages ("geometry 3", "mesh 0").
/// @throws std::logic_error when the row names a material that is not among the document's, or
///         one that differs from the row's.
void writeAppearance(const SceneDocument& doc, std::uint32_t row, Json& g, const std::string& what);

struct LightFields {
  std::optional<Color> intensity;
  std::optional<Point> position;
  std::optional<Vector> direction;
  double kC = 1, kL = 0, kQ = 0, narrowBeam = 1;
  double radius = 0;      ///< mini 1's key (soft shadows): PointLight::radius
  int shadowSamples = 1;  ///< mini 1's key: PointLight::shadowSamples
};

}  // namespace rt::scenefile
