// mini2: the BVH's structure. Invariants on random scenes (every bounded shape in exactly one
// leaf, unbounded ones outside, each child's box inside its parent's, each leaf's box around its
// shapes' boxes, depth-first layout, one kind per leaf, depth below the stack's size), the SAH's
// choice on two clusters, and the degenerate scenes: empty, one shape, only unbounded shapes,
// identical centroids, a distribution that defeats the SAH's balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>
#include <vector>

#include "bvh/BoundingBox.h"
#include "bvh/Bvh.h"

#include "RandomScenes.h"

namespace rt {
namespace {

static_assert(sizeof(BvhNode) == 32 && alignof(BvhNode) == 32, "two nodes per cache line");

/// Checks every invariant of the tree over scene; returns the number of leaves.
int expectValidTree(const Bvh& bvh, const Geometries& scene) {
  const auto nodes = bvh.nodes();
  std::vector<int> seen(scene.size(), 0);
  for (std::uint32_t i : bvh.unboundedShapes()) {
    const std::optional<Aabb> box = boundingBox(scene[i]);
    EXPECT_TRUE(!box || !std::isfinite(conservativeBox(*box).widen().surfaceArea()))
        << "shape " << i << " has a float box";
    ++seen[i];
  }
  int leaves = 0, deepest = 0;
  // (node, depth) pairs, walked depth-first from the root.
  std::vector<std::pair<std::uint32_t, int>> pending;
  if (!nodes.empty()) pending.emplace_back(0, 0);
  std::uint32_t walked = 0;
  while (!pending.empty()) {
    const auto [index, depth] = pending.back();
    pending.pop_back();
    ++walked;
    const BvhNode& node = nodes[index];
    const Aabb box = node.box.widen();
    if (node.isLeaf()) {
      ++leaves;
      deepest = std::max(deepest, depth);
      EXPECT_GE(node.count, 1);
      EXPECT_LE(node.count, Bvh::MAX_LEAF_SIZE);
      for (std::uint32_t shape : bvh.leafShapes(node)) {
        ++seen[shape];
        EXPECT_TRUE(box.contains(conservativeBox(*boundingBox(scene[shape])).widen()));
        EXPECT_EQ(std::holds_alternative<Sphere>(scene[shape]),
                  node.kind == BvhNode::Kind::Spheres);
      }
      continue;
    }
    EXPECT_EQ(node.count, 0);
    EXPECT_LT(node.axis, 3);
    const std::uint32_t first = index + 1, second = node.offset;
    EXPECT_LT(first, second);  // depth-first: the first child's subtree comes before the second
    EXPECT_LT(second, nodes.size());
    EXPECT_TRUE(box.contains(nodes[first].box.widen())) << "node " << first;
    EXPECT_TRUE(box.contains(nodes[second].box.widen())) << "node " << second;
    pending.emplace_back(second, depth + 1);
    pending.emplace_back(first, depth + 1);
  }
  EXPECT_EQ(walked, nodes.size());  // every node reached once: a tree
  for (std::uint32_t i = 0; i < scene.size(); ++i)
    EXPECT_EQ(seen[i], 1) << "shape " << i << " appears " << seen[i] << " times";
  EXPECT_EQ(bvh.depth(), deepest);
  EXPECT_LT(bvh.depth(), Bvh::STACK_SIZE);
  return leaves;
}

TEST(BvhBuildTests, invariants) {
  const Aabb box(Double3(-30), Double3(30));
  // ============ Equivalence Partitions Tests ==============
  // TC01: spheres only
  {
    test::Random random(1);
    Geometries scene;
    test::addSpheres(scene, random, 3000, box, 0.2, 3);
    const Bvh bvh(scene);
    const int leaves = expectValidTree(bvh, scene);
    EXPECT_EQ(bvh.nodes().size(), 2u * leaves - 1);  // a full binary tree
    EXPECT_GT(bvh.depth(), 10);                      // it does split
  }
  // TC02: every kind, copies, planes and tubes
  {
    test::Random random(2);
    Geometries scene;
    test::addMixedShapes(scene, random, 1000, box);
    test::addCopies(scene, random, 200);
    test::addUnbounded(scene, box);
    const Bvh bvh(scene);
    expectValidTree(bvh, scene);
    EXPECT_EQ(bvh.unboundedShapes().size(), 4u);
  }
}

TEST(BvhBuildTests, sahSeparatesClusters) {
  // TC01: 50 spheres around (-100,0,0), then 50 around (100,0,0): the root splits along x into
  // exactly the two clusters, the lower one first
  test::Random random(3);
  Geometries scene;
  test::addSpheres(scene, random, 50, Aabb(Double3(-105, -5, -5), Double3(-95, 5, 5)), 0.5, 1);
  test::addSpheres(scene, random, 50, Aabb(Double3(95, -5, -5), Double3(105, 5, 5)), 0.5, 1);
  const Bvh bvh(scene);
  expectValidTree(bvh, scene);
  const BvhNode& root = bvh.nodes()[0];
  ASSERT_FALSE(root.isLeaf());
  EXPECT_EQ(root.axis, 0);
  EXPECT_LT(bvh.nodes()[1].box.hi[0], -90);
  EXPECT_GT(bvh.nodes()[root.offset].box.lo[0], 90);
}

TEST(BvhBuildTests, degenerateScenes) {
  // =============== Boundary Values Tests ==================
  // TC11: an empty scene: no node
  const Geometries empty;
  const Bvh none(empty);
  EXPECT_TRUE(none.nodes().empty());
  EXPECT_EQ(none.depth(), 0);
  // TC12: one shape: one leaf, whose box is the shape's conservative box
  Geometries one;
  one.add(Sphere(Point(1, 2, 3), 0.5));
  const Bvh single(one);
  ASSERT_EQ(single.nodes().size(), 1u);
  EXPECT_TRUE(single.nodes()[0].isLeaf());
  EXPECT_EQ(single.nodes()[0].box.widen(), conservativeBox(*boundingBox(one[0])).widen());
  expectValidTree(single, one);
  // TC13: only unbounded shapes: no node, every shape outside the tree
  Geometries unbounded;
  test::addUnbounded(unbounded, Aabb(Double3(-1), Double3(1)));
  const Bvh outside(unbounded);
  EXPECT_TRUE(outside.nodes().empty());
  expectValidTree(outside, unbounded);
  // TC14: 1000 identical spheres (one centroid): split in halves down to leaves of at most
  // MAX_LEAF_SIZE
  Geometries same;
  for (int i = 0; i < 1000; ++i) same.add(Sphere(Point(1, 2, 3), 5));
  const Bvh halves(same);
  expectValidTree(halves, same);
  // TC15: a sphere and a triangle in one leaf's range: a leaf of each kind under one node
  Geometries mixed;
  mixed.add(Sphere(Point(0, 0, 0), 1), Triangle(Point(-1, -1, 0), Point(1, -1, 0), Point(0, 1, 0)));
  const Bvh kinds(mixed);
  ASSERT_EQ(kinds.nodes().size(), 3u);
  EXPECT_FALSE(kinds.nodes()[0].isLeaf());
  expectValidTree(kinds, mixed);
  // TC18: a sphere beyond the float range (x = 1e39) is kept outside the tree, like a plane
  Geometries far;
  far.add(Sphere(Point(0, 0, 0), 1), Sphere(Point(1e39, 0, 0), 1), Sphere(Point(5, 0, 0), 1));
  const Bvh beyond(far);
  ASSERT_EQ(beyond.unboundedShapes().size(), 1u);
  EXPECT_EQ(beyond.unboundedShapes()[0], 1u);
  expectValidTree(beyond, far);
  // TC16: spheres at x = 2^i, radius 2^(i-1) (each far from all the smaller ones): the SAH
  // peels off a few at a time, yet the depth stays far below the stack's size
  Geometries spread;
  for (int i = 0; i < 120; ++i)
    spread.add(Sphere(Point(std::ldexp(1.0, i), 0, 0), std::ldexp(0.5, i)));
  const Bvh deep(spread);
  expectValidTree(deep, spread);
  EXPECT_GT(deep.depth(), 30);
  // TC17: median splits from depth 0 and from depth 3 on: a balanced tree, ceil(log2(n/8))
  // levels for n = 3000 spheres in leaves of at most 8 (median halves: 3000 → … → 6 in 9 levels)
  test::Random random(4);
  Geometries many;
  test::addSpheres(many, random, 3000, Aabb(Double3(-30), Double3(30)), 0.2, 3);
  const Bvh median(many, BvhBuildOptions{0});
  expectValidTree(median, many);
  EXPECT_EQ(median.depth(), 9);
  const Bvh late(many, BvhBuildOptions{3});
  expectValidTree(late, many);
  EXPECT_GE(late.depth(), 3);
}

}  // namespace
}  // namespace rt
