// The wide BVH: collapsing the binary tree, and the walks with four float box tests at once.
//
// The box test is FloatRay.h's, written once with SSE (the x86-64 baseline, so every x86-64
// build has it) and once in plain C++ for other processors; both compute the same floats (the
// same operations, each rounded once: SSE's and C++'s float arithmetic are IEEE single
// precision, and neither contracts a multiply and a subtract here: intrinsics are never fused,
// and the plain loop is compiled without FMA in the portable build).

#include "bvh/WideBvh.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "bvh/FloatRay.h"
#include "bvh/SlabRay.h"
#include "bvh/UnboundedShapes.h"
#include "intersections/HitRules.h"

namespace rt {

namespace {

constexpr int WIDTH = WideNode::WIDTH;
constexpr float FLOAT_INF = std::numeric_limits<float>::infinity();

/// Builds the wide nodes from the binary ones, depth first (a node's index is below its
/// children's).
class Collapser {
 public:
  Collapser(std::span<const BvhNode> binary, std::vector<WideNode>& wide,
            std::vector<WideBvh::Leaf>& leaves)
      : binary_(binary), wide_(wide), leaves_(leaves) {}

  /// The wide nodes that collapsing the subtree of binary node `index` makes (a dry run, so
  /// that the array is allocated once, at its size: no copy of it ever coexists with it).
  std::size_t count(std::uint32_t index) const noexcept {
    std::array<std::uint32_t, WIDTH> slots{};
    const int used = slotsOf(index, slots);
    std::size_t n = 1;
    for (int k = 0; k < used; ++k)
      if (!binary_[slots[k]].isLeaf()) n += count(slots[k]);
    return n;
  }

  /// Collapses the subtree of binary node `index` into wide nodes; returns the first one's index.
  std::uint32_t collapse(std::uint32_t index, int depth) {
    depth_ = std::max(depth_, depth);
    std::array<std::uint32_t, WIDTH> slots{};
    const int used = slotsOf(index, slots);
    WideNode out;
    for (int a = 0; a < 3; ++a) {
      out.lo[a].fill(FLOAT_INF);
      out.hi[a].fill(-FLOAT_INF);
    }
    out.used = static_cast<std::uint8_t>(used);
    out.axis = binary_[index].axis;
    const auto at = static_cast<std::uint32_t>(wide_.size());
    wide_.emplace_back();
    for (int k = 0; k < used; ++k) {
      const BvhNode& s = binary_[slots[k]];
      for (int a = 0; a < 3; ++a) {
        out.lo[a][k] = s.box.lo[a];
        out.hi[a][k] = s.box.hi[a];
      }
      if (s.isLeaf()) {
        out.kind[k] =
            s.kind == BvhNode::Kind::Spheres ? WideNode::Kind::Spheres : WideNode::Kind::Shapes;
        out.child[k] = WideNode::LEAF | static_cast<std::uint32_t>(leaves_.size());
        out.count[k] = s.count;
        leaves_.push_back(WideBvh::Leaf{s.offset, s.count, s.kind});
      } else {
        out.kind[k] = WideNode::Kind::Interior;
        out.child[k] = collapse(slots[k], depth + 1);
      }
    }
    wide_[at] = out;
    return at;
  }

  int depth() const noexcept { return depth_; }

 private:
  /// The slots of the wide node made from binary node `index`, as binary node indices: its two
  /// children (or the node itself, a leaf at the root), then the widest interior slot opened
  /// until four are full (or every slot is a leaf). Returns how many.
  int slotsOf(std::uint32_t index, std::array<std::uint32_t, WIDTH>& slots) const noexcept {
    int used = 0;
    const BvhNode& node = binary_[index];
    if (node.isLeaf()) {
      slots[used++] = index;
      return used;
    }
    slots[used++] = index + 1;
    slots[used++] = node.offset;
    while (used < WIDTH) {
      int widest = -1;
      double widestArea = -1;
      for (int k = 0; k < used; ++k) {
        const BvhNode& s = binary_[slots[k]];
        const double area = s.box.widen().surfaceArea();
        if (!s.isLeaf() && area > widestArea) {
          widest = k;
          widestArea = area;
        }
      }
      if (widest < 0) break;  // every slot is a leaf
      // The opened slot's children take its place, in order: the slots stay in the binary
      // tree's left-to-right order, the order of the top split's axis.
      const std::uint32_t opened = slots[widest];
      for (int k = used; k > widest + 1; --k) slots[k] = slots[k - 1];
      slots[widest] = opened + 1;
      slots[widest + 1] = binary_[opened].offset;
      ++used;
    }
    return used;
  }

  std::span<const BvhNode> binary_;
  std::vector<WideNode>& wide_;
  std::vector<WideBvh::Leaf>& leaves_;
  int depth_ = 0;
};

/// A FloatRay spread over the lanes, for the four slots of a node at once: every number
/// broadcast, and per axis the byte offsets in a node of the bounds met first and last (lo or
/// hi), so that the walk's loads need no branch.
struct LaneRay {
#if defined(__SSE2__)
  __m128 originIn[3], originOut[3], invIn[3], invOut[3];
#else
  FloatRay ray;
#endif
  std::array<std::size_t, 3> nearOffset, farOffset;
  std::array<bool, 3> negative;

  explicit LaneRay(const FloatRay& r) noexcept
#if !defined(__SSE2__)
      : ray(r)
#endif
  {
    for (int a = 0; a < 3; ++a) {
#if defined(__SSE2__)
      originIn[a] = _mm_set1_ps(r.originIn[a]);
      originOut[a] = _mm_set1_ps(r.originOut[a]);
      invIn[a] = _mm_set1_ps(r.invIn[a]);
      invOut[a] = _mm_set1_ps(r.invOut[a]);
#endif
      const std::size_t lo = offsetof(WideNode, lo) + a * sizeof(WideNode::lo[0]);
      const std::size_t hi = offsetof(WideNode, hi) + a * sizeof(WideNode::hi[0]);
      negative[a] = r.negative[a];
      nearOffset[a] = r.negative[a] ? hi : lo;
      farOffset[a] = r.negative[a] ? lo : hi;
    }
  }
};

/// The four floats of a node at a byte offset (a row of lo or hi).
inline const float* row(const WideNode& node, std::size_t offset) noexcept {
  return reinterpret_cast<const float*>(reinterpret_cast<const char*>(&node) + offset);
}

/// The slots of node whose box the ray enters at some t in [0, limit] (bit k for slot k), with
/// their entries; conservative (FloatRay.h).
inline unsigned enteredSlots(const WideNode& node, const LaneRay& r, float limit,
                             std::array<float, WIDTH>& entry) noexcept {
#if defined(__SSE2__)
  __m128 tNear = _mm_setzero_ps();
  __m128 tFar = _mm_set1_ps(limit);
  for (int a = 0; a < 3; ++a) {
    const __m128 nearB = _mm_load_ps(row(node, r.nearOffset[a]));
    const __m128 farB = _mm_load_ps(row(node, r.farOffset[a]));
    const __m128 tIn = _mm_mul_ps(_mm_sub_ps(nearB, r.originIn[a]), r.invIn[a]);
    const __m128 tOut = _mm_mul_ps(_mm_sub_ps(farB, r.originOut[a]), r.invOut[a]);
    // The new value first: maxps and minps return the second operand when one is NaN.
    tNear = _mm_max_ps(tIn, tNear);
    tFar = _mm_min_ps(tOut, tFar);
  }
  _mm_storeu_ps(entry.data(), tNear);
  const auto hits = static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(tNear, tFar)));
#else
  unsigned hits = 0;
  for (int k = 0; k < WIDTH; ++k) {
    float tNear = 0;
    float tFar = limit;
    for (int a = 0; a < 3; ++a) {
      const float tIn = (row(node, r.nearOffset[a])[k] - r.ray.originIn[a]) * r.ray.invIn[a];
      const float tOut = (row(node, r.farOffset[a])[k] - r.ray.originOut[a]) * r.ray.invOut[a];
      tNear = tIn > tNear ? tIn : tNear;  // a NaN leaves the bound as it was
      tFar = tOut < tFar ? tOut : tFar;
    }
    entry[k] = tNear;
    if (tNear <= tFar) hits |= 1u << k;
  }
#endif
  return hits & ((1u << node.used) - 1);
}

/// node.child[k], through a branch per value of k: the next node's address then depends on a
/// predicted branch, which the processor runs ahead of, rather than on the box test's result,
/// which it would wait for (a bit scan's result used as an index is a data dependency). The
/// empty asm statements keep the compiler from merging the four loads back into one.
inline std::uint32_t childAt(const WideNode& node, int k) noexcept {
  switch (k) {
    case 0: asm("" ::: "memory"); return node.child[0];
    case 1: asm("" ::: "memory"); return node.child[1];
    case 2: asm("" ::: "memory"); return node.child[2];
    default: asm("" ::: "memory"); return node.child[3];
  }
}

/// A pending slot of the walk: 8 bytes, written and read whole (two smaller stores read back by
/// one load would stall the store-to-load forwarding of the processor).
struct Pending {
  std::uint32_t ref;  ///< WideBvh's encoding: a node's index, or LEAF | a leaf's index
  float entry;
};

}  // namespace

WideBvh::WideBvh(Primitives primitives, BvhBuildOptions options) : binary_(primitives, options) {
  if (binary_.nodes_.empty()) return;
  // A binary tree of n nodes has (n + 1) / 2 leaves; a leaf's index must fit below LEAF.
  const std::size_t leafCount = (binary_.nodes_.size() + 1) / 2;
  if (leafCount >= WideNode::LEAF)
    throw std::length_error("WideBvh: " + std::to_string(leafCount) +
                            " leaves, more than the wide nodes can number (2^31 - 1)");
  Collapser collapser(binary_.nodes_, nodes_, leaves_);
  nodes_.reserve(collapser.count(0));
  leaves_.reserve(leafCount);
  collapser.collapse(0, 0);
  depth_ = collapser.depth();
  std::vector<BvhNode>().swap(binary_.nodes_);
}

std::span<const std::uint32_t> WideBvh::leafShapes(const WideNode& node, int slot) const noexcept {
  const std::vector<std::uint32_t>* shapes = nullptr;
  if (node.kind[slot] == WideNode::Kind::Spheres) shapes = &binary_.sphereShapes_;
  if (node.kind[slot] == WideNode::Kind::Shapes) shapes = &binary_.otherShapes_;
  if (shapes == nullptr) return {};
  const Leaf& leaf = leaves_[node.child[slot] & ~WideNode::LEAF];
  return std::span<const std::uint32_t>(*shapes).subspan(leaf.first, leaf.count);
}

std::size_t WideBvh::memoryBytes() const noexcept {
  return binary_.memoryBytes() + nodes_.capacity() * sizeof(WideNode) +
         leaves_.capacity() * sizeof(Leaf);
}

namespace {
/// The binary node that Bvh::forEachPrimitive reads a leaf's range from.
BvhNode asBinaryLeaf(const WideBvh::Leaf& leaf) noexcept {
  BvhNode node;
  node.offset = leaf.first;
  node.count = leaf.count;
  node.kind = leaf.kind;
  return node;
}
}  // namespace

std::optional<Hit> WideBvh::closestHit(const Ray& ray, double tMax,
                                       QueryCounts* counts) const noexcept {
  NearestHit nearest(tMax);
  std::uint64_t tests = offerUnbounded(binary_.unbounded_, binary_.primitives_, ray, nearest);
  std::uint64_t visited = 0;
  if (!nodes_.empty()) {
    const LaneRay lanes{FloatRay(ray)};
    const double limit = slabLimit(tMax);
    float limitF = floatLimit(std::min(limit, nearest.t()));
    Pending stack[STACK_SIZE];
    int top = 0;
    std::uint32_t current = 0;  // the root
    for (;;) {
      if ((current & WideNode::LEAF) == 0) {
        const WideNode& node = nodes_[current];
        ++visited;
        std::array<float, WIDTH> entry;
        unsigned hits = enteredSlots(node, lanes, limitF, entry);
        if (hits != 0) {
          int k = __builtin_ctz(hits);
          hits &= hits - 1;
          if (hits == 0) {  // one slot entered, the most common case: straight on
            current = childAt(node, k);
            continue;
          }
          // Several: push them so that the nearest along the node's top split axis comes off
          // the stack first (the slots are in that axis's order, low to high). Sorting by the
          // entries instead was slower on the galaxy (59 against 64 ns per camera ray) and
          // tested more shapes (1.71 against 1.60 per ray): the entries of boxes that hold the
          // ray's origin are all 0.
          hits |= 1u << k;
          if (lanes.negative[node.axis]) {
            for (; hits != 0; hits &= hits - 1) {
              k = __builtin_ctz(hits);
              stack[top++] = Pending{node.child[k], entry[k]};
            }
          } else {
            for (; hits != 0; hits &= ~(1u << k)) {
              k = 31 - __builtin_clz(hits);
              stack[top++] = Pending{node.child[k], entry[k]};
            }
          }
          current = stack[--top].ref;
          continue;
        }
      } else {
        const Leaf& leaf = leaves_[current & ~WideNode::LEAF];
        tests += leaf.count;
        binary_.forEachPrimitive(asBinaryLeaf(leaf), ray,
                                 [&](const Roots& roots, std::uint32_t shape) {
                                   nearest.offer(roots, shape);
                                   return true;
                                 });
        limitF = floatLimit(std::min(limit, nearest.t()));
      }
      // The next pending slot not entered beyond the best hit found since it was pushed.
      while (top > 0 && stack[top - 1].entry > limitF) --top;
      if (top == 0) break;
      current = stack[--top].ref;
    }
  }
  addQueryCounts(counts, tests, visited);
  return nearest.hit();
}

bool WideBvh::forEachHit(const Ray& ray, double tMax, HitVisitor visit, QueryCounts* counts) const {
  std::uint64_t tests = 0, visited = 0;
  bool complete = true;
  const std::vector<std::uint32_t>& unbounded = binary_.unbounded_;
  for (std::size_t k = 0; complete && k < unbounded.size(); ++k) {
    ++tests;
    complete = visitHits(binary_.primitives_.roots(unbounded[k], ray), unbounded[k], tMax, visit);
  }
  if (complete && !nodes_.empty()) {
    const LaneRay lanes{FloatRay(ray)};
    const float limitF = floatLimit(slabLimit(tMax));
    // Only the references: every entered slot is walked, in no particular order.
    std::uint32_t stack[STACK_SIZE];
    int top = 0;
    std::uint32_t current = 0;  // the root
    for (;;) {
      if ((current & WideNode::LEAF) == 0) {
        const WideNode& node = nodes_[current];
        ++visited;
        std::array<float, WIDTH> entry;
        unsigned hits = enteredSlots(node, lanes, limitF, entry);
        if (hits != 0) {
          current = childAt(node, __builtin_ctz(hits));
          for (hits &= hits - 1; hits != 0; hits &= hits - 1)
            stack[top++] = node.child[__builtin_ctz(hits)];
          continue;
        }
      } else {
        const Leaf& leaf = leaves_[current & ~WideNode::LEAF];
        complete = binary_.forEachPrimitive(asBinaryLeaf(leaf), ray,
                                            [&](const Roots& roots, std::uint32_t shape) {
                                              ++tests;
                                              return visitHits(roots, shape, tMax, visit);
                                            });
        if (!complete) break;
      }
      if (top == 0) break;
      current = stack[--top];
    }
  }
  addQueryCounts(counts, tests, visited);
  return complete;
}

}  // namespace rt
