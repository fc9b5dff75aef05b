#pragma once
/// @file Primitives.h
/// What the queries test one at a time: the course's shapes, and after them the triangles of the
/// triangle meshes, one primitive each. A primitive's number is its index among the shapes, or,
/// for triangle t of a mesh, the number of shapes plus the mesh's first number plus t. A Hit
/// names a primitive by that number, so a mesh of a million triangles is a million primitives of
/// the accelerations (mini2_bvh), not one opaque box, and costs no entry of the Geometry variant.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>

#include "geometries/Geometry.h"
#include "geometries/TriangleMesh.h"
#include "intersections/Intersect.h"

namespace rt {

/// A mesh in a collection: its data (shared with every copy of the scene) and the number of its
/// first triangle among the collection's mesh triangles (the triangles of the meshes before it).
struct PlacedMesh {
  std::shared_ptr<const TriangleMesh> mesh;
  std::uint32_t first = 0;
};

/// Which mesh of a collection, and which of its triangles, a primitive is.
struct MeshTriangle {
  std::uint32_t mesh;
  std::uint32_t triangle;
};

/// A view of a collection's primitives (as a std::span views an array): shapes and meshes must
/// outlive it unchanged. A span of shapes converts to it, with no meshes.
class Primitives {
 public:
  Primitives(std::span<const Geometry> shapes) noexcept  // NOLINT: a span of shapes is one
      : shapes_(shapes), count_(static_cast<std::uint32_t>(shapes.size())) {}
  /// @param triangles the meshes' triangles in all (the last mesh's first plus its count).
  Primitives(std::span<const Geometry> shapes, std::span<const PlacedMesh> meshes,
             std::uint32_t triangles) noexcept
      : shapes_(shapes),
        meshes_(meshes),
        count_(static_cast<std::uint32_t>(shapes.size()) + triangles) {}

  /// Shapes and mesh triangles.
  std::uint32_t size() const noexcept { return count_; }
  std::uint32_t shapeCount() const noexcept { return static_cast<std::uint32_t>(shapes_.size()); }
  std::span<const Geometry> shapes() const noexcept { return shapes_; }
  std::span<const PlacedMesh> meshes() const noexcept { return meshes_; }

  /// True when primitive is one of the shapes, false for a mesh triangle.
  bool isShape(std::uint32_t primitive) const noexcept { return primitive < shapes_.size(); }

  /// The mesh and triangle of a mesh primitive (not a shape; below size()): a binary search of
  /// the meshes' first numbers, one comparison for a scene of one mesh.
  MeshTriangle meshTriangle(std::uint32_t primitive) const noexcept {
    const std::uint32_t k = primitive - shapeCount();
    const auto after =
        std::upper_bound(meshes_.begin(), meshes_.end(), k,
                         [](std::uint32_t n, const PlacedMesh& m) { return n < m.first; });
    const auto mesh = static_cast<std::uint32_t>(after - meshes_.begin() - 1);
    return {mesh, k - meshes_[mesh].first};
  }

  /// The primitive's roots: intersectRoots of the shape, or of the mesh triangle.
  Roots roots(std::uint32_t primitive, const Ray& ray) const noexcept {
    if (isShape(primitive)) return intersectRoots(shapes_[primitive], ray);
    const MeshTriangle m = meshTriangle(primitive);
    return intersectRoots(*meshes_[m.mesh].mesh, m.triangle, ray);
  }

 private:
  std::span<const Geometry> shapes_;
  std::span<const PlacedMesh> meshes_;
  std::uint32_t count_;
};

}  // namespace rt
