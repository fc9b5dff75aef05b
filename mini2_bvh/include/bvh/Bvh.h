#pragma once
/// @file Bvh.h
/// A bounding volume hierarchy built automatically over a scene's shapes: binned surface-area
/// heuristic, one flat array of 32-byte nodes in depth-first order, traversal near child first
/// with an explicit stack. It is an Intersectable over the same shapes and indices as the scene's
/// Geometries and gives the same answers, bit for bit (see the README for why).
///
/// Planes and tubes are unbounded: they stay outside the tree and are tested on their own before
/// it (a plane hit found first also lets the tree skip every box behind it). So is a shape whose
/// box does not fit in floats (coordinates beyond ±3.4e38), which no scene should have.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "bvh/BvhNode.h"
#include "bvh/FlatShapes.h"
#include "geometries/Geometry.h"
#include "intersections/Geometries.h"
#include "intersections/Intersect.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"

namespace rt {

/// How a Bvh is built; the defaults are what a renderer wants.
struct BvhBuildOptions {
  static constexpr int SAH_MAX_DEPTH = 64;
  /// Where the build turns from the SAH to median splits (clamped to 0..SAH_MAX_DEPTH). 0 gives
  /// a median-split tree, to compare with; the tests use small values to reach median splits.
  int sahMaxDepth = SAH_MAX_DEPTH;
  /// Threads that build, the calling thread included; 0: one per core. The tree is the same,
  /// node for node, for any number (BvhBuild.cpp says how).
  int threads = 0;
};

class Bvh final : public Intersectable {
 public:
  /// Number of bins along each axis for the SAH (the candidate splits are the bins' borders);
  /// a range of fewer primitives uses as many bins as it has primitives.
  static constexpr int BINS = 12;
  /// The most primitives a leaf holds (larger sets are split even when the SAH says it does not
  /// pay, as for shapes whose centroids coincide).
  static constexpr int MAX_LEAF_SIZE = 8;
  /// The SAH's cost of one node, in units of one primitive test. Measured, a node visit takes
  /// about 0.6 of a sphere test; but speed hardly changes between 1 and 3 (the README's table)
  /// while the tree shrinks from 98 to 57 bytes per sphere: 3 charges a node its memory too.
  static constexpr double TRAVERSAL_COST = 3.0;
  /// The SAH's cost of one exact test of a bounded shape that is not a sphere (triangle,
  /// polygon, cylinder), in units of one sphere test. Measured on the galaxy, a polygon test runs
  /// about 3.5 times the instructions of a sphere test, with more mispredicted branches; charging
  /// it 4 splits the glass box's and the frame's polygons into small leaves with tight boxes
  /// (see the README): on the galaxy a ray then tests 2.8 shapes instead of 4.9.
  static constexpr double SHAPE_COST = 4.0;
  /// Below this depth the SAH chooses the splits; from it on, object-median splits, which halve
  /// the count at each level, so that no leaf is deeper than this + 33 (< STACK_SIZE).
  static constexpr int SAH_MAX_DEPTH = BvhBuildOptions::SAH_MAX_DEPTH;
  /// Capacity of the traversal stack (node indices), on the stack of the calling thread.
  static constexpr int STACK_SIZE = 128;

  /// Builds the hierarchy over shapes and mesh triangles alike (a mesh's triangles are
  /// primitives of the tree one by one).
  /// @param primitives viewed, not copied (as by a std::span), except the spheres, which the tree
  ///        keeps compactly: the shapes and meshes must outlive the Bvh and stay unchanged. Hit
  ///        indices are the primitives' numbers.
  explicit Bvh(Primitives primitives, BvhBuildOptions options = {})
      : Bvh(primitives, options, SpheresLater{}) {
    nodes_.shrink_to_fit();  // reserved for the most nodes the tree could have (BvhBuild.cpp)
    makeCompactSpheres(buildThreads(options.threads));
  }
  explicit Bvh(std::span<const Geometry> shapes, BvhBuildOptions options = {})
      : Bvh(Primitives(shapes), options) {}
  explicit Bvh(const Geometries& geometries, BvhBuildOptions options = {})
      : Bvh(geometries.primitives(), options) {}
  Bvh(Geometries&&, BvhBuildOptions = {}) = delete;  // would view a temporary

  /// The same answer as Geometries::closestHit over the same shapes, bit for bit. Counts every
  /// node whose box it tests and every exact shape test.
  std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                QueryCounts* counts = nullptr) const noexcept override;
  /// The same hits as Geometries::forEachHit over the same shapes (in another order); stops as
  /// soon as visit returns false.
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts = nullptr) const override;

  /// A sphere as the leaves store it: 32 bytes instead of a 104-byte Geometry, for the cache.
  struct CompactSphere {
    Double3 centre;
    double radius;
  };

  // ---- Inspection: for the tests, the benchmark and the README's figures ----

  /// The nodes, root first; empty when no shape is bounded.
  std::span<const BvhNode> nodes() const noexcept { return nodes_; }
  /// The shapes (indices into the scene) of a leaf node, in their stored order.
  std::span<const std::uint32_t> leafShapes(const BvhNode& leaf) const noexcept;
  /// The sphere leaves' copies of their spheres, in leaf order (leafShapes' order).
  std::span<const CompactSphere> compactSpheres() const noexcept { return spheres_; }
  /// The unbounded shapes (planes, tubes; shapes beyond the float range), tested outside the tree.
  std::span<const std::uint32_t> unboundedShapes() const noexcept { return unbounded_; }
  /// The deepest leaf's depth (the root has depth 0; 0 for an empty tree).
  int depth() const noexcept { return depth_; }
  /// Bytes the Bvh holds on the heap (nodes, compact spheres, index arrays).
  std::size_t memoryBytes() const noexcept;

 private:
  /// The wide BVH collapses this tree's nodes and walks down to its leaves (forEachPrimitive).
  friend class WideBvh;

  /// Builds the nodes and the leaves' index arrays, but not the compact spheres: the wide BVH
  /// makes them once it has freed the binary nodes, so that the two never add up at its peak
  /// (for 10^6 stars, 30 MiB of spheres and 21 MiB of nodes). The node array keeps its
  /// reservation (address space beyond the nodes written).
  struct SpheresLater {};
  Bvh(Primitives primitives, BvhBuildOptions options, SpheresLater);
  /// The sphere leaves' copies of their spheres (spheres_), from sphereShapes_, on `threads`
  /// threads.
  void makeCompactSpheres(int threads);
  /// The threads a build uses for BvhBuildOptions::threads (0: one per core).
  static int buildThreads(int threads) noexcept;
  /// The flat shapes' records (flats_) and where the leaves find them (otherFlat_).
  void makeFlatShapes();

  /// Walks the nodes whose box the ray meets before limit() (asked again at every node, so a
  /// closest-hit query can shrink it), near child first, calling leaf(node) at each leaf reached;
  /// stops when leaf returns false, and then returns false.
  template <typename Limit, typename Leaf>
  bool traverse(const Ray& ray, const Limit& limit, const Leaf& leaf,
                std::uint64_t& nodesVisited) const;
  /// Calls f(roots, shape index) for each primitive of a leaf, until f returns false.
  template <typename F>
  bool forEachPrimitive(const BvhNode& leaf, const Ray& ray, const F& f) const;

  Primitives primitives_;
  std::vector<BvhNode> nodes_;
  std::vector<CompactSphere> spheres_;       ///< the sphere leaves' primitives, in leaf order
  std::vector<std::uint32_t> sphereShapes_;  ///< their numbers among the primitives
  std::vector<std::uint32_t> otherShapes_;   ///< the other leaves' primitives (mesh triangles too)
  std::vector<std::uint32_t> unbounded_;     ///< planes and tubes (and the like): their numbers
  /// The triangles' and polygons' records among the other leaves' primitives: otherFlat_[k] is
  /// otherShapes_[k]'s record in flats_, or NOT_FLAT; empty when there is none.
  std::vector<std::uint32_t> otherFlat_;
  FlatShapes flats_;
  static constexpr std::uint32_t NOT_FLAT = 0xFFFF'FFFFu;
  int depth_ = 0;
};

template <typename F>
inline bool Bvh::forEachPrimitive(const BvhNode& leaf, const Ray& ray, const F& f) const {
  const std::uint32_t end = leaf.offset + leaf.count;
  if (leaf.kind == BvhNode::Kind::Spheres) {
    for (std::uint32_t k = leaf.offset; k < end; ++k) {
      const CompactSphere& s = spheres_[k];
      if (!f(intersectSphereRoots(s.centre, s.radius, ray), sphereShapes_[k])) return false;
    }
  } else {
    for (std::uint32_t k = leaf.offset; k < end; ++k) {
      const std::uint32_t shape = otherShapes_[k];
      const std::uint32_t flat = otherFlat_.empty() ? NOT_FLAT : otherFlat_[k];
      if (!f(flat != NOT_FLAT ? flats_.roots(flat, ray) : primitives_.roots(shape, ray), shape))
        return false;
    }
  }
  return true;
}

}  // namespace rt
