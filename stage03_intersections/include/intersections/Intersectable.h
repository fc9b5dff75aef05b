#pragma once
/// @file Intersectable.h
/// The open seam for collections of shapes: the course's Geometries composite implements it
/// with a linear scan, and an acceleration structure (the BVH mini project) with a tree. The
/// tracers only talk to this interface.

#include <cstdint>
#include <optional>
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

class Intersectable {
 public:
  virtual ~Intersectable() = default;

  /// The nearest hit with t in (0, tMax]. Allocates nothing.
  virtual std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE) const = 0;

  /// Calls visit for every hit with t in (0, tMax], in no particular order, until visit returns
  /// false. Returns false when visit stopped the walk, true when every hit was visited.
  /// Allocates nothing; this is what shadow queries are built on.
  virtual bool forEachHit(const Ray& ray, double tMax, HitVisitor visit) const = 0;

  /// The course's findGeoIntersections: every hit in (0, maxDistance], sorted by distance.
  std::vector<GeoPoint> findGeoIntersections(const Ray& ray,
                                             double maxDistance = INFINITE_DISTANCE) const;
  /// The course's findIntersections: the points of findGeoIntersections.
  std::vector<Point> findIntersections(const Ray& ray,
                                       double maxDistance = INFINITE_DISTANCE) const;
};

}  // namespace rt
