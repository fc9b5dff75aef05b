#pragma once
/// @file Geometry.h
/// The course's closed set of shapes as one value type.
///
/// The shapes are fixed at stage 2, while operations keep arriving (normals here,
/// intersections in stage 3, bounding boxes in the BVH mini project). A std::variant keeps
/// the shape list closed and lets each later stage add an operation as a free function in its
/// own files, with std::visit, without touching the shape classes. See stage03's README.

#include <variant>

#include "geometries/Cylinder.h"
#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "geometries/Sphere.h"
#include "geometries/Triangle.h"
#include "geometries/Tube.h"

namespace rt {

using Geometry = std::variant<Sphere, Plane, Triangle, Polygon, Tube, Cylinder>;

/// The outward unit normal of any shape at a point of its surface.
/// @throws std::invalid_argument where the normal is undefined (a sphere's centre, a tube's
///         axis).
Vector normalAt(const Geometry& g, const Point& p);

/// The same normal for the per-ray path, which must never throw: where the normal is undefined
/// (exactly at a sphere's centre or on a tube's axis, which only a shape far smaller than its
/// coordinates' rounding error can put under a hit point) it returns fallback instead.
Vector hitNormal(const Geometry& g, const Point& p, const Vector& fallback) noexcept;

/// The course's lower-case name of the shape ("sphere", "plane", ...).
const char* shapeName(const Geometry& g);

}  // namespace rt
