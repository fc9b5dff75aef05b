#pragma once
/// @file BoundingBox.h
/// The bounding box of each shape: the operation mini project 2 adds to the closed set of
/// shapes, as free functions dispatched with std::visit (like stage 2's normalAt and stage 3's
/// intersectRoots), without touching the shape classes.
///
/// The boxes are the exact ones (up to the rounding of their own arithmetic): the smallest box
/// holding the shape. Planes and tubes are infinite, so they have none; they stay outside any
/// hierarchy (see the README).

#include <optional>

#include "bvh/Aabb.h"
#include "geometries/Geometry.h"
#include "geometries/TriangleMesh.h"
#include "intersections/Primitives.h"

namespace rt {

/// centre ± radius on every axis.
Aabb boundingBox(const Sphere& s) noexcept;
/// The minimum and maximum of the vertices, per axis.
Aabb boundingBox(const Triangle& t) noexcept;
/// The minimum and maximum of the vertices, per axis.
Aabb boundingBox(const Polygon& p) noexcept;
/// The box of the two cap discs. A disc of radius r, centre C, unit normal a spans
/// C_i ± r·√(1 − a_i²) on axis i (the disc's widest extent along e_i is r·|e_i − (e_i·a)a| =
/// r·√(1 − a_i²)); the cylinder spans the union of its two caps' spans.
Aabb boundingBox(const Cylinder& c) noexcept;
/// A plane is unbounded: no box.
std::optional<Aabb> boundingBox(const Plane& p) noexcept;
/// A tube is unbounded: no box.
std::optional<Aabb> boundingBox(const Tube& t) noexcept;

/// The box of any shape; nullopt for the unbounded ones (planes and tubes).
std::optional<Aabb> boundingBox(const Geometry& g) noexcept;

/// Triangle t of a mesh: the minimum and maximum of its corners, per axis (the box of a
/// `Triangle` of the same corners).
Aabb boundingBox(const TriangleMesh& mesh, std::size_t t) noexcept;
/// The box of a primitive: its shape's (nullopt for an unbounded one), or its mesh triangle's.
std::optional<Aabb> boundingBox(const Primitives& primitives, std::uint32_t primitive) noexcept;

}  // namespace rt
