#pragma once
/// @file WideBvh.h
/// The wide BVH: the binary SAH tree (Bvh.h) collapsed into nodes of four children whose boxes
/// lie side by side, so that one SSE instruction tests the ray against all four (FloatRay.h
/// proves that the float test never loses a box). The leaves are the binary tree's, tested with
/// the exact double solvers: the same answers as the linear scan, bit for bit. `--accel bvh4`,
/// the default; the binary tree stays the course's reference (`--accel bvh`).
///
///   binary tree (Bvh)                    wide tree (WideBvh)
///
///            A                              [ B1 | B2 | C1 | C2 ]     one node, four boxes
///          /   \                              /    |    |     \     (each slot: a node,
///         B     C             collapse     ...    ...  ...    ...     a leaf or empty)
///        / \   / \              ──►
///      B1  B2 C1  C2.
///
/// Collapsing: a wide node starts with the binary node's two children and, while it has fewer
/// than four, replaces the interior child of largest surface area by its two children (the
/// child a ray most likely enters is opened first). A binary leaf stays a leaf, referenced from
/// its parent's slot, so a wide node's slot is an interior node, a leaf or empty.
///
/// One node, 128 bytes (two cache lines), the boxes as structure of arrays:
///
///      0       16      32      48      64      80      96        112      120    124  125  126
///     +-------+-------+-------+-------+-------+-------+---------+--------+------+----+----+---+
///     | lo.x  | lo.y  | lo.z  | hi.x  | hi.y  | hi.z  | child   | count  | kind |used|axis|pad|
///     | 4 f32 | 4 f32 | 4 f32 | 4 f32 | 4 f32 | 4 f32 | 4 u32   | 4 u16  | 4 u8 | u8 | u8 |   |
///     +-------+-------+-------+-------+-------+-------+---------+--------+------+----+----+---+
///
/// The slots keep the binary tree's left-to-right order. A closest-hit walk takes the entered
/// slots nearest first along the node's top split axis (as the binary walk takes its near
/// child first), pruning those entered beyond the best hit; an every-hit walk (the shadow
/// rays', which visit every hit, so order does not matter) takes them as they come.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "bvh/Bvh.h"
#include "intersections/Geometries.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"

namespace rt {

struct alignas(64) WideNode {
  static constexpr int WIDTH = 4;
  enum class Kind : std::uint8_t {
    Empty,     ///< no child in this slot (its box is empty: lo = +∞, hi = −∞)
    Interior,  ///< a wide node: child is its index
    Spheres,   ///< a leaf of compact spheres: [child, child + count) of the sphere arrays
    Shapes,    ///< a leaf of other bounded primitives: [child, child + count)
  };

  std::array<std::array<float, WIDTH>, 3> lo;  ///< lo[axis][slot]
  std::array<std::array<float, WIDTH>, 3> hi;  ///< hi[axis][slot]
  /// Interior: the node's index; leaf: LEAF | the index of its entry in the leaf table.
  std::array<std::uint32_t, WIDTH> child{};
  std::array<std::uint16_t, WIDTH> count{};  ///< leaf: its primitives; else 0
  std::array<Kind, WIDTH> kind{};
  std::uint8_t used = 0;  ///< slots in use (the first `used`; at least 2 but in a one-leaf tree)
  std::uint8_t axis = 0;  ///< the top split's axis, along which the slots are ordered

  /// The bit of `child` that marks a leaf.
  static constexpr std::uint32_t LEAF = 0x8000'0000u;

  /// The box of a slot, as the binary tree stored it.
  FloatBox box(int slot) const noexcept {
    return FloatBox{{lo[0][slot], lo[1][slot], lo[2][slot]},
                    {hi[0][slot], hi[1][slot], hi[2][slot]}};
  }
};

static_assert(sizeof(WideNode) == 128, "a wide node is two cache lines");

class WideBvh final : public Intersectable {
 public:
  /// Capacity of the walk's stack: a node pushes at most WIDTH − 1 entries more than it pops,
  /// once per level, and no leaf is deeper than the binary tree's limit.
  static constexpr int STACK_SIZE = (WideNode::WIDTH - 1) * Bvh::STACK_SIZE + WideNode::WIDTH;

  /// Builds the binary tree over the primitives (Bvh's options), then collapses it; the binary
  /// nodes are freed, the leaves' primitive arrays kept. Viewed, not copied, as by Bvh.
  explicit WideBvh(Primitives primitives, BvhBuildOptions options = {});
  explicit WideBvh(const Geometries& geometries, BvhBuildOptions options = {})
      : WideBvh(geometries.primitives(), options) {}
  WideBvh(Geometries&&, BvhBuildOptions = {}) = delete;  // would view a temporary

  /// The same answer as Geometries::closestHit, bit for bit; counts every wide node whose four
  /// boxes it tests (as one visit) and every exact test.
  std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                QueryCounts* counts = nullptr) const noexcept override;
  /// The same hits as Geometries::forEachHit (in another order); stops when visit says so.
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts = nullptr) const override;

  // ---- Packets: rays traced together ----

  /// The rays closestHits traces together: one lane each of an AVX register (or of two SSE ones).
  static constexpr int PACKET = 8;
  /// The instruction set of the packets' box tests. Both compute the same floats lane by lane
  /// (the same IEEE operations, none fused), so the answers are the same bits: only the speed
  /// differs.
  enum class Simd {
    Sse2,  ///< the x86-64 baseline (or plain C++ elsewhere): two 4-lane halves
    Avx2,  ///< 8 lanes at once, chosen at run time where the processor has AVX2
  };
  /// Avx2 when this build and processor have it, else Sse2.
  static Simd bestSimd() noexcept;

  /// closestHit of each ray, hits[i] for rays[i] (hits.size() == rays.size()), the rays traced
  /// together PACKET at a time: a node is fetched once for the packet and each slot's box tested
  /// against every ray of it in one go. The answers are closestHit's, bit for bit. Counts add one
  /// node visit per ray that tests a node's boxes, and the exact tests made (a packet may test a
  /// leaf for a ray that has since found a nearer hit, so these can exceed closestHit's).
  /// Allocates nothing.
  void closestHits(std::span<const Ray> rays, double tMax, std::span<std::optional<Hit>> hits,
                   QueryCounts* counts, Simd simd) const noexcept;
  /// The packets with bestSimd(): what a tracer gets through Intersectable.
  void closestHits(std::span<const Ray> rays, double tMax, std::span<std::optional<Hit>> hits,
                   QueryCounts* counts = nullptr) const noexcept override {
    closestHits(rays, tMax, hits, counts, bestSimd());
  }

  // ---- Inspection: for the tests, the benchmark and the README ----

  /// The wide nodes, root first; empty when no primitive is bounded.
  std::span<const WideNode> nodes() const noexcept { return nodes_; }
  /// A leaf as the walk finds it from a slot: its range of one of the primitive arrays.
  struct Leaf {
    std::uint32_t first;
    std::uint16_t count;
    BvhNode::Kind kind;  ///< Spheres or Shapes
  };
  /// The leaf table (a leaf slot's child is LEAF | its index here).
  std::span<const Leaf> leaves() const noexcept { return leaves_; }
  /// The primitives of a leaf slot (kind Spheres or Shapes), in their stored order.
  std::span<const std::uint32_t> leafShapes(const WideNode& node, int slot) const noexcept;
  /// Primitives tested outside the tree (planes, tubes, shapes beyond the float range).
  std::span<const std::uint32_t> unboundedShapes() const noexcept {
    return binary_.unboundedShapes();
  }
  /// The deepest wide node's depth (the root has depth 0).
  int depth() const noexcept { return depth_; }
  /// Bytes held on the heap: the wide nodes and the leaves' arrays.
  std::size_t memoryBytes() const noexcept;

 private:
  template <typename SlotTest>
  void tracePacket(std::span<const Ray> rays, double tMax, std::span<std::optional<Hit>> hits,
                   QueryCounts* counts) const noexcept;
  void tracePacketSse2(std::span<const Ray> rays, double tMax, std::span<std::optional<Hit>> hits,
                       QueryCounts* counts) const noexcept;
  void tracePacketAvx2(std::span<const Ray> rays, double tMax, std::span<std::optional<Hit>> hits,
                       QueryCounts* counts) const noexcept;

  /// The binary tree whose leaves (primitive arrays) the wide nodes reference; its own nodes
  /// are freed once collapsed.
  Bvh binary_;
  std::vector<WideNode> nodes_;
  std::vector<Leaf> leaves_;
  int depth_ = 0;
};

}  // namespace rt
