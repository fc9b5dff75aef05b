#include "shadows/ShadowQuery.h"

#include <utility>

namespace rt {

ShadowQuery::ShadowQuery(const Intersectable& shapes, const LitScene& scene, double cutOff)
    : shapes_(shapes),
      occluders_(dynamic_cast<const LightOccluders*>(&shapes)),
      scene_(scene),
      cutOff_(cutOff) {
  for (const Appearance& a : scene.appearances) {
    const Double3& k = a.material.kT;
    if (k.x > 1 || k.y > 1 || k.z > 1) productOnlyFalls_ = false;
  }
}

Transmittance ShadowQuery::operator()(const Ray& ray, double tMin, double tMax,
                                      const Double3& weight, QueryCounts* counts,
                                      std::uint32_t light) const noexcept {
  // BEGIN SOLUTION: hint: ShadowQuery, the blockers' kT product in [tMin, tMax], canonical order
  Transmittance result;
  if (!(tMax >= tMin)) return result;  // an empty range (light closer than 2ε): nothing between
  ShadowCrossings crossings(scene_, cutOff_, productOnlyFalls_, tMin, weight);
  walk(light, ray, tMin, tMax, crossings, counts);
  result.crossings = crossings.count();
  if (crossings.stoppedEarly()) {
    result.stoppedEarly = true;
    result.factor = Double3::ZERO;
    return result;
  }
  result.factor =
      crossings.overflow() ? canonicalProduct(ray, tMin, tMax, counts) : crossings.product();
  if (result.factor.lowerThan(cutOff_) || (result.factor * weight).lowerThan(cutOff_))
    result.factor = Double3::ZERO;
  return result;
  // END SOLUTION
}

Double3 ShadowQuery::canonicalProduct(const Ray& ray, double tMin, double tMax,
                                      QueryCounts* counts) const noexcept {
  // BEGIN SOLUTION: hint: canonicalProduct, the kT product in (geometry, t) order, walk by walk
  // Each walk finds the smallest crossing after the previous one (and how many crossings share
  // it exactly); its kT joins the product. One walk per distinct crossing, then one that finds
  // none.
  Double3 factor = Double3::ONE;
  bool started = false;
  using Crossing = ShadowCrossings::Crossing;
  constexpr auto before = ShadowCrossings::before;
  Crossing last{};
  for (;;) {
    bool found = false;
    Crossing next{};
    int multiplicity = 0;
    shapes_.forEachHit(
        ray, tMax,
        [&](const Hit& hit) {
          if (hit.t < tMin) return true;
          const Crossing c{hit.geometry, hit.t};
          if (started && !before(last, c)) return true;  // already multiplied in
          if (!found || before(c, next)) {
            next = c;
            multiplicity = 1;
            found = true;
          } else if (!before(next, c)) {
            ++multiplicity;  // the same (geometry, t) again
          }
          return true;
        },
        counts);
    if (!found) return factor;
    for (int i = 0; i < multiplicity; ++i) factor = factor * kT(next.geometry);
    last = next;
    started = true;
  }
  // END SOLUTION
}

}  // namespace rt
