#pragma once
/// @file ModelTransform.h
/// The placement of a model's vertices, p' = m·p + t in double precision: one piece of code for
/// the model files (ModelFile.cpp, composed with a file's node transforms) and the scene file's
/// inline meshes (parts/mini2_bvh.cpp), both from a ModelTransform (scenefile/ModelFile.h).

#include <array>
#include <span>

#include "primitives/Double3.h"
#include "primitives/Point.h"
#include "scenefile/ModelFile.h"

namespace rt::scenefile {

/// A 3x3 matrix (its rows) and a translation: p' = m·p + t.
struct Affine {
  std::array<Double3, 3> m{Double3(1, 0, 0), Double3(0, 1, 0), Double3(0, 0, 1)};
  Double3 t{0, 0, 0};

  Double3 linear(const Double3& v) const {
    return {m[0].x * v.x + m[0].y * v.y + m[0].z * v.z, m[1].x * v.x + m[1].y * v.y + m[1].z * v.z,
            m[2].x * v.x + m[2].y * v.y + m[2].z * v.z};
  }
  Double3 apply(const Double3& p) const { return linear(p) + t; }

  /// this·o (o applied first).
  Affine after(const Affine& o) const;

  double determinant() const;

  /// The cofactor matrix times the sign of the determinant: the inverse transpose up to a
  /// positive factor, which the normalisation of the normals removes (and no division).
  Affine normalMatrix() const;

  /// True when the map is exactly the identity.
  bool isIdentity() const;

  /// Moves a model's vertices by this map, and its normals (one per vertex, or none) by
  /// normalMatrix(), unnormalised (TriangleMesh normalises them). Nothing for the identity:
  /// applying it would still turn a -0 coordinate into +0 (-0 + 0 is +0), and a mesh written
  /// inline must read back to the same bits.
  void place(std::span<Point> vertices, std::span<Double3> normals) const;
};

/// The map of a ModelTransform: S scales each axis, then the rotations about x, y and z (exact
/// at multiples of 90 degrees), then the translation.
/// @throws std::invalid_argument "the transform is degenerate: ..." naming the value, for a
///         scale that is zero or not finite on some axis, or a rotation or translation that is
///         not finite.
Affine affineOf(const ModelTransform& transform);

}  // namespace rt::scenefile
