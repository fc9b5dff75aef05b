#pragma once
/// @file Cbr.h
/// The course's CBR ("conservative boundary region"): the shapes are still scanned one after
/// another, but each bounded shape's box is tested first, and the shape itself only when the ray
/// meets the box before the best hit so far. Unbounded shapes (planes, tubes) have no box and
/// are always tested. A step between the linear Geometries and the BVH: it saves the expensive
/// exact tests, not the scan.

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/FloatBox.h"
#include "geometries/Geometry.h"
#include "intersections/Geometries.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"

namespace rt {

class Cbr final : public Intersectable {
 public:
  /// @param primitives viewed, not copied (as by a std::span): the shapes and meshes must outlive
  ///        the Cbr and stay unchanged. Hit indices are the primitives' numbers.
  explicit Cbr(Primitives primitives);
  explicit Cbr(std::span<const Geometry> shapes) : Cbr(Primitives(shapes)) {}
  explicit Cbr(const Geometries& geometries) : Cbr(geometries.primitives()) {}
  Cbr(Geometries&&) = delete;  // would view a temporary

  /// The same answer as Geometries::closestHit over the same shapes, bit for bit. Counts each
  /// box it tests as a visited node (a CBR is a hierarchy one level deep) and each exact test.
  std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                QueryCounts* counts = nullptr) const noexcept override;
  /// The same hits as Geometries::forEachHit over the same shapes.
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts = nullptr) const override;

 private:
  struct BoxedShape {
    FloatBox box;
    std::uint32_t geometry;
  };

  Primitives primitives_;
  std::vector<std::uint32_t> unbounded_;  ///< planes and tubes, by index
  std::vector<BoxedShape> bounded_;       ///< the others (mesh triangles too) with their boxes
};

}  // namespace rt
