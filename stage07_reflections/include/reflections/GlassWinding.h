#pragma once
/// @file GlassWinding.h

#include <cstdint>
#include <vector>

#include "lighting/LitScene.h"

namespace rt {

/// A connected glass surface of polygons and triangles whose faces are wound both ways: the
/// faces (geometry indices, ascending) that should be reversed, and the others.
struct WindingProblem {
  std::vector<std::uint32_t> reverse;  ///< the faces to reverse; never empty
  std::vector<std::uint32_t> keep;     ///< the faces wound right; never empty
  /// True when every edge of the surface is shared by exactly two of its faces: `reverse` are
  /// then the faces whose normals point inwards. For an open surface, `reverse` is the smaller
  /// class of faces (on a tie, the class without the surface's first face).
  bool closed = false;

  bool operator==(const WindingProblem&) const = default;
};

/// The glass surfaces of `scene` whose faces are wound both ways, ordered by their first face
/// to reverse. Refraction asks a face's normal, which follows its winding, whether a ray enters
/// the glass or leaves it; a face wound the wrong way refracts as if the glass were outside it.
/// Looked at: the polygons and triangles whose material refracts with an index other than 1
/// (ior != 1 and kT not zero), grouped by their row of the appearance table (see the source for
/// the algorithm). Checks a scene once, when it is read; not for per-ray code.
std::vector<WindingProblem> glassWindingProblems(const LitScene& scene);

}  // namespace rt
