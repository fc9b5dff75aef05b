#include "shadows/ShadowTracer.h"

namespace rt {

ShadowTracer::ShadowTracer(const LitScene& scene, const Intersectable* accelerator,
                           const RayOffset& offset)
    : PhongTracer(scene, accelerator),
      offset_(offset),
      shadows_(intersector_, scene, MIN_CALC_COLOR_K) {}

Transmittance ShadowTracer::shadowQuery(const Point& p, const Vector& n, const Vector& toLight,
                                        double lightDistance, const Double3& k,
                                        RayCounts& counts) const noexcept {
  // BEGIN SOLUTION: hint: shadowQuery, a counted shadow ray from p (offset) to the light
  ++counts.shadow;
  const Ray shadowRay = offset_.ray(p, n, toLight);
  const RayOffset::Range range = offset_.shadowRange(p, lightDistance);
  return shadows_(shadowRay, range.tMin, range.tMax, k, &counts.queries);
  // END SOLUTION
}

Transmittance ShadowTracer::shadowQuery(const Point& p, const Vector& n, const LightSample& light,
                                        const Double3& k, RayCounts& counts) const noexcept {
  // BEGIN SOLUTION: hint: shadowQuery towards a light sample (l goes from the light to p)
  // l points from the light to p, so the shadow ray goes along −l.
  return shadowQuery(p, n, -light.l, light.distance, k, counts);
  // END SOLUTION
}

Double3 ShadowTracer::transmittance(const HitContext& h, std::uint32_t, const LightSample& sample,
                                    const Double3& k, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: ShadowTracer::transmittance, the shadow query's factor
  // The query already cuts the light (ZERO) below MIN_CALC_COLOR_K, alone or times k.
  return shadowQuery(h.point, h.normal, sample, k, ctx.counts).factor;
  // END SOLUTION
}

}  // namespace rt
