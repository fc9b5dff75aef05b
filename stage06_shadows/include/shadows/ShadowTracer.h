#pragma once
/// @file ShadowTracer.h

#include "intersections/Intersectable.h"
#include "lighting/LightSource.h"
#include "lighting/LitScene.h"
#include "lighting/PhongTracer.h"
#include "primitives/Double3.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"
#include "shadows/RayOffset.h"
#include "shadows/ShadowQuery.h"

namespace rt {

/// The course's stage-7 part 1: the Phong tracer with shadows and partial shadows.
///
/// For every light that passes the same-side rule, a shadow ray leaves the hit point (shifted by
/// the RayOffset) towards the light, and the light's intensity is scaled by the transmittance
/// Π kT of the blockers in the ray's range (see RayOffset::shadowRange). A light whose
/// transmittance times the path weight k is lowerThan MIN_CALC_COLOR_K (PhongTracer's, 0.001)
/// is skipped.
class ShadowTracer : public PhongTracer {
 public:
  /// @param scene must outlive the tracer.
  /// @param accelerator see RayTracer.
  /// @param offset how secondary rays leave a surface (default: scale-aware).
  /// @throws what scene.validate() throws.
  explicit ShadowTracer(const LitScene& scene, const Intersectable* accelerator = nullptr,
                        const RayOffset& offset = RayOffset{});

  const RayOffset& rayOffset() const { return offset_; }

  /// The shadow ray from point p of a surface with unit normal n along the unit direction
  /// toLight, to a light at distance lightDistance from p (+infinity for a directional light),
  /// for a path of weight k; counted in counts (one shadow ray and its queries). light: the
  /// index of the light the ray is aimed at, or ShadowQuery::NO_LIGHT (see ShadowQuery; the
  /// answer is the same). Allocates nothing, never throws.
  Transmittance shadowQuery(const Point& p, const Vector& n, const Vector& toLight,
                            double lightDistance, const Double3& k, RayCounts& counts,
                            std::uint32_t light = ShadowQuery::NO_LIGHT) const noexcept;
  /// The same towards a light that gives p the sample (its direction −l, its distance).
  Transmittance shadowQuery(const Point& p, const Vector& n, const LightSample& sample,
                            const Double3& k, RayCounts& counts,
                            std::uint32_t light = ShadowQuery::NO_LIGHT) const noexcept;

 protected:
  /// The transmittance towards the light (one shadow ray), ZERO when it, or it times k, is
  /// lowerThan(MIN_CALC_COLOR_K) (the light is then skipped).
  Double3 transmittance(const HitContext& h, std::uint32_t light, const LightSample& sample,
                        const Double3& k, SampleContext& ctx) const override;

  RayOffset offset_;
  ShadowQuery shadows_;
};

// Defined here, not in ShadowTracer.cpp, so that the tracers above (the beam tracer's
// transmittance) reach the shadow query without a call per layer: these run once per light and
// shaded point.

inline Transmittance ShadowTracer::shadowQuery(const Point& p, const Vector& n,
                                               const Vector& toLight, double lightDistance,
                                               const Double3& k, RayCounts& counts,
                                               std::uint32_t light) const noexcept {
  // BEGIN SOLUTION: hint: shadowQuery, a counted shadow ray from p (offset) to the light
  ++counts.shadow;
  const Ray shadowRay = offset_.ray(p, n, toLight);
  const RayOffset::Range range = offset_.shadowRange(p, lightDistance);
  return shadows_(shadowRay, range.tMin, range.tMax, k, &counts.queries, light);
  // END SOLUTION
}

inline Transmittance ShadowTracer::shadowQuery(const Point& p, const Vector& n,
                                               const LightSample& sample, const Double3& k,
                                               RayCounts& counts,
                                               std::uint32_t light) const noexcept {
  // BEGIN SOLUTION: hint: shadowQuery towards a light sample (l goes from the light to p)
  // l points from the light to p, so the shadow ray goes along −l.
  return shadowQuery(p, n, -sample.l, sample.distance, k, counts, light);
  // END SOLUTION
}

inline Double3 ShadowTracer::transmittance(const HitContext& h, std::uint32_t light,
                                           const LightSample& sample, const Double3& k,
                                           SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: ShadowTracer::transmittance, the shadow query's factor
  // A light that gives P nothing (a spot light facing away) is skipped without a shadow ray:
  // its term would be zero whatever blocks it.
  if (sample.intensity.rgb().isExactlyZero()) return Double3::ZERO;
  // The query already cuts the light (ZERO) below MIN_CALC_COLOR_K, alone or times k. The
  // light's index lets an acceleration with a structure per light find the blockers faster.
  return shadowQuery(h.point, h.normal, sample, k, ctx.counts, light).factor;
  // END SOLUTION
}

}  // namespace rt
