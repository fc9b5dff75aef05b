#pragma once
/// @file TriangleMesh.h
/// Many triangles sharing one vertex array: the data of a mesh (DESIGN.md §9). Not one of the
/// course's six shapes and not in the `Geometry` variant: its triangles are meant to be the
/// primitives of the accelerations one by one, each named by the mesh and its triangle's number.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "primitives/Double3.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {

/// A triangle mesh: one vertex array, three 32-bit vertex indices per triangle, and optionally
/// one unit normal per vertex (smooth shading) or none (flat shading).
///
/// Built once through the constructor, which validates everything and keeps nothing it refused:
/// after it, every index is in range, every coordinate finite, every normal a finite unit vector,
/// and every triangle has a non-zero area, so the per-ray code needs no checks.
///
/// Memory, all included: 24 bytes per vertex (a Point), 24 more with normals, 12 bytes per
/// triangle. A closed mesh has about half as many vertices as triangles (Euler: V - E + F = 2
/// with E = 3F/2), so a triangle costs about 12 + 12 = 24 bytes, 36 with normals. Nothing is
/// precomputed per triangle: the normal and the edges are derived from the vertices when asked.
class TriangleMesh {
 public:
  /// The indices of a triangle's three vertices in the vertex array. Their order is the
  /// winding: the flat normal is (v1 - v0) x (v2 - v0), normalised (the right-hand rule).
  using Indices = std::array<std::uint32_t, 3>;

  /// More vertices than a 32-bit index can name are refused.
  static constexpr std::uint64_t kMaxVertices = 0xFFFF'FFFFu;
  /// More triangles than a 32-bit number can name are refused (the accelerations name a mesh's
  /// triangle by a 32-bit number).
  static constexpr std::uint64_t kMaxTriangles = 0xFFFF'FFFFu;
  /// The stated limit on the mesh's arrays: 16 GiB (about 700 million triangles with normals).
  static constexpr std::uint64_t kMaxBytes = std::uint64_t{1} << 34;

  /// The bytes the arrays of a mesh of that size take (vertices, normals when asked, indices);
  /// exact for counts up to kMaxVertices and kMaxTriangles (beyond them it may overflow).
  static constexpr std::uint64_t bytesFor(std::uint64_t vertexCount, std::uint64_t triangleCount,
                                          bool withNormals) {
    const std::uint64_t perVertex = sizeof(Point) + (withNormals ? sizeof(Vector) : 0);
    return vertexCount * perVertex + triangleCount * sizeof(Indices);
  }

  /// Checks a size before anything is allocated for it: a reader calls it with the counts a
  /// file's header announces, before it reads the arrays; the constructor calls it too. The
  /// counts must not exceed kMaxVertices and kMaxTriangles, and bytesFor them must not exceed
  /// kMaxBytes (both checks are made without overflow for any 64-bit counts).
  /// @throws std::invalid_argument naming the counts, the bytes and the limit exceeded.
  static void requireFits(std::uint64_t vertexCount, std::uint64_t triangleCount, bool withNormals);

  /// Validates and builds the mesh.
  /// @param vertices  at least one; every coordinate finite.
  /// @param triangles at least one; every index below vertices.size(). A triangle of zero area
  ///                  (two indices equal, or the course's zero cross product: every component
  ///                  of (v1 - v0) x (v2 - v0) below 2^-40, exactly the triangles that the
  ///                  `Triangle` constructor refuses) is dropped and counted in
  ///                  droppedTriangles(); the others keep their order.
  /// @param normals   empty (flat shading), or one per vertex: finite, not the zero vector (in the
  ///                  course's sense), any length; stored normalised.
  /// @throws std::invalid_argument, the message starting "TriangleMesh: " and naming the value
  ///         and its place, for: no vertices, or no triangles; a size requireFits refuses;
  ///         "normals has N entries for M vertices"; "vertices[i] must be finite, got (x,y,z)";
  ///         "normals[i] ..." not finite or zero; "triangles[t] (a,b,c): index b is out of
  ///         range ..."; "triangles[t] ...: its normal overflows" (coordinates beyond ~1e154);
  ///         every triangle of zero area (none would be left).
  TriangleMesh(std::vector<Point> vertices, std::vector<Indices> triangles,
               std::vector<Double3> normals = {});

  const std::vector<Point>& vertices() const { return vertices_; }
  /// The triangles kept, in their given order without the dropped ones.
  const std::vector<Indices>& triangles() const { return triangles_; }
  /// Empty, or one unit vector per vertex.
  const std::vector<Vector>& normals() const { return normals_; }
  bool hasNormals() const { return !normals_.empty(); }

  std::size_t vertexCount() const { return vertices_.size(); }
  std::size_t triangleCount() const { return triangles_.size(); }
  /// How many of the given triangles had zero area and were dropped (the caller's warning).
  std::size_t droppedTriangles() const { return dropped_; }

  /// The three corners of triangle t (t < triangleCount()).
  std::array<Point, 3> corners(std::size_t t) const noexcept {
    const Indices& i = triangles_[t];
    return {vertices_[i[0]], vertices_[i[1]], vertices_[i[2]]};
  }

  /// The geometric normal of triangle t: normalize((v1 - v0) x (v2 - v0)), the expression a
  /// `Triangle` of the same three points computes (through its Plane), so both give the same
  /// bits.
  Vector flatNormal(std::size_t t) const noexcept;

  /// The shading normal at the point of triangle t whose barycentric coordinates are (b1, b2):
  /// the point is (1 - b1 - b2)·v0 + b1·v1 + b2·v2, and the normal the same blend of the three
  /// vertex normals, normalised. flatNormal(t) when the mesh has no normals, or when the blend
  /// is the exact zero vector (opposite vertex normals).
  Vector shadingNormal(std::size_t t, double b1, double b2) const noexcept;

  /// The shading normal at point p of triangle t, p being a hit point (on the triangle, up to
  /// rounding): p's barycentric coordinates, from the areas of the sub-triangles it makes,
  ///
  ///     n = (v1 - v0) x (v2 - v0),  b1 = ((p - v0) x (v2 - v0))·n / n·n,
  ///     b2 = ((v1 - v0) x (p - v0))·n / n·n,
  ///
  /// given to shadingNormal. flatNormal(t) for a mesh without normals (nothing is computed then).
  Vector normalAt(std::size_t t, const Point& p) const noexcept;

  /// The bytes of the arrays as allocated (their capacities): what the mesh costs in memory.
  std::size_t memoryBytes() const;

 private:
  std::vector<Point> vertices_;
  std::vector<Indices> triangles_;
  std::vector<Vector> normals_;
  std::size_t dropped_ = 0;
};

}  // namespace rt
