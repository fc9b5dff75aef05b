#pragma once
/// @file Geometries.h

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <vector>

#include "geometries/Geometry.h"
#include "geometries/TriangleMesh.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"

namespace rt {

/// The course's composite: a list of shapes, intersected one after another.
/// A shape's index (the order of add) identifies it in every Hit.
///
/// Beyond the course, it also holds triangle meshes (addMesh), whose triangles are primitives
/// numbered after the shapes (Primitives.h): a Hit's geometry is then a primitive's number, which
/// is a shape's index whenever it is below size().
class Geometries final : public Intersectable {
 public:
  /// The most primitives (shapes and mesh triangles): a Hit numbers them in 32 bits.
  static constexpr std::uint32_t MAX_PRIMITIVES = 0xFFFF'FFFFu;

  Geometries() = default;
  Geometries(std::initializer_list<Geometry> shapes) : shapes_(shapes) {}

  /// Appends a shape and returns its index.
  /// @throws std::length_error when there are MAX_PRIMITIVES primitives already.
  std::uint32_t add(Geometry shape);
  /// Appends several shapes.
  template <typename... Shapes>
  void add(Shapes&&... shapes) requires(sizeof...(Shapes) > 1) {
    (add(Geometry(std::forward<Shapes>(shapes))), ...);
  }

  /// The number of shapes (the meshes' triangles not included: see primitiveCount()).
  std::uint32_t size() const { return static_cast<std::uint32_t>(shapes_.size()); }
  bool empty() const { return shapes_.empty(); }
  const Geometry& operator[](std::uint32_t i) const { return shapes_[i]; }
  std::span<const Geometry> shapes() const { return shapes_; }

  std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                QueryCounts* counts = nullptr) const noexcept override;
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts = nullptr) const override;

  /// Adds a mesh, whose triangles become primitives numbered after those of the meshes before
  /// it; returns the mesh's index. The mesh is shared, not copied, by every copy of this.
  /// @throws std::invalid_argument for a null mesh; std::length_error when the primitives would
  ///         outnumber 2^32 - 1 (the number of a Hit is 32-bit).
  std::uint32_t addMesh(std::shared_ptr<const TriangleMesh> mesh);
  std::span<const PlacedMesh> meshes() const { return meshes_; }
  /// The meshes' triangles in all.
  std::uint32_t triangleCount() const { return triangles_; }
  /// Shapes and mesh triangles: the numbers a Hit can hold are below this.
  std::uint32_t primitiveCount() const { return size() + triangles_; }
  /// The view the accelerations are built over (valid while this is unchanged).
  Primitives primitives() const { return Primitives(shapes_, meshes_, triangles_); }

  /// What a primitive belongs to: a shape's own index, or size() + the mesh's index for a mesh
  /// triangle; a scene gives each of these one appearance.
  std::uint32_t partOf(std::uint32_t primitive) const noexcept {
    return primitive < size() ? primitive : size() + primitives().meshTriangle(primitive).mesh;
  }
  /// The shading normal of a primitive at a hit point: hitNormal of the shape (fallback where
  /// its normal is undefined), or the mesh's normalAt (interpolated when it has vertex normals).
  /// Never throws (the per-ray path).
  Vector hitNormal(std::uint32_t primitive, const Point& p, const Vector& fallback) const noexcept;
  /// The same normal, for the course's API and the tools: normalAt of a shape, which throws
  /// where it is undefined.
  Vector normalAt(std::uint32_t primitive, const Point& p) const;

  /// Room for n shapes in all, so that adding them reallocates once (a generated scene of a
  /// million spheres would otherwise keep up to twice the memory it needs).
  void reserve(std::uint32_t n) { shapes_.reserve(n); }

 private:
  std::vector<Geometry> shapes_;
  std::vector<PlacedMesh> meshes_;
  std::uint32_t triangles_ = 0;
};

}  // namespace rt
