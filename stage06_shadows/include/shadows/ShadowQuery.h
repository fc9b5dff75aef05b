#pragma once
/// @file ShadowQuery.h
/// The shadow query: how much of a light gets through the shapes between a point and the light.
///
/// It is a query of its own, not "all intersections, then filter": it walks the hits of the
/// shadow ray with Intersectable::forEachHit (no list, no sorting, no allocation), multiplies the
/// blockers' kT as it goes, and stops as soon as the product no longer matters.
///
///     light  *
///             \            ktr = Π kT over every crossing in the range
///          ----\----  kT1        (a sphere crossed twice counts twice, as in the course)
///               \.
///          ------\--  kT2
///                 \.
///     ============ P' ======  (P shifted by the RayOffset)

#include <span>

#include "intersections/Intersectable.h"
#include "lighting/LitScene.h"
#include "primitives/Double3.h"
#include "primitives/Ray.h"

namespace rt {

/// What the shadow query found.
struct Transmittance {
  /// Π kT of the blockers, per channel; ZERO when the walk stopped at the cut-off.
  Double3 factor = Double3::ONE;
  /// How many crossings were multiplied in (hits before tMin are not counted).
  int crossings = 0;
  /// True when the walk stopped before visiting every hit (opaque blocker or cut-off).
  bool stoppedEarly = false;
};

/// The transmittance along shadowRay for hits with t in [tMin, tMax].
///
/// @param appearances appearances[i] is the look of shape i of shapes (its kT is used).
/// @param weight the path weight k of the point being shaded ((1,1,1) for a primary hit).
/// @param cutOff the walk stops, with factor ZERO, once factor.lowerThan(cutOff) or
///        (factor·weight).lowerThan(cutOff) — every further blocker can only lower it. An opaque
///        blocker (kT = 0) always stops it. lowerThan has the course's meaning: all three
///        components below.
/// Allocates nothing; never throws.
Transmittance transmittance(const Intersectable& shapes, std::span<const Appearance> appearances,
                            const Ray& shadowRay, double tMin, double tMax, const Double3& weight,
                            double cutOff) noexcept;

}  // namespace rt
