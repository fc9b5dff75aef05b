#pragma once
/// @file Intersectable.h
/// The open seam for collections of shapes: the course's Geometries composite implements it
/// with a linear scan, and an acceleration structure (the BVH mini project) with a tree. The
/// tracers only talk to this interface.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometries/Geometry.h"
#include "intersections/FunctionRef.h"
#include "intersections/Intersect.h"
#include "primitives/Ray.h"

namespace rt {

/// A hit: the ray parameter and the index of the shape in its Geometries.
struct Hit {
  double t;
  std::uint32_t geometry;
};

/// The course's GeoPoint: which shape, where, and at which ray parameter.
struct GeoPoint {
  std::uint32_t geometry;
  Point point;
  double t;
};

/// Called for each hit; returns true to go on, false to stop.
using HitVisitor = FunctionRef<bool(const Hit&)>;

/// What intersection queries cost, to explain timings rather than only measure them: how many
/// exact ray-shape tests were made, and how many nodes of a bounding-volume hierarchy were
/// visited (always 0 for the course's linear Geometries). A query adds to the counts it is
/// given; the renderer gives each thread its own and adds them up once per block of pixels.
struct QueryCounts {
  std::uint64_t shapeTests = 0;    ///< intersectRoots calls
  std::uint64_t nodesVisited = 0;  ///< hierarchy nodes whose box was tested

  QueryCounts& operator+=(const QueryCounts& o) noexcept {
    shapeTests += o.shapeTests;
    nodesVisited += o.nodesVisited;
    return *this;
  }
  bool operator==(const QueryCounts&) const = default;
};

class Intersectable {
 public:
  virtual ~Intersectable() = default;

  /// The nearest hit with t in (0, tMax] (tMax inclusive, as withinDistance). When several
  /// shapes are hit at exactly the same t, the one with the smallest index wins: the answer is
  /// the smallest (t, geometry) pair, so every implementation (a linear scan, a hierarchy that
  /// visits shapes in another order) returns the same hit. Allocates nothing, never throws.
  /// @param counts when not null, the query adds what it cost.
  virtual std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                        QueryCounts* counts = nullptr) const noexcept = 0;

  /// Calls visit for every hit with t in (0, tMax], in no particular order, until visit returns
  /// false. Returns false when visit stopped the walk, true when every hit was visited.
  /// Allocates nothing; this is what shadow queries are built on.
  /// @param counts when not null, the query adds what it cost.
  virtual bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                          QueryCounts* counts = nullptr) const = 0;

  /// closestHit of several rays: hits[i] = closestHit(rays[i], tMax), the same bits, for every i
  /// (hits.size() == rays.size()). This version asks closestHit ray by ray; a structure that can
  /// trace rays together (the wide BVH's packets, mini2) overrides it. The counts may then differ
  /// from closestHit's, the hits never. Allocates nothing, never throws.
  virtual void closestHits(std::span<const Ray> rays, double tMax,
                           std::span<std::optional<Hit>> hits,
                           QueryCounts* counts = nullptr) const noexcept;

  /// The course's findGeoIntersections: every hit in (0, maxDistance], sorted by distance (equal
  /// distances by geometry index).
  std::vector<GeoPoint> findGeoIntersections(const Ray& ray,
                                             double maxDistance = INFINITE_DISTANCE) const;
  /// The course's findIntersections: the points of findGeoIntersections.
  std::vector<Point> findIntersections(const Ray& ray,
                                       double maxDistance = INFINITE_DISTANCE) const;
};

}  // namespace rt
