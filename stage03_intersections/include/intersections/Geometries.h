#pragma once
/// @file Geometries.h

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include "geometries/Geometry.h"
#include "intersections/Intersectable.h"

namespace rt {

/// The course's composite: a list of shapes, intersected one after another.
/// A shape's index (the order of add) identifies it in every Hit.
class Geometries final : public Intersectable {
 public:
  Geometries() = default;
  Geometries(std::initializer_list<Geometry> shapes) : shapes_(shapes) {}

  /// Appends a shape and returns its index.
  std::uint32_t add(Geometry shape);
  /// Appends several shapes.
  template <typename... Shapes>
  void add(Shapes&&... shapes) requires(sizeof...(Shapes) > 1) {
    (add(Geometry(std::forward<Shapes>(shapes))), ...);
  }

  std::uint32_t size() const { return static_cast<std::uint32_t>(shapes_.size()); }
  bool empty() const { return shapes_.empty(); }
  const Geometry& operator[](std::uint32_t i) const { return shapes_[i]; }
  std::span<const Geometry> shapes() const { return shapes_; }

  std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                QueryCounts* counts = nullptr) const noexcept override;
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts = nullptr) const override;

  /// Room for n shapes in all, so that adding them reallocates once (a generated scene of a
  /// million spheres would otherwise keep up to twice the memory it needs).
  void reserve(std::uint32_t n) { shapes_.reserve(n); }

 private:
  std::vector<Geometry> shapes_;
};

}  // namespace rt
