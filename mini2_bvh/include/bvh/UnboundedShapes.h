#pragma once
/// @file UnboundedShapes.h
/// What every acceleration structure does first: the primitives it cannot bound (planes, tubes,
/// shapes or mesh triangles beyond the float range) stay outside it, and a query tests them one by
/// one before it walks the boxes, the tree or the cells. CBR, the BVH and the grid share these
/// steps, so that the three answer the unbounded shapes exactly alike, and count them alike.

#include <cstdint>
#include <span>

#include "bvh/FlatShapes.h"
#include "geometries/Geometry.h"
#include "intersections/HitRules.h"
#include "intersections/Intersect.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"
#include "primitives/Ray.h"

namespace rt {

/// The closest-hit query's first step: offers each unbounded shape's hits to nearest.
/// @returns the exact tests made (one per unbounded shape).
inline std::uint64_t offerUnbounded(std::span<const std::uint32_t> unbounded,
                                    const Primitives& primitives, const Ray& ray,
                                    NearestHit& nearest) noexcept {
  for (const std::uint32_t i : unbounded) {
    // A ray running away from a plane it starts beside has no root (FlatShapes::awayFromPlane):
    // no call for the floor under every ray that goes up.
    if (const Plane* plane =
            primitives.isShape(i) ? std::get_if<Plane>(&primitives.shapes()[i]) : nullptr;
        plane != nullptr &&
        FlatShapes::awayFromPlane(plane->point().xyz(), plane->normal().xyz(), ray))
      continue;
    nearest.offer(primitives.roots(i, ray), i);
  }
  return unbounded.size();
}

/// The every-hit query's first step: visits each unbounded shape's hits within tMax until visit
/// says stop, adding the exact tests made to tests.
/// @returns false when visit stopped the query.
inline bool visitUnbounded(std::span<const std::uint32_t> unbounded, const Primitives& primitives,
                           const Ray& ray, double tMax, HitVisitor visit, std::uint64_t& tests) {
  bool complete = true;
  for (std::size_t k = 0; complete && k < unbounded.size(); ++k) {
    ++tests;
    complete = visitHits(primitives.roots(unbounded[k], ray), unbounded[k], tMax, visit);
  }
  return complete;
}

/// Adds a query's exact tests and its boxes, nodes or cells to counts, when counts is given.
inline void addQueryCounts(QueryCounts* counts, std::uint64_t tests,
                           std::uint64_t visited) noexcept {
  if (counts != nullptr) *counts += QueryCounts{tests, visited};
}

}  // namespace rt
