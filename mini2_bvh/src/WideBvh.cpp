// The wide BVH: collapsing the binary tree, and the walks with four float box tests at once.
//
// The box test is FloatRay.h's, written once with SSE (the x86-64 baseline, so every x86-64
// build has it) and once in plain C++ for other processors; both compute the same floats (the
// same operations, each rounded once: SSE's and C++'s float arithmetic are IEEE single
// precision, and neither contracts a multiply and a subtract here: intrinsics are never fused,
// and the plain loop is compiled without FMA in the portable build).

#include "bvh/WideBvh.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "bvh/FloatRay.h"
#include "bvh/HugePages.h"
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
    case 0:
      asm("" ::: "memory");
      return node.child[0];
    case 1:
      asm("" ::: "memory");
      return node.child[1];
    case 2:
      asm("" ::: "memory");
      return node.child[2];
    default:
      asm("" ::: "memory");
      return node.child[3];
  }
}

/// A pending slot of the walk: 8 bytes, written and read whole (two smaller stores read back by
/// one load would stall the store-to-load forwarding of the processor).
struct Pending {
  std::uint32_t ref;  ///< WideBvh's encoding: a node's index, or LEAF | a leaf's index
  float entry;
};

}  // namespace

WideBvh::WideBvh(Primitives primitives, BvhBuildOptions options)
    : binary_(primitives, options, Bvh::SpheresLater{}) {
  if (binary_.nodes_.empty()) return;  // no bounded primitive, so no sphere to copy either
  // A binary tree of n nodes has (n + 1) / 2 leaves; a leaf's index must fit below LEAF.
  const std::size_t leafCount = (binary_.nodes_.size() + 1) / 2;
  if (leafCount >= WideNode::LEAF)
    throw std::length_error("WideBvh: " + std::to_string(leafCount) +
                            " leaves, more than the wide nodes can number (2^31 - 1)");
  Collapser collapser(binary_.nodes_, nodes_, leaves_);
  reserveHugeWritten(nodes_, collapser.count(0));  // filled whole (HugePages.h)
  reserveHugeWritten(leaves_, leafCount);
  collapser.collapse(0, 0);
  depth_ = collapser.depth();
  std::vector<BvhNode>().swap(binary_.nodes_);
  binary_.makeCompactSpheres(Bvh::buildThreads(options.threads));
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
        const double before = nearest.t();
        binary_.forEachPrimitive(asBinaryLeaf(leaf), ray,
                                 [&](const Roots& roots, std::uint32_t shape) {
                                   nearest.offer(roots, shape);
                                   return true;
                                 });
        // Rounded again only when the leaf found a nearer hit (most leaves do not).
        if (nearest.t() != before) limitF = floatLimit(std::min(limit, nearest.t()));
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

// ---- Packets ----
//
// A packet holds up to PACKET rays as structure of arrays, one lane per ray, each lane its
// FloatRay. A slot's box is tested against every lane at once: the lane's near bound is lo or
// hi by its own direction's sign, chosen with and/andnot masks (SSE2 has no blend). The walk
// carries, with each pending slot, the mask of the rays that entered it; a node's slot is
// pushed with the rays of that mask that enter it too. A ray's limit shrinks with its own best
// hit, so its lanes stop entering boxes behind it.

namespace {

constexpr int PACKET = WideBvh::PACKET;

struct PacketLanes {
  alignas(32) float originIn[3][PACKET];
  alignas(32) float originOut[3][PACKET];
  alignas(32) float invIn[3][PACKET];
  alignas(32) float invOut[3][PACKET];
  alignas(32) std::uint32_t negative[3][PACKET];  ///< all ones where the lane's ray runs down
  alignas(32) float limit[PACKET];
};

#if defined(__SSE2__)
/// The lanes of `active` whose ray enters slot k's box: two halves of four lanes.
struct SlotTestSse2 {
  static unsigned test(const WideNode& node, int k, const PacketLanes& p) noexcept {
    unsigned hits = 0;
    for (int h = 0; h < PACKET; h += 4) {
      __m128 tNear = _mm_setzero_ps();
      __m128 tFar = _mm_load_ps(p.limit + h);
      for (int a = 0; a < 3; ++a) {
        const __m128 lo = _mm_set1_ps(node.lo[a][k]);
        const __m128 hi = _mm_set1_ps(node.hi[a][k]);
        const __m128 down =
            _mm_castsi128_ps(_mm_load_si128(reinterpret_cast<const __m128i*>(p.negative[a] + h)));
        const __m128 nearB = _mm_or_ps(_mm_and_ps(down, hi), _mm_andnot_ps(down, lo));
        const __m128 farB = _mm_or_ps(_mm_and_ps(down, lo), _mm_andnot_ps(down, hi));
        const __m128 tIn = _mm_mul_ps(_mm_sub_ps(nearB, _mm_load_ps(p.originIn[a] + h)),
                                      _mm_load_ps(p.invIn[a] + h));
        const __m128 tOut = _mm_mul_ps(_mm_sub_ps(farB, _mm_load_ps(p.originOut[a] + h)),
                                       _mm_load_ps(p.invOut[a] + h));
        tNear = _mm_max_ps(tIn, tNear);
        tFar = _mm_min_ps(tOut, tFar);
      }
      hits |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(tNear, tFar))) << h;
    }
    return hits;
  }
};

/// The same test on eight lanes at once (compiled for AVX2, called only where the processor has
/// it): the same operations lane by lane, so the same floats and the same mask.
struct SlotTestAvx2 {
  __attribute__((target("avx2"))) static unsigned test(const WideNode& node, int k,
                                                       const PacketLanes& p) noexcept {
    __m256 tNear = _mm256_setzero_ps();
    __m256 tFar = _mm256_load_ps(p.limit);
    for (int a = 0; a < 3; ++a) {
      const __m256 lo = _mm256_set1_ps(node.lo[a][k]);
      const __m256 hi = _mm256_set1_ps(node.hi[a][k]);
      const __m256 down =
          _mm256_castsi256_ps(_mm256_load_si256(reinterpret_cast<const __m256i*>(p.negative[a])));
      const __m256 nearB = _mm256_or_ps(_mm256_and_ps(down, hi), _mm256_andnot_ps(down, lo));
      const __m256 farB = _mm256_or_ps(_mm256_and_ps(down, lo), _mm256_andnot_ps(down, hi));
      const __m256 tIn = _mm256_mul_ps(_mm256_sub_ps(nearB, _mm256_load_ps(p.originIn[a])),
                                       _mm256_load_ps(p.invIn[a]));
      const __m256 tOut = _mm256_mul_ps(_mm256_sub_ps(farB, _mm256_load_ps(p.originOut[a])),
                                        _mm256_load_ps(p.invOut[a]));
      // maxps and minps return their second operand for a NaN, in 256 bits as in 128.
      tNear = _mm256_max_ps(tIn, tNear);
      tFar = _mm256_min_ps(tOut, tFar);
    }
    return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(tNear, tFar, _CMP_LE_OS)));
  }
};
#else
/// Other processors: the lanes one by one, the same floats.
struct SlotTestSse2 {
  static unsigned test(const WideNode& node, int k, const PacketLanes& p) noexcept {
    unsigned hits = 0;
    for (int lane = 0; lane < PACKET; ++lane) {
      float tNear = 0, tFar = p.limit[lane];
      for (int a = 0; a < 3; ++a) {
        const bool down = p.negative[a][lane] != 0;
        const float nearB = down ? node.hi[a][k] : node.lo[a][k];
        const float farB = down ? node.lo[a][k] : node.hi[a][k];
        const float tIn = (nearB - p.originIn[a][lane]) * p.invIn[a][lane];
        const float tOut = (farB - p.originOut[a][lane]) * p.invOut[a][lane];
        tNear = tIn > tNear ? tIn : tNear;
        tFar = tOut < tFar ? tOut : tFar;
      }
      if (tNear <= tFar) hits |= 1u << lane;
    }
    return hits;
  }
};
using SlotTestAvx2 = SlotTestSse2;
#endif

/// A pending slot of a packet's walk, with the lanes that entered it and where its box is (so
/// that a leaf's box is tested again, with the lanes' limits of the moment, before its exact
/// tests: a lane may have found a nearer hit since the slot was pushed).
struct PendingLanes {
  std::uint32_t ref;
  std::uint32_t lanes;
  std::uint32_t parent;  ///< the node whose slot it is
  std::uint32_t slot;
};

}  // namespace

WideBvh::Simd WideBvh::bestSimd() noexcept {
#if defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
  static const Simd best = __builtin_cpu_supports("avx2") ? Simd::Avx2 : Simd::Sse2;
  return best;
#else
  return Simd::Sse2;
#endif
}

template <typename SlotTest>
void WideBvh::tracePacket(std::span<const Ray> rays, double tMax,
                          std::span<std::optional<Hit>> hits, QueryCounts* counts) const noexcept {
  const auto n = static_cast<int>(rays.size());
  const double limit = slabLimit(tMax);
  // NearestHit has no default state: the packet's are made in place, one per lane used.
  alignas(NearestHit) unsigned char storage[PACKET * sizeof(NearestHit)];
  NearestHit* nearest = reinterpret_cast<NearestHit*>(storage);
  std::uint64_t tests = 0, visited = 0;
  PacketLanes p;
  for (int lane = 0; lane < PACKET; ++lane) {
    new (&nearest[lane]) NearestHit(tMax);
    const bool used = lane < n;
    const FloatRay r(used ? rays[lane] : rays[0]);
    for (int a = 0; a < 3; ++a) {
      p.originIn[a][lane] = r.originIn[a];
      p.originOut[a][lane] = r.originOut[a];
      p.invIn[a][lane] = r.invIn[a];
      p.invOut[a][lane] = r.invOut[a];
      p.negative[a][lane] = r.negative[a] ? ~0u : 0u;
    }
    if (used) {
      tests += offerUnbounded(binary_.unbounded_, binary_.primitives_, rays[lane], nearest[lane]);
      p.limit[lane] = floatLimit(std::min(limit, nearest[lane].t()));
    } else {
      p.limit[lane] = -FLOAT_INF;  // an unused lane enters nothing
    }
  }
  const std::uint32_t all = (1u << n) - 1;
  if (!nodes_.empty()) {
    PendingLanes stack[STACK_SIZE];
    int top = 0;
    PendingLanes current{0, all, 0, 0};
    for (;;) {
      if ((current.ref & WideNode::LEAF) == 0) {
        const WideNode& node = nodes_[current.ref];
        visited += static_cast<unsigned>(std::popcount(current.lanes));
        std::array<std::uint32_t, WIDTH> entered{};
        unsigned slots = 0;
        for (int k = 0; k < node.used; ++k) {
          entered[k] = SlotTest::test(node, k, p) & current.lanes;
          if (entered[k] != 0) slots |= 1u << k;
        }
        if (slots != 0) {
          // Nearest first along the node's axis, for the direction of the packet's first ray.
          const int first = __builtin_ctz(current.lanes);
          const bool down = p.negative[node.axis][first] != 0;
          // Push all but the one walked next: the lowest slot going up, the highest going down.
          const int next = down ? 31 - __builtin_clz(slots) : __builtin_ctz(slots);
          slots &= ~(1u << next);
          while (slots != 0) {
            const int k = down ? __builtin_ctz(slots) : 31 - __builtin_clz(slots);
            slots &= ~(1u << k);
            stack[top++] =
                PendingLanes{node.child[k], entered[k], current.ref, static_cast<std::uint32_t>(k)};
          }
          current = PendingLanes{node.child[next], entered[next], current.ref,
                                 static_cast<std::uint32_t>(next)};
          continue;
        }
      } else {
        const Leaf& leaf = leaves_[current.ref & ~WideNode::LEAF];
        const std::uint32_t still =
            current.lanes &
            SlotTest::test(nodes_[current.parent], static_cast<int>(current.slot), p);
        for (std::uint32_t lanes = still; lanes != 0; lanes &= lanes - 1) {
          const int lane = __builtin_ctz(lanes);
          tests += leaf.count;
          const double before = nearest[lane].t();
          binary_.forEachPrimitive(asBinaryLeaf(leaf), rays[lane],
                                   [&](const Roots& roots, std::uint32_t shape) {
                                     nearest[lane].offer(roots, shape);
                                     return true;
                                   });
          if (nearest[lane].t() != before)
            p.limit[lane] = floatLimit(std::min(limit, nearest[lane].t()));
        }
      }
      if (top == 0) break;
      current = stack[--top];
    }
  }
  for (int lane = 0; lane < n; ++lane) hits[lane] = nearest[lane].hit();
  addQueryCounts(counts, tests, visited);
}

void WideBvh::tracePacketSse2(std::span<const Ray> rays, double tMax,
                              std::span<std::optional<Hit>> hits,
                              QueryCounts* counts) const noexcept {
  tracePacket<SlotTestSse2>(rays, tMax, hits, counts);
}

// Compiled for AVX2 as a whole, so that the walk, the box tests and the leaves' exact tests
// inline into one function (the exact tests' double arithmetic is IEEE in AVX registers too;
// AVX2 does not bring FMA, so nothing is fused).
__attribute__((target("avx2"))) void WideBvh::tracePacketAvx2(std::span<const Ray> rays,
                                                              double tMax,
                                                              std::span<std::optional<Hit>> hits,
                                                              QueryCounts* counts) const noexcept {
  tracePacket<SlotTestAvx2>(rays, tMax, hits, counts);
}

void WideBvh::closestHits(std::span<const Ray> rays, double tMax,
                          std::span<std::optional<Hit>> hits, QueryCounts* counts,
                          Simd simd) const noexcept {
  const bool avx2 = simd == Simd::Avx2 && bestSimd() == Simd::Avx2;
  for (std::size_t i = 0; i < rays.size(); i += PACKET) {
    const std::size_t n = std::min<std::size_t>(PACKET, rays.size() - i);
    if (avx2)
      tracePacketAvx2(rays.subspan(i, n), tMax, hits.subspan(i, n), counts);
    else
      tracePacketSse2(rays.subspan(i, n), tMax, hits.subspan(i, n), counts);
  }
}

}  // namespace rt
