#pragma once
/// @file UtahTeapot.h
/// The Utah teapot: Martin Newell's 1975 Bezier patch data (UtahTeapotData.cpp) and its
/// tessellation into a TriangleMesh, the model of the course's TeapotTest benchmark.

#include <array>
#include <cstddef>
#include <cstdint>

#include "geometries/TriangleMesh.h"
#include "primitives/Double3.h"

namespace rt {

/// Newell's teaset data, as published by Frank Crow: 32 bicubic Bezier patches over 306 control
/// points. Coordinates in Newell's units, z up: the bottom at z = 0, the lid's knob at z = 3.15,
/// the spout towards +x, the handle towards -x, symmetric about the plane y = 0.
struct UtahTeapotData {
  static constexpr std::size_t kPatchCount = 32;
  static constexpr std::size_t kControlPointCount = 306;

  /// Each patch's 16 control points as numbers 1..306 into kControlPoints (one-based, as
  /// published), row by row: entry 4·i + j is the control point P(i, j), i the row (the patch's
  /// v direction), j the column (its u direction). Patches 0-3 the rim, 4-11 the body, 12-15 the
  /// handle, 16-19 the spout, 20-27 the lid, 28-31 the bottom.
  static const std::array<std::array<std::uint16_t, 16>, kPatchCount> kPatches;
  /// The control points; kControlPoints[k - 1] is the point number k of kPatches.
  static const std::array<Double3, kControlPointCount> kControlPoints;
};

/// The largest detail utahTeapot accepts: 256 quads per patch side, 4,192,256 triangles over
/// 2,113,568 vertices (about 152 MB with the normals).
inline constexpr int kUtahTeapotMaxDetail = 256;

/// The triangles utahTeapot(detail) has: 32 patches of detail² quads, two triangles each, less
/// the one degenerate triangle of each quad along the collapsed edge (a pole) of the 4 lid-top
/// and the 4 bottom patches: 64·detail² − 8·detail (992 at the course's detail 4). At detail 1
/// four more go: the spout's two tip patches have their four corners on one line (z = 2.4,
/// y = 0), so both triangles of each are degenerate (52, not 56).
constexpr std::size_t utahTeapotTriangleCount(int detail) {
  const auto d = static_cast<std::size_t>(detail);
  return 64 * d * d - 8 * d - (d == 1 ? 4 : 0);
}

/// The teapot tessellated from Newell's patches, in the data's own coordinates (z up, see
/// UtahTeapotData; the course's TeapotTest looks along +z with y up, so a scene turns it, see
/// stage02's README).
///
/// Each patch is sampled on a (detail + 1) × (detail + 1) grid of parameters (u, v) = (j/detail,
/// i/detail), every sample a vertex with its analytic unit normal normalize(∂P/∂u × ∂P/∂v)
/// (the outward side: Newell's patches are all wound that way). Where an edge of a patch
/// collapses to a point (the lid's knob and the bottom's centre), ∂P/∂u vanishes along it and
/// the normal is the limit from inside the patch, normalize(∂²P/∂u∂v × ∂P/∂v). Each grid quad
/// is split into two triangles along its diagonal (0,0)-(1,1); the degenerate one beside a pole
/// is dropped by TriangleMesh (droppedTriangles() = 8·detail, 4 more at detail 1).
///
/// Vertices are shared inside each patch's grid but not across patches: a point on the border
/// of two patches is stored once per patch (32·(detail + 1)² vertices in all). The copies have
/// the same position, bit for bit where the two patches share the border's control points (the
/// evaluation at a border reduces to them exactly), up to the last bits at the poles: 530
/// distinct positions at detail 4, as the course's "about 530 points". Each copy has its own
/// patch's normal; the copies agree to rounding (the patches join smoothly), except at the point
/// (-2, 0, 0.9) where the handle's lower end touches the body (a corner of both).
///
/// The result depends only on detail: the same call gives the same bits.
/// @param detail quads per patch side, 1..kUtahTeapotMaxDetail (the course's 992 triangles: 4).
/// @throws std::invalid_argument naming the detail and the limit when it is outside 1..256.
TriangleMesh utahTeapot(int detail);

}  // namespace rt
