#include "shadows/ShadowQuery.h"

namespace rt {

Transmittance transmittance(const Intersectable& shapes, std::span<const Appearance> appearances,
                            const Ray& shadowRay, double tMin, double tMax, const Double3& weight,
                            double cutOff) noexcept {
  Transmittance result;
  if (!(tMax >= tMin)) return result;  // an empty range (light closer than 2ε): nothing between
  shapes.forEachHit(shadowRay, tMax, [&](const Hit& hit) {
    if (hit.t < tMin) return true;  // within ε of the origin: the surface itself, not a blocker
    result.factor = result.factor * appearances[hit.geometry].material.kT;
    ++result.crossings;
    if (result.factor.isZero() || result.factor.lowerThan(cutOff) ||
        (result.factor * weight).lowerThan(cutOff)) {
      result.factor = Double3::ZERO;
      result.stoppedEarly = true;
      return false;
    }
    return true;
  });
  return result;
}

}  // namespace rt
