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
Vector normalAt(const Geometry& g, const Point& p);

/// The course's lower-case name of the shape ("sphere", "plane", ...).
const char* shapeName(const Geometry& g);

}  // namespace rt
