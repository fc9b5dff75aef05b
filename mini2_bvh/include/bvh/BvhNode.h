#pragma once
/// @file BvhNode.h
/// One node of the flattened BVH: 32 bytes, so two share a 64-byte cache line (pbrt-v4's
/// LinearBVHNode is the model).
///
///      0          12         24       28     30     31
///     +----------+----------+--------+------+------+------+
///     | box.lo   | box.hi   | offset | count| axis | kind |
///     | 3 floats | 3 floats | u32    | u16  | u8   | u8   |
///     +----------+----------+--------+------+------+------+
///
/// The nodes lie in one array in depth-first order: an interior node's first child is the next
/// node, so only the second child's index is stored (offset). A leaf's primitives are a
/// contiguous range [offset, offset + count) of one of the BVH's primitive arrays, chosen by its
/// kind: the compact spheres, or the other bounded shapes.

#include <cstdint>

#include "bvh/FloatBox.h"

namespace rt {

struct alignas(32) BvhNode {
  enum class Kind : std::uint8_t {
    Interior,  ///< two children: this + 1 and offset
    Spheres,   ///< a leaf of spheres, stored compactly (centre, radius)
    Shapes,    ///< a leaf of other bounded shapes (triangles, polygons, cylinders)
  };

  FloatBox box;              ///< holds every primitive below, rounded outwards
  std::uint32_t offset = 0;  ///< interior: index of the second child; leaf: first primitive
  std::uint16_t count = 0;   ///< leaf: number of primitives (at least 1); interior: 0
  std::uint8_t axis = 0;     ///< interior: the split axis, which orders the children
  Kind kind = Kind::Interior;

  bool isLeaf() const noexcept { return kind != Kind::Interior; }
};

static_assert(sizeof(BvhNode) == 32, "a node is 32 bytes: two per cache line");

}  // namespace rt
