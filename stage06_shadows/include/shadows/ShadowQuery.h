#pragma once
/// @file ShadowQuery.h
/// The shadow query: how much of a light gets through the shapes between a point and the light.
///
/// It is a query of its own, not "all intersections, then filter": it walks the hits of the
/// shadow ray with Intersectable::forEachHit (no list, no sorting of a list, no allocation),
/// and stops as soon as the answer is known.
///
///     light  *
///             \            transmittance = Π kT over every crossing in the range
///          ----\----  kT1        (a sphere crossed twice counts twice, as in the course)
///               \.
///          ------\--  kT2
///                 \.
///     ============ P' ======  (P shifted by the RayOffset)
///
/// The same bits whatever the order of the hits. Multiplication of doubles is commutative but
/// not associative: (a·b)·c and (a·c)·b can differ in the last bit, and an acceleration
/// structure reports the hits of a shadow ray in another order than the course's linear scan.
/// So the kT of the crossings are multiplied in one canonical order, by (shape index, t): the
/// walk keeps up to CAPACITY crossings on the stack and sorts them; a ray that crosses more
/// shapes than that (rare: each crossing dims the light) finds them in canonical order with one
/// more walk per crossing. The early stops do not depend on the order either: an opaque
/// blocker (kT = 0) makes the product 0 in any order, and the cut-off is applied to a partial
/// product only when no kT of the scene exceeds 1 (then every further factor can only lower it),
/// with a margin far above the rounding differences between orders.

#include <cstdint>

#include "intersections/Intersectable.h"
#include "lighting/LitScene.h"
#include "primitives/Double3.h"
#include "primitives/Ray.h"
#include "shadows/LightOccluders.h"
#include "shadows/ShadowCrossings.h"

namespace rt {

/// What the shadow query found.
struct Transmittance {
  /// Π kT of the blockers, per channel; ZERO when the light is cut off (an opaque blocker, or
  /// the product or the product times the path weight lowerThan the cut-off).
  Double3 factor = Double3::ONE;
  /// How many crossings the walk met before it ended (hits before tMin are not counted).
  int crossings = 0;
  /// True when the walk stopped before visiting every hit (opaque blocker or cut-off).
  bool stoppedEarly = false;
};

/// The shadow query over one scene's shapes and looks.
class ShadowQuery {
 public:
  /// Crossings kept on the stack for the canonical order.
  static constexpr int CAPACITY = ShadowCrossings::CAPACITY;
  /// A partial product stops the walk when below cutOff·(1 − MARGIN) (ShadowCrossings.h).
  static constexpr double MARGIN = ShadowCrossings::MARGIN;

  /// @param shapes what to intersect (scene.geometries or an accelerator over the same shapes);
  ///        it and scene must outlive the query.
  /// @param cutOff the light is cut (factor ZERO) once the product, or the product times the
  ///        path weight, is lowerThan(cutOff) (the course's meaning: all three channels below).
  ShadowQuery(const Intersectable& shapes, const LitScene& scene, double cutOff);

  /// For a shadow ray aimed at no light of the scene's list (a point of a light's disk).
  static constexpr std::uint32_t NO_LIGHT = 0xFFFF'FFFFu;

  /// The transmittance along shadowRay for hits with t in [tMin, tMax] (an empty range when
  /// tMax < tMin: nothing in between). weight is the path weight of the point being shaded
  /// ((1,1,1) for a primary hit). The walk's cost is added to counts when given. light: the
  /// index of the light the ray is aimed at (in LitScene::lights), or NO_LIGHT; it changes only
  /// how the hits are found (walk), never the answer. Allocates nothing; never throws.
  Transmittance operator()(const Ray& shadowRay, double tMin, double tMax, const Double3& weight,
                           QueryCounts* counts = nullptr,
                           std::uint32_t light = NO_LIGHT) const noexcept;

 private:
  /// Hands crossings the hits of ray with t in [tMin, tMax] (and maybe some before tMin), until
  /// it says stop: through the shapes' LightOccluders when they are one and the ray is aimed at
  /// a light (the same shapes crossed, found faster: mini2_bvh's light buffers), else with
  /// shapes.forEachHit. False when crossings stopped the walk.
  bool walk(std::uint32_t light, const Ray& ray, double tMin, double tMax,
            ShadowCrossings& crossings, QueryCounts* counts) const {
    if (occluders_ != nullptr && light != NO_LIGHT)
      return occluders_->crossingsTowards(light, ray, tMin, tMax, crossings, counts);
    return shapes_.forEachHit(
        ray, tMax, [&crossings](const Hit& hit) { return crossings.add(hit); }, counts);
  }
  const Double3& kT(std::uint32_t geometry) const noexcept {
    return scene_.appearanceOf(geometry).material.kT;
  }
  /// Π kT over every crossing in [tMin, tMax], in (geometry, t) order, found by repeated walks.
  Double3 canonicalProduct(const Ray& ray, double tMin, double tMax,
                           QueryCounts* counts) const noexcept;

  const Intersectable& shapes_;
  /// shapes_ as a LightOccluders, when it is one (found once, by the constructor); else null.
  const LightOccluders* occluders_;
  const LitScene& scene_;
  double cutOff_;
  /// True when every kT of the scene is at most 1 in every channel (computed once).
  bool productOnlyFalls_ = true;
};

}  // namespace rt
