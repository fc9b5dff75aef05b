// Queries on the BVH: a walk over the flat node array with an explicit stack, near child first.
//
// The closest-hit query prunes a node when the ray misses its box or enters it strictly after
// the best hit so far (a box entered exactly at the best t may still hold a hit with a smaller
// index, which must win, as in the linear scan). The boxes are conservative (FloatBox.h) and the
// slab test rounds towards "hit" (SlabRay.h), so no node is pruned that holds a hit the linear
// scan would return; at the leaves the shapes are tested with the very solvers, and judged by the
// very rule (HitRules.h), of Geometries::closestHit: the answers are the same, bit for bit.

#include "bvh/Bvh.h"

#include <algorithm>

#include "bvh/SlabRay.h"
#include "bvh/UnboundedShapes.h"
#include "intersections/HitRules.h"

namespace rt {

std::span<const std::uint32_t> Bvh::leafShapes(const BvhNode& leaf) const noexcept {
  if (!leaf.isLeaf()) return {};
  const std::vector<std::uint32_t>& shapes =
      leaf.kind == BvhNode::Kind::Spheres ? sphereShapes_ : otherShapes_;
  return std::span<const std::uint32_t>(shapes).subspan(leaf.offset, leaf.count);
}

std::size_t Bvh::memoryBytes() const noexcept {
  return nodes_.capacity() * sizeof(BvhNode) + spheres_.capacity() * sizeof(CompactSphere) +
         (sphereShapes_.capacity() + otherShapes_.capacity() + unbounded_.capacity() +
          otherFlat_.capacity()) *
             sizeof(std::uint32_t) +
         flats_.memoryBytes();
}

template <typename Limit, typename Leaf>
bool Bvh::traverse(const Ray& ray, const Limit& limit, const Leaf& leaf,
                   std::uint64_t& nodesVisited) const {
  // BEGIN SOLUTION: hint: Bvh::traverse, the stack walk, near child first
  if (nodes_.empty()) return true;
  const SlabRay slab(ray);
  // Pending second choices; at most one per level above the current node, and no leaf is deeper
  // than STACK_SIZE − 1 (see SAH_MAX_DEPTH).
  std::uint32_t stack[STACK_SIZE];
  int top = 0;
  std::uint32_t current = 0;
  for (;;) {
    const BvhNode& node = nodes_[current];
    ++nodesVisited;
    double entry;
    if (slabHit(slab, node.box, limit(), entry)) {
      if (!node.isLeaf()) {
        // Near child first: the first child holds the lower centroids along the split axis, so a
        // ray running towards lower coordinates meets the second child first.
        const bool secondFirst = slab.negative[node.axis];
        stack[top++] = secondFirst ? current + 1 : node.offset;
        current = secondFirst ? node.offset : current + 1;
        continue;
      }
      if (!leaf(node)) return false;
    }
    if (top == 0) return true;
    current = stack[--top];
  }
  // END SOLUTION
}

std::optional<Hit> Bvh::closestHit(const Ray& ray, double tMax,
                                   QueryCounts* counts) const noexcept {
  // BEGIN SOLUTION: hint: Bvh::closestHit, unbounded shapes, then the walk, bound min(limit, t)
  NearestHit nearest(tMax);
  std::uint64_t tests = offerUnbounded(unbounded_, primitives_, ray, nearest), visited = 0;
  const double limit = slabLimit(tMax);
  traverse(
      ray, [&] { return std::min(limit, nearest.t()); },
      [&](const BvhNode& leaf) {
        tests += leaf.count;
        return forEachPrimitive(leaf, ray, [&](const Roots& roots, std::uint32_t shape) {
          nearest.offer(roots, shape);
          return true;
        });
      },
      visited);
  addQueryCounts(counts, tests, visited);
  return nearest.hit();
  // END SOLUTION
}

bool Bvh::forEachHit(const Ray& ray, double tMax, HitVisitor visit, QueryCounts* counts) const {
  // BEGIN SOLUTION: hint: Bvh::forEachHit, every hit within tMax until the visitor says stop
  std::uint64_t tests = 0, visited = 0;
  // The unbounded shapes' step, spelled out rather than through visitUnbounded: with the call,
  // GCC 12 stops inlining the walk below into this query, which costs the galaxy 2.4 % of its
  // instructions (callgrind, 96 x 54, one thread); CBR and the grid use the shared step.
  bool complete = true;
  for (std::size_t k = 0; complete && k < unbounded_.size(); ++k) {
    ++tests;
    complete = visitHits(primitives_.roots(unbounded_[k], ray), unbounded_[k], tMax, visit);
  }
  if (complete) {
    const double limit = slabLimit(tMax);
    complete = traverse(
        ray, [limit] { return limit; },
        [&](const BvhNode& leaf) {
          return forEachPrimitive(leaf, ray, [&](const Roots& roots, std::uint32_t shape) {
            ++tests;
            return visitHits(roots, shape, tMax, visit);
          });
        },
        visited);
  }
  addQueryCounts(counts, tests, visited);
  return complete;
  // END SOLUTION
}

}  // namespace rt
