#include "shadows/ShadowQuery.h"

#include <utility>

namespace rt {

namespace {

/// A crossing of the shadow ray, ordered by (geometry, t): the canonical order of the product.
struct Crossing {
  std::uint32_t geometry;
  double t;
};

bool before(const Crossing& a, const Crossing& b) noexcept {
  return a.geometry < b.geometry || (a.geometry == b.geometry && a.t < b.t);
}

}  // namespace

ShadowQuery::ShadowQuery(const Intersectable& shapes, const LitScene& scene, double cutOff)
    : shapes_(shapes), scene_(scene), cutOff_(cutOff) {
  for (const Appearance& a : scene.appearances) {
    const Double3& k = a.material.kT;
    if (k.x > 1 || k.y > 1 || k.z > 1) productOnlyFalls_ = false;
  }
}

Transmittance ShadowQuery::operator()(const Ray& ray, double tMin, double tMax,
                                      const Double3& weight, QueryCounts* counts) const noexcept {
  // BEGIN SOLUTION: hint: ShadowQuery, the blockers' kT product in [tMin, tMax], canonical order
  Transmittance result;
  if (!(tMax >= tMin)) return result;  // an empty range (light closer than 2ε): nothing between

  Crossing kept[CAPACITY];
  int keptCount = 0;
  bool overflow = false;
  Double3 partial = Double3::ONE;  // in the walk's order: only to decide an early stop
  const double stopBelow = cutOff_ * (1 - MARGIN);
  shapes_.forEachHit(
      ray, tMax,
      [&](const Hit& hit) {
        if (hit.t < tMin) return true;  // within ε of the origin: the surface itself
        ++result.crossings;
        const Double3& k = kT(hit.geometry);
        bool cut = k.isExactlyZero();  // an opaque blocker: 0 in any order
        if (!cut && productOnlyFalls_) {
          partial = partial * k;
          cut = partial.lowerThan(stopBelow) || (partial * weight).lowerThan(stopBelow);
        }
        if (cut) {
          result.stoppedEarly = true;
          return false;
        }
        if (keptCount < CAPACITY)
          kept[keptCount++] = {hit.geometry, hit.t};
        else
          overflow = true;
        return true;
      },
      counts);
  if (result.stoppedEarly) {
    result.factor = Double3::ZERO;
    return result;
  }

  if (overflow) {
    result.factor = canonicalProduct(ray, tMin, tMax, counts);
  } else {
    // Insertion sort: a handful of crossings at most.
    for (int i = 1; i < keptCount; ++i)
      for (int j = i; j > 0 && before(kept[j], kept[j - 1]); --j) std::swap(kept[j], kept[j - 1]);
    for (int i = 0; i < keptCount; ++i) result.factor = result.factor * kT(kept[i].geometry);
  }
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
