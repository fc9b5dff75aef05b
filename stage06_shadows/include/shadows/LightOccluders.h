#pragma once
/// @file LightOccluders.h
/// A seam for what a shadow query walks: the shapes that may stand between a point and one light.
///
/// A shadow ray is not any ray: it is aimed at a light the scene knows before any ray is cast.
/// A structure built for that light (mini2_bvh's light buffers) can list the shapes that may lie
/// on a ray aimed at it far faster than a walk of every box the ray meets. ShadowQuery asks its
/// Intersectable whether it also is a LightOccluders, once, when it is made; if it is, every
/// shadow ray towards a light goes through crossingsTowards, else through forEachHit. Both find
/// the same crossings, so the answer, and the image, are the same bits either way.

#include <cstdint>

#include "intersections/Intersectable.h"
#include "primitives/Ray.h"
#include "shadows/ShadowCrossings.h"

namespace rt {

class LightOccluders {
 public:
  virtual ~LightOccluders() = default;

  /// Hands crossings.add() the hits of a shadow ray aimed at light number `light` of the scene
  /// (its index in LitScene::lights) that matter to a shadow query, in no particular order,
  /// until add returns false (then false is returned): every hit of the shapes with t in
  /// [tMin, tMax]; hits with t in (0, tMin) may be handed over or not. A hit's t is the
  /// shape's solver's, bit for bit, except for a flat shape (triangle, polygon: crossed once at
  /// most) that the structure has proved the ray crosses in [tMin, tMax] without running its
  /// solver: its t is then some value in [tMin, tMax]. A shadow query needs no more: which
  /// shapes are crossed in the range, and in which order along the ray each one's crossings
  /// come (a flat shape has one). A ray that is not aimed at the light, or a light the
  /// structure knows nothing of, gets every hit as Intersectable::forEachHit finds them.
  /// Allocates nothing.
  virtual bool crossingsTowards(std::uint32_t light, const Ray& ray, double tMin, double tMax,
                                ShadowCrossings& crossings,
                                QueryCounts* counts = nullptr) const = 0;
};

}  // namespace rt
