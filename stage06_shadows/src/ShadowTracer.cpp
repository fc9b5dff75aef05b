#include "shadows/ShadowTracer.h"

namespace rt {

ShadowTracer::ShadowTracer(const LitScene& scene, const Intersectable* accelerator,
                           const RayOffset& offset)
    : PhongTracer(scene, accelerator), offset_(offset) {}

Transmittance ShadowTracer::shadowQuery(const Point& p, const Vector& n, const LightSample& light,
                                        const Double3& k) const noexcept {
  // l points from the light to p, so the shadow ray goes along −l.
  const Vector toLight = -light.l;
  const Ray shadowRay = offset_.ray(p, n, toLight);
  const RayOffset::Range range = offset_.shadowRange(p, light.distance);
  return transmittance(intersector_, litScene_.appearances, shadowRay, range.tMin, range.tMax, k,
                       MIN_CALC_COLOR_K);
}

Double3 ShadowTracer::transparency(const HitContext& h, const LightSample& light,
                                   const Double3& k) const {
  const Double3 ktr = shadowQuery(h.point, h.normal, light, k).factor;
  return (ktr * k).lowerThan(MIN_CALC_COLOR_K) ? Double3::ZERO : ktr;
}

}  // namespace rt
