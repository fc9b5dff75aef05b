#include "bvh/Cbr.h"

#include <algorithm>

#include "bvh/BoundingBox.h"
#include "bvh/SlabRay.h"
#include "bvh/UnboundedShapes.h"
#include "intersections/HitRules.h"

namespace rt {

Cbr::Cbr(Primitives primitives) : primitives_(primitives) {
  bounded_.reserve(primitives.size());
  for (std::uint32_t i = 0; i < primitives.size(); ++i) {
    if (const std::optional<Aabb> box = boundingBox(primitives, i))
      bounded_.push_back(BoxedShape{conservativeBox(*box), i});
    else
      unbounded_.push_back(i);
  }
}

std::optional<Hit> Cbr::closestHit(const Ray& ray, double tMax,
                                   QueryCounts* counts) const noexcept {
  // BEGIN SOLUTION: hint: Cbr::closestHit, a shape's exact test only when its box is hit
  NearestHit nearest(tMax);
  std::uint64_t tests = offerUnbounded(unbounded_, primitives_, ray, nearest);
  const SlabRay slab(ray);
  const double limit = slabLimit(tMax);
  for (const BoxedShape& s : bounded_) {
    // A box entered strictly after the best hit cannot hold a better one; at exactly the best t
    // it can (a smaller index), so that box is still opened.
    double entry;
    if (!slabHit(slab, s.box, std::min(limit, nearest.t()), entry)) continue;
    nearest.offer(primitives_.roots(s.geometry, ray), s.geometry);
    ++tests;
  }
  addQueryCounts(counts, tests, bounded_.size());
  return nearest.hit();
  // END SOLUTION
}

bool Cbr::forEachHit(const Ray& ray, double tMax, HitVisitor visit, QueryCounts* counts) const {
  // BEGIN SOLUTION: hint: Cbr::forEachHit, visit the hits of the shapes whose box is hit
  std::uint64_t tests = 0;
  bool complete = visitUnbounded(unbounded_, primitives_, ray, tMax, visit, tests);
  const SlabRay slab(ray);
  const double limit = slabLimit(tMax);
  std::uint64_t boxes = 0;
  for (std::size_t k = 0; complete && k < bounded_.size(); ++k) {
    const BoxedShape& s = bounded_[k];
    ++boxes;
    double entry;
    if (!slabHit(slab, s.box, limit, entry)) continue;
    ++tests;
    complete = visitHits(primitives_.roots(s.geometry, ray), s.geometry, tMax, visit);
  }
  addQueryCounts(counts, tests, boxes);
  return complete;
  // END SOLUTION
}

}  // namespace rt
