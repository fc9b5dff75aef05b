// mini2: what the queries cost, counted in QueryCounts: the CBR skips the shapes whose box the
// ray misses or enters after the best hit, the BVH visits few nodes and tests few shapes (mesh
// triangles too); and neither query allocates.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "bvh/Bvh.h"
#include "bvh/Cbr.h"
#include "bvh/WideBvh.h"
#include "geometries/UtahTeapot.h"
#include "grid/Grid.h"
#include "support/AllocationCounter.h"

#include "RandomScenes.h"

namespace rt {
namespace {

/// Spheres S0 at the origin, S1 at (10,0,0), S2 at (0,10,0), radius 1; the plane y = -5.
Geometries threeSpheresAndAFloor() {
  Geometries g;
  g.add(Sphere(Point(0, 0, 0), 1), Sphere(Point(10, 0, 0), 1), Sphere(Point(0, 10, 0), 1),
        Plane(Point(0, -5, 0), Vector(0, 1, 0)));
  return g;
}

const Ray kAlongX(Point(-5, 0, 0), Vector(1, 0, 0));

TEST(QueryCountTests, cbr) {
  const Geometries scene = threeSpheresAndAFloor();
  const Cbr cbr(scene);
  // ============ Equivalence Partitions Tests ==============
  // TC01: closest hit along x: the three boxes are tested; the plane (no box) and S0 are tested;
  // S1's box is entered at t ≈ 14, after S0's hit at t = 4; S2's box is missed (2 tests; the
  // linear scan makes 4)
  QueryCounts counts;
  const auto hit = cbr.closestHit(kAlongX, INFINITE_DISTANCE, &counts);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->geometry, 0u);
  EXPECT_EQ(counts, (QueryCounts{2, 3}));
  QueryCounts linear;
  scene.closestHit(kAlongX, INFINITE_DISTANCE, &linear);
  EXPECT_EQ(linear.shapeTests, 4u);
  // TC02: every hit along x: S1's box is no longer skipped (3 tests)
  QueryCounts all;
  cbr.forEachHit(
      kAlongX, INFINITE_DISTANCE, [](const Hit&) { return true; }, &all);
  EXPECT_EQ(all, (QueryCounts{3, 3}));
  // =============== Boundary Values Tests ==================
  // TC11: tMax before S0's box: only the plane is tested
  QueryCounts shortRay;
  EXPECT_FALSE(cbr.closestHit(kAlongX, 3, &shortRay).has_value());
  EXPECT_EQ(shortRay, (QueryCounts{1, 3}));
  // TC12: counts add up over queries
  cbr.closestHit(kAlongX, 3, &shortRay);
  EXPECT_EQ(shortRay, (QueryCounts{2, 6}));
}

TEST(QueryCountTests, bvh) {
  // TC01: three spheres make one leaf (a split costs at least TRAVERSAL_COST = 3 tests, a leaf
  // of three 3): the closest hit along x visits that node and tests the plane and the three
  // spheres; all hits along x, the same
  const Geometries scene = threeSpheresAndAFloor();
  const Bvh bvh(scene);
  ASSERT_EQ(bvh.nodes().size(), 1u);
  QueryCounts counts;
  ASSERT_EQ(bvh.closestHit(kAlongX, INFINITE_DISTANCE, &counts)->geometry, 0u);
  EXPECT_EQ(counts, (QueryCounts{4, 1}));
  QueryCounts all;
  bvh.forEachHit(
      kAlongX, INFINITE_DISTANCE, [](const Hit&) { return true; }, &all);
  EXPECT_EQ(all, (QueryCounts{4, 1}));
  // TC11: a ray above the leaf's box: the box is tested, no sphere (only the plane)
  QueryCounts above;
  EXPECT_FALSE(bvh.closestHit(Ray(Point(-5, 20, 0), Vector(1, 0, 0)), INFINITE_DISTANCE, &above)
                   .has_value());
  EXPECT_EQ(above, (QueryCounts{1, 1}));
  // TC02: on 5000 random spheres, 1000 rays test under 2 % of the shapes the linear scan tests
  test::Random random(7);
  const Aabb box(Double3(-50), Double3(50));
  Geometries big;
  test::addSpheres(big, random, 5000, box, 0.2, 1);
  const Bvh tree(big);
  QueryCounts fast, slow;
  for (const test::Query& q : test::randomQueries(random, 1000, box)) {
    tree.closestHit(q.ray, q.tMax, &fast);
    big.closestHit(q.ray, q.tMax, &slow);
  }
  EXPECT_EQ(slow.shapeTests, 5000u * 1000u);
  EXPECT_LT(fast.shapeTests * 50, slow.shapeTests);
  EXPECT_GT(fast.nodesVisited, 1000u);
}

TEST(QueryCountTests, meshTriangles) {
  // The teapot at detail 8 (4032 triangles) on the plane z = 0, 1000 rays around it: each exact
  // test of a mesh triangle is counted as a shape's.
  Geometries scene;
  scene.add(Plane(Point(0, 0, 0), Vector(0, 0, 1)));
  scene.addMesh(std::make_shared<const TriangleMesh>(utahTeapot(8)));
  ASSERT_EQ(scene.primitiveCount(), 4033u);
  test::Random random(9);
  const std::vector<test::Query> queries =
      test::randomQueries(random, 1000, Aabb(Double3(-4, -3, 0), Double3(4, 3, 3.5)));
  const Cbr cbr(scene);
  const Bvh bvh(scene);
  const Grid grid(scene);
  QueryCounts linear, boxed, tree, cells;
  for (const test::Query& q : queries) {
    scene.closestHit(q.ray, q.tMax, &linear);
    cbr.closestHit(q.ray, q.tMax, &boxed);
    bvh.closestHit(q.ray, q.tMax, &tree);
    grid.closestHit(q.ray, q.tMax, &cells);
  }
  // ============ Equivalence Partitions Tests ==============
  // TC01: the linear scan tests every primitive, shape and triangle, for every ray
  EXPECT_EQ(linear, (QueryCounts{1000u * 4033u, 0}));
  // TC02: the CBR tests every triangle's box (the plane has none) and far fewer triangles
  EXPECT_EQ(boxed.nodesVisited, 1000u * 4032u);
  EXPECT_LT(boxed.shapeTests * 10, linear.shapeTests);
  // TC03: the BVH and the grid test under 2 % of the triangles the linear scan tests, visiting
  // nodes or cells
  EXPECT_LT(tree.shapeTests * 50, linear.shapeTests);
  EXPECT_GT(tree.nodesVisited, 1000u);
  EXPECT_LT(cells.shapeTests * 50, linear.shapeTests);
  EXPECT_GT(cells.nodesVisited, 1000u);
  // =============== Boundary Values Tests ==================
  // TC11: a ray above the teapot's box (z = 10): the BVH tests its root's box and only the plane
  QueryCounts above;
  EXPECT_FALSE(bvh.closestHit(Ray(Point(-10, 0, 10), Vector(1, 0, 0)), INFINITE_DISTANCE, &above)
                   .has_value());
  EXPECT_EQ(above, (QueryCounts{1, 1}));
}

TEST(QueryCountTests, noAllocationPerRay) {
  // TC01: closestHit and forEachHit of the CBR, the BVH, the wide BVH and the grid allocate
  // nothing, over shapes and mesh triangles (the counter works: one operator new counts one)
  EXPECT_EQ(1, testing::allocationsDuring([] { ::operator delete(::operator new(16)); }));
  test::Random random(8);
  const Aabb box(Double3(-30), Double3(30));
  Geometries scene;
  test::addMixedShapes(scene, random, 500, box);
  test::addUnbounded(scene, box);
  scene.addMesh(test::movedMesh(utahTeapot(6), Double3(0, 0, -1)));
  const Bvh bvh(scene);
  const WideBvh wide(scene);
  const Cbr cbr(scene);
  const Grid grid(scene);
  const std::vector<test::Query> queries = test::randomQueries(random, 500, box);
  double sink = 0;
  const long allocations = testing::allocationsDuring([&] {
    for (const test::Query& q : queries) {
      for (const Intersectable* s :
           {static_cast<const Intersectable*>(&bvh), static_cast<const Intersectable*>(&wide),
            static_cast<const Intersectable*>(&cbr), static_cast<const Intersectable*>(&grid)}) {
        if (const auto hit = s->closestHit(q.ray, q.tMax)) sink += hit->t;
        s->forEachHit(q.ray, q.tMax, [&sink](const Hit& h) {
          sink += h.t;
          return true;
        });
      }
    }
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(sink, 0);
}

}  // namespace
}  // namespace rt
