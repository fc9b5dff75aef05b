// mini2: the CBR, the BVH, the wide BVH and the grid answer exactly as the linear Geometries over
// the same shapes: closestHit returns the same t (compared with ==) and the same index, forEachHit
// visits the same multiset of (t, index) hits and stops when told. Random scenes and rays with
// fixed seeds; each query is also repeated with tMax exactly at its closest hit (the inclusive
// bound) and relaunched from that hit point. Triangle meshes' triangles are primitives like the
// shapes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "bvh/Bvh.h"
#include "bvh/Cbr.h"
#include "bvh/WideBvh.h"
#include "geometries/UtahTeapot.h"
#include "grid/Grid.h"

#include "RandomScenes.h"

namespace rt {
namespace {

using test::Query;
using test::Random;

using HitList = std::vector<std::pair<double, std::uint32_t>>;

/// Every hit forEachHit visits, sorted, so that two walks in different orders compare equal.
HitList allHits(const Intersectable& shapes, const Ray& ray, double tMax) {
  HitList hits;
  shapes.forEachHit(ray, tMax, [&hits](const Hit& h) {
    hits.emplace_back(h.t, h.geometry);
    return true;
  });
  std::sort(hits.begin(), hits.end());
  return hits;
}

std::string describe(const std::optional<Hit>& hit) {
  std::ostringstream os;
  os.precision(17);
  if (hit)
    os << "t = " << hit->t << " shape " << hit->geometry;
  else
    os << "no hit";
  return os.str();
}

/// One query on `fast` against the linear scan. stopAfter: the visitor of the stop check
/// returns false at its stopAfter-th call.
::testing::AssertionResult sameAnswers(const Geometries& linear, const Intersectable& fast,
                                       const Ray& ray, double tMax, std::uint32_t stopAfter) {
  const std::optional<Hit> expected = linear.closestHit(ray, tMax);
  const std::optional<Hit> got = fast.closestHit(ray, tMax);
  const bool same = expected.has_value() == got.has_value() &&
                    (!expected || (expected->t == got->t && expected->geometry == got->geometry));
  if (!same) {
    return ::testing::AssertionFailure()
           << "closestHit: expected " << describe(expected) << ", got " << describe(got) << " for "
           << ray << " tMax " << tMax;
  }
  const HitList expectedHits = allHits(linear, ray, tMax);
  if (allHits(fast, ray, tMax) != expectedHits)
    return ::testing::AssertionFailure() << "forEachHit: other hits for " << ray;
  std::uint32_t calls = 0;
  const bool complete = fast.forEachHit(ray, tMax, [&](const Hit&) { return ++calls < stopAfter; });
  const auto total = static_cast<std::uint32_t>(expectedHits.size());
  if (calls != std::min(stopAfter, total) || complete != (stopAfter > total)) {
    return ::testing::AssertionFailure() << "forEachHit: told to stop at hit " << stopAfter
                                         << " of " << total << ", made " << calls << " calls";
  }
  return ::testing::AssertionSuccess();
}

/// Every query, with its two derived queries, on the CBR, the BVH, the wide BVH and the grid of
/// the scene.
/// Reports the first few differences and returns how many queries were checked.
int expectEquivalent(const Geometries& scene, const std::vector<Query>& queries, Random& random) {
  const Cbr cbr(scene);
  const Bvh bvh(scene);
  const WideBvh wide(scene);
  const Grid grid(scene);
  int checked = 0, failures = 0;
  auto check = [&](const Ray& ray, double tMax) {
    const auto stopAfter = static_cast<std::uint32_t>(random.integer(1, 4));
    for (const Intersectable* fast :
         {static_cast<const Intersectable*>(&cbr), static_cast<const Intersectable*>(&bvh),
          static_cast<const Intersectable*>(&wide), static_cast<const Intersectable*>(&grid)}) {
      const ::testing::AssertionResult result = sameAnswers(scene, *fast, ray, tMax, stopAfter);
      if (!result && ++failures <= 5)
        ADD_FAILURE() << (fast == &bvh    ? "Bvh "
                          : fast == &wide ? "WideBvh "
                          : fast == &grid ? "Grid "
                                          : "Cbr ")
                      << result.message();
    }
    ++checked;
  };
  for (const Query& q : queries) {
    check(q.ray, q.tMax);
    if (const std::optional<Hit> hit = scene.closestHit(q.ray, q.tMax)) {
      check(q.ray, hit->t);                                        // tMax exactly at the hit
      check(Ray(q.ray.point(hit->t), q.ray.direction()), q.tMax);  // relaunched from the hit
    }
  }
  EXPECT_EQ(failures, 0) << "of " << checked << " queries";
  return checked;
}

const Aabb kBox(Double3(-30, -30, -30), Double3(30, 30, 30));

TEST(EquivalenceTests, randomScenes) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: spheres only (2000), rays of every kind
  {
    Random random(101);
    Geometries scene;
    test::addSpheres(scene, random, 2000, kBox, 0.2, 3);
    EXPECT_GT(expectEquivalent(scene, test::randomQueries(random, 2000, kBox), random), 3000);
  }
  // TC02: every bounded kind mixed (1500 shapes: spheres, triangles, flat and tilted
  // rectangles, cylinders)
  {
    Random random(202);
    Geometries scene;
    test::addMixedShapes(scene, random, 1500, kBox);
    expectEquivalent(scene, test::randomQueries(random, 2000, kBox), random);
  }
  // TC03: copies of shapes: exact ties between two indices, which the smaller must win
  {
    Random random(303);
    Geometries scene;
    test::addMixedShapes(scene, random, 600, kBox);
    test::addSpheres(scene, random, 300, kBox, 0.5, 4);
    test::addCopies(scene, random, 600);
    expectEquivalent(scene, test::randomQueries(random, 2000, kBox), random);
  }
  // TC04: planes and tubes (outside the tree) among the bounded shapes
  {
    Random random(404);
    Geometries scene;
    test::addMixedShapes(scene, random, 800, kBox);
    test::addUnbounded(scene, kBox);
    test::addCopies(scene, random, 100);
    expectEquivalent(scene, test::randomQueries(random, 2000, kBox), random);
  }
  // TC05: a dense scene (spheres overlapping a lot, many hits per ray)
  {
    Random random(505);
    Geometries scene;
    test::addSpheres(scene, random, 1000, Aabb(Double3(-5), Double3(5)), 0.5, 2);
    expectEquivalent(scene, test::randomQueries(random, 1000, Aabb(Double3(-5), Double3(5))),
                     random);
  }
  // TC06: overlapping coplanar rectangles: exact ties between shapes of different boxes, whose
  // boxes are entered exactly where they are hit
  {
    Random random(606);
    Geometries scene;
    test::addCoplanarRectangles(scene, random, 400);
    const Aabb box(Double3(-13), Double3(13));
    expectEquivalent(scene, test::randomQueries(random, 2000, box), random);
  }
  // TC07: triangle meshes among shapes: the teapot at detail 8 (4032 triangles) standing on a
  // plane in its bottom's plane (exact ties), spheres around it, shapes added after the mesh
  // (copies of its triangles as Triangle shapes: ties between a shape and a mesh triangle, the
  // mesh's triangles numbered after them), and a second teapot at detail 3 beside it
  {
    Random random(808);
    const auto teapot = std::make_shared<const TriangleMesh>(utahTeapot(8));
    const Aabb box(Double3(-6, -6, -2), Double3(10, 6, 6));
    Geometries scene;
    test::addSpheres(scene, random, 150, box, 0.2, 1.5);
    scene.add(Plane(Point(0, 0, 0), Vector(0, 0, 1)));
    scene.addMesh(teapot);
    test::addTriangleCopies(scene, random, *teapot, 100);
    scene.addMesh(test::movedMesh(utahTeapot(3), Double3(6, 1, 0.5)));
    ASSERT_EQ(scene.primitiveCount(), 150u + 1 + 100 + 4032 + utahTeapotTriangleCount(3));
    expectEquivalent(scene, test::randomQueries(random, 600, box), random);
  }
}

TEST(EquivalenceTests, boundaryScenes) {
  Random random(707);
  const std::vector<Query> queries = test::randomQueries(random, 500, kBox);
  // =============== Boundary Values Tests ==================
  // TC11: an empty scene (no hit, no tree): the 500 queries are checked as they are, none with
  // the two queries derived from a hit (which the linear scan of nothing never finds)
  EXPECT_EQ(500, expectEquivalent(Geometries(), queries, random));
  // TC12: one shape of each bounded kind alone (a tree of one leaf)
  {
    Geometries kinds;
    test::addMixedShapes(kinds, random, 5, kBox);
    for (const Geometry& shape : kinds.shapes()) {
      Geometries one;
      one.add(Geometry(shape));
      expectEquivalent(one, queries, random);
    }
  }
  // TC13: only unbounded shapes (no tree at all)
  {
    Geometries unbounded;
    test::addUnbounded(unbounded, kBox);
    expectEquivalent(unbounded, queries, random);
  }
  // TC14: 500 copies of one sphere: every centroid the same, exact ties everywhere
  {
    Geometries same;
    for (int i = 0; i < 500; ++i) same.add(Sphere(Point(1, 2, 3), 5));
    expectEquivalent(same, queries, random);
  }
  // TC15: two shapes (the smallest tree that splits)
  {
    Geometries two;
    two.add(Sphere(Point(-10, 0, 0), 3), Sphere(Point(10, 0, 0), 3));
    expectEquivalent(two, queries, random);
  }
  // TC16: a mesh of one triangle and nothing else (a tree of one leaf of one triangle)
  {
    Geometries one;
    one.addMesh(std::make_shared<const TriangleMesh>(
        std::vector<Point>{Point(-20, -20, 0), Point(20, -20, 5), Point(0, 20, -5)},
        std::vector<TriangleMesh::Indices>{{0, 1, 2}}));
    expectEquivalent(one, queries, random);
  }
  // TC17: only mesh triangles, no shape: the teapot scaled up to the box
  {
    const TriangleMesh small = utahTeapot(4);
    std::vector<Point> vertices;
    for (const Point& v : small.vertices()) vertices.emplace_back(v.xyz() * 8);
    Geometries only;
    only.addMesh(std::make_shared<const TriangleMesh>(std::move(vertices), small.triangles()));
    expectEquivalent(only, queries, random);
  }
}

}  // namespace
}  // namespace rt
