// mini2: the BVH built on several threads is the tree built on one, node for node: the same
// nodes (boxes, offsets, counts, axes, kinds), the same primitives in every leaf, the same
// unbounded list and depth. The scenes are large enough for the parallel top phase to make many
// tasks (a mesh of tens of thousands of triangles, with spheres, polygons and planes mixed in),
// and small ones that stay below its threshold.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

#include "bvh/Bvh.h"
#include "geometries/UtahTeapot.h"

#include "RandomScenes.h"

namespace rt {
namespace {

/// The tree of geometries built on `threads` threads.
Bvh buildOn(const Geometries& geometries, int threads,
            int sahMaxDepth = BvhBuildOptions{}.sahMaxDepth) {
  BvhBuildOptions options;
  options.threads = threads;
  options.sahMaxDepth = sahMaxDepth;
  return Bvh(geometries, options);
}

/// Every node's bytes, every leaf's primitives, the compact spheres' bytes, the unbounded list and
/// the depth agree.
void expectSameTree(const Bvh& a, const Bvh& b) {
  ASSERT_EQ(a.nodes().size(), b.nodes().size());
  for (std::size_t i = 0; i < a.nodes().size(); ++i) {
    ASSERT_EQ(0, std::memcmp(&a.nodes()[i], &b.nodes()[i], sizeof(BvhNode))) << "node " << i;
    if (!a.nodes()[i].isLeaf()) continue;
    const auto pa = a.leafShapes(a.nodes()[i]), pb = b.leafShapes(b.nodes()[i]);
    ASSERT_TRUE(std::equal(pa.begin(), pa.end(), pb.begin(), pb.end())) << "leaf " << i;
  }
  const auto sa = a.compactSpheres(), sb = b.compactSpheres();
  ASSERT_EQ(sa.size(), sb.size());
  for (std::size_t i = 0; i < sa.size(); ++i)  // (an empty span's data() may be null)
    ASSERT_EQ(0, std::memcmp(&sa[i], &sb[i], sizeof(sa[i]))) << "compact sphere " << i;
  const auto ua = a.unboundedShapes(), ub = b.unboundedShapes();
  EXPECT_TRUE(std::equal(ua.begin(), ua.end(), ub.begin(), ub.end()));
  EXPECT_EQ(a.depth(), b.depth());
  EXPECT_EQ(a.memoryBytes(), b.memoryBytes());
}

/// The teapot at detail 16 (16,256 triangles), 3,000 spheres and 500 other shapes around it, and
/// two planes.
Geometries largeMixedScene() {
  Geometries g;
  test::Random random(15);
  const Aabb box(Double3(-4, -4, -1), Double3(4, 4, 4));
  test::addSpheres(g, random, 3000, box, 0.01, 0.2);
  test::addMixedShapes(g, random, 500, box);
  test::addUnbounded(g, box);
  g.addMesh(std::make_shared<const TriangleMesh>(utahTeapot(16)));
  return g;
}

// TC01: a large mixed scene, on 2, 3 and 8 threads (more threads than cores is allowed).
TEST(BvhParallelBuildTests, largeSceneSameTreeOnAnyThreads) {
  const Geometries g = largeMixedScene();
  ASSERT_EQ(g.triangleCount(), 64u * 16 * 16 - 8 * 16);
  const Bvh one = buildOn(g, 1);
  for (int threads : {2, 3, 8}) {
    SCOPED_TRACE(threads);
    expectSameTree(one, buildOn(g, threads));
  }
}

// TC02: the same with median splits from depth 2 on (the top phase then splits by the median).
TEST(BvhParallelBuildTests, medianSplitsSameTreeOnAnyThreads) {
  const Geometries g = largeMixedScene();
  expectSameTree(buildOn(g, 1, 2), buildOn(g, 2, 2));
}

// TC11: a scene below the parallel threshold is built on the calling thread alone, the same.
TEST(BvhParallelBuildTests, smallSceneSameTree) {
  Geometries g;
  test::Random random(16);
  test::addSpheres(g, random, 200, Aabb(Double3(-1), Double3(1)), 0.01, 0.1);
  expectSameTree(buildOn(g, 1), buildOn(g, 2));
}

// TC13: a scene large enough for the boxes and the compact spheres to be made in chunks, one
// per thread (16,384 primitives per thread at least), with unbounded shapes in every chunk:
// the same tree and compact spheres, the unbounded shapes in the scene's order, and the same
// closest hit (t and index) for every query.
TEST(BvhParallelBuildTests, chunkedRecordsAndSpheresSameTree) {
  Geometries g;
  test::Random random(17);
  const Aabb box(Double3(-8, -8, -8), Double3(8, 8, 8));
  std::vector<std::uint32_t> unbounded;
  for (int part = 0; part < 3; ++part) {
    test::addSpheres(g, random, 20000, box, 0.005, 0.05);
    test::addMixedShapes(g, random, 300, box);
    const auto first = static_cast<std::uint32_t>(g.size());
    test::addUnbounded(g, box);
    for (auto i = first; i < g.size(); ++i) unbounded.push_back(i);
  }
  ASSERT_EQ(unbounded.size(), 12u);
  ASSERT_EQ(g.size(), 60912u);
  const Bvh one = buildOn(g, 1);
  const auto u = one.unboundedShapes();
  EXPECT_TRUE(std::equal(u.begin(), u.end(), unbounded.begin(), unbounded.end()));
  const std::vector<test::Query> queries = test::randomQueries(random, 3000, box);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    const Bvh many = buildOn(g, threads);
    expectSameTree(one, many);
    int hits = 0;
    for (const test::Query& q : queries) {
      const std::optional<Hit> a = one.closestHit(q.ray, q.tMax),
                               b = many.closestHit(q.ray, q.tMax);
      ASSERT_EQ(a.has_value(), b.has_value());
      if (!a) continue;
      ++hits;
      EXPECT_EQ(a->t, b->t);
      EXPECT_EQ(a->geometry, b->geometry);
    }
    EXPECT_GT(hits, 1500);
  }
}

// TC12: only a mesh (no spheres: every leaf of the "other shapes" kind).
TEST(BvhParallelBuildTests, meshOnlySameTree) {
  Geometries g;
  g.addMesh(std::make_shared<const TriangleMesh>(utahTeapot(24)));
  expectSameTree(buildOn(g, 1), buildOn(g, 2));
}

}  // namespace
}  // namespace rt
