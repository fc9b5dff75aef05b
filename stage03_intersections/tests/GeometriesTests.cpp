// Stage 3: the Geometries composite (the course's partitions: empty, none, one, some, all;
// tomi832's data) and its queries: closestHit, forEachHit, findGeoIntersections.
#include <gtest/gtest.h>

#include <cstddef>
#include <optional>
#include <vector>

#include "intersections/Geometries.h"

#include "ExpectHits.h"

namespace rt {
namespace {

using test::hits;

const Triangle kTriangle(Point(-1, -1, 1), Point(1, -1, 1), Point(0, 1, 1));
const Sphere kSphere(Point(0, 0, 1), 1);
const Polygon kSquareA({Point(5, 5, 1), Point(5, 10, 1), Point(10, 10, 1), Point(10, 5, 1)});
const Polygon kSquareB({Point(1, 1, 1), Point(1, -1, 1), Point(-1, -1, 1), Point(-1, 1, 1)});
const Ray kDownAtOrigin(Point(0, 0, 5), Vector(0, 0, -1));

TEST(GeometriesTests, findIntersectionsPartitions) {
  const Geometries all{kTriangle, kSphere, kSquareA, kSquareB};
  // ============ Equivalence Partitions Tests ==============
  // TC01: some shapes but not all are hit: triangle at (0,0,1), sphere at (0,0,2),(0,0,0);
  // square A missed (3 points)
  const Geometries some{kTriangle, kSphere, kSquareA};
  EXPECT_TRUE(hits(some, kDownAtOrigin, {Point(0, 0, 2), Point(0, 0, 1), Point(0, 0, 0)}));
  // =============== Boundary Values Tests ==================
  // TC11: an empty collection (0 points)
  EXPECT_TRUE(hits(Geometries(), kDownAtOrigin, {}));
  // TC12: no shape is hit (0 points)
  EXPECT_TRUE(hits(all, Ray(Point(0, 0, 100), Vector(0, 0, 1)), {}));
  // TC13: exactly one shape is hit: square A at (7,7,1)
  EXPECT_TRUE(hits(all, Ray(Point(7, 7, 5), Vector(0, 0, -1)), {Point(7, 7, 1)}));
  // TC14: all shapes are hit: triangle and square B both at (0,0,1) (4 points)
  const Geometries allHit{kTriangle, kSphere, kSquareB};
  EXPECT_TRUE(hits(allHit, kDownAtOrigin,
                   {Point(0, 0, 2), Point(0, 0, 1), Point(0, 0, 1), Point(0, 0, 0)}));
}

TEST(GeometriesTests, findGeoIntersectionsNamesTheShapes) {
  const Geometries g{kTriangle, kSphere, kSquareA};
  // TC01: the hits sorted by distance, each with its shape's index and its t
  const std::vector<GeoPoint> found = g.findGeoIntersections(kDownAtOrigin);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].geometry, 1u);
  EXPECT_NEAR(found[0].t, 3, 1e-12);
  EXPECT_TRUE(test::near(found[0].point, Point(0, 0, 2)));
  EXPECT_EQ(found[1].geometry, 0u);
  EXPECT_NEAR(found[1].t, 4, 1e-12);
  EXPECT_EQ(found[2].geometry, 1u);
  EXPECT_NEAR(found[2].t, 5, 1e-12);
  // TC02: with a maximum distance between the hits
  const std::vector<GeoPoint> near = g.findGeoIntersections(kDownAtOrigin, 4.5);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_EQ(near[1].geometry, 0u);
}

TEST(GeometriesTests, maxDistance) {
  const Geometries g{kTriangle, kSphere, kSquareB};
  // Hits at t = 3 (sphere), 4 (triangle and square B), 5 (sphere).
  // TC01: before everything (0 points)
  EXPECT_TRUE(hits(g, kDownAtOrigin, {}, 2));
  // TC02: between the first and the second distance (1 point)
  EXPECT_TRUE(hits(g, kDownAtOrigin, {Point(0, 0, 2)}, 3.5));
  // TC11: exactly the second distance, shared by two shapes (inclusive: 3 points)
  EXPECT_TRUE(hits(g, kDownAtOrigin, {Point(0, 0, 2), Point(0, 0, 1), Point(0, 0, 1)}, 4));
  // TC12: exactly the first distance (inclusive: 1 point)
  EXPECT_TRUE(hits(g, kDownAtOrigin, {Point(0, 0, 2)}, 3));
}

TEST(GeometriesTests, closestHit) {
  const Geometries g{kSquareA, kTriangle, kSphere};
  // TC01: the nearest hit is the sphere's near point, whatever the order of the shapes
  const auto hit = g.closestHit(kDownAtOrigin);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 3, 1e-12);
  EXPECT_EQ(hit->geometry, 2u);
  // TC02: the sphere behind the ray's head only counts its far point: a ray starting inside the
  // sphere at (0,0,1.5) first meets the triangle (t = 0.5)
  const auto inside = g.closestHit(Ray(Point(0, 0, 1.5), Vector(0, 0, -1)));
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->t, 0.5, 1e-12);
  EXPECT_EQ(inside->geometry, 1u);
  // TC03: no hit
  EXPECT_FALSE(g.closestHit(Ray(Point(0, 0, 100), Vector(0, 0, 1))).has_value());
  // TC11: tMax just before the nearest hit: none; exactly at it: the hit
  EXPECT_FALSE(g.closestHit(kDownAtOrigin, 3 - 1e-9).has_value());
  ASSERT_TRUE(g.closestHit(kDownAtOrigin, 3).has_value());
  // TC12: an empty collection has no hit
  EXPECT_FALSE(Geometries().closestHit(kDownAtOrigin).has_value());
}

TEST(GeometriesTests, closestHitsOfSeveralRays) {
  const Geometries g{kSquareA, kTriangle, kSphere};
  const std::vector<Ray> rays{kDownAtOrigin, Ray(Point(0, 0, 1.5), Vector(0, 0, -1)),
                              Ray(Point(0, 0, 100), Vector(0, 0, 1)),
                              Ray(Point(7, 7, 5), Vector(0, 0, -1))};
  // ============ Equivalence Partitions Tests ==============
  // TC01: each ray's answer is its closestHit, the same bits: the sphere at t = 3, the triangle
  // at t = 0.5, none, square A at t = 4; the counts are those of the four queries (3 shapes each)
  std::vector<std::optional<Hit>> found(rays.size());
  QueryCounts counts;
  g.closestHits(rays, INFINITE_DISTANCE, found, &counts);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const std::optional<Hit> one = g.closestHit(rays[i]);
    ASSERT_EQ(one.has_value(), found[i].has_value()) << i;
    if (one) {
      EXPECT_TRUE(one->t == found[i]->t && one->geometry == found[i]->geometry) << i;
    }
  }
  ASSERT_TRUE(found[0] && found[1] && !found[2] && found[3]);
  EXPECT_NEAR(3, found[0]->t, 1e-12);
  EXPECT_EQ(2u, found[0]->geometry);
  EXPECT_NEAR(0.5, found[1]->t, 1e-12);
  EXPECT_EQ(1u, found[1]->geometry);
  EXPECT_NEAR(4, found[3]->t, 1e-12);
  EXPECT_EQ(0u, found[3]->geometry);
  EXPECT_EQ((QueryCounts{12, 0}), counts);
  // TC02: tMax applies to every ray: at 3.5 only the first two are hit
  g.closestHits(rays, 3.5, found);
  EXPECT_TRUE(found[0] && found[1] && !found[2] && !found[3]);
  // =============== Boundary Values Tests ==================
  // TC11: no ray: nothing written, nothing counted
  QueryCounts none;
  g.closestHits({}, INFINITE_DISTANCE, {}, &none);
  EXPECT_EQ(QueryCounts{}, none);
}

TEST(GeometriesTests, forEachHit) {
  const Geometries g{kTriangle, kSphere, kSquareB};
  // TC01: visits every hit within tMax and reports a complete walk
  std::vector<Hit> visited;
  EXPECT_TRUE(g.forEachHit(kDownAtOrigin, INFINITE_DISTANCE, [&](const Hit& h) {
    visited.push_back(h);
    return true;
  }));
  ASSERT_EQ(visited.size(), 4u);
  double sum = 0;
  for (const Hit& h : visited) sum += h.t;
  EXPECT_NEAR(sum, 3 + 4 + 4 + 5, 1e-12);
  // TC02: a visitor that stops at the first hit: one visit, the walk reports it stopped
  int calls = 0;
  EXPECT_FALSE(g.forEachHit(kDownAtOrigin, INFINITE_DISTANCE, [&](const Hit&) {
    ++calls;
    return false;
  }));
  EXPECT_EQ(calls, 1);
  // TC03: tMax limits the hits visited (t = 3 and the two at t = 4)
  visited.clear();
  EXPECT_TRUE(g.forEachHit(kDownAtOrigin, 4, [&](const Hit& h) {
    visited.push_back(h);
    return true;
  }));
  EXPECT_EQ(visited.size(), 3u);
  // TC11: no hit: the visitor is never called, the walk is complete
  calls = 0;
  EXPECT_TRUE(
      g.forEachHit(Ray(Point(0, 0, 100), Vector(0, 0, 1)), INFINITE_DISTANCE, [&](const Hit&) {
        ++calls;
        return true;
      }));
  EXPECT_EQ(calls, 0);
}

TEST(GeometriesTests, closestHitTiesGoToTheSmallestIndex) {
  // The rule every Intersectable follows, so that an acceleration structure visiting the shapes
  // in another order returns the same hit: the smallest (t, geometry) pair wins.
  // ============ Equivalence Partitions Tests ==============
  // TC01: from below, the sphere's near point (0,0,0) at t = 5 comes before the flat shapes at
  // (0,0,1), t = 6: the sphere wins
  const Geometries g{kTriangle, kSphere, kSquareB};
  const Ray fromBelow(Point(0, 0, -5), Vector(0, 0, 1));
  ASSERT_TRUE(g.closestHit(fromBelow).has_value());
  EXPECT_EQ(1u, g.closestHit(fromBelow)->geometry);
  // TC02: without the sphere, the two flat shapes tie at t = 6: the smaller index wins, in
  // either order of addition
  const Geometries flat{kTriangle, kSquareB};
  ASSERT_TRUE(flat.closestHit(fromBelow).has_value());
  EXPECT_EQ(0u, flat.closestHit(fromBelow)->geometry);
  EXPECT_EQ(6.0, flat.closestHit(fromBelow)->t);
  const Geometries reversed{kSquareB, kTriangle};
  EXPECT_EQ(0u, reversed.closestHit(fromBelow)->geometry);
  // =============== Boundary Values Tests ==================
  // TC11: a tie exactly at an inclusive tMax still goes to the smaller index
  EXPECT_EQ(0u, flat.closestHit(fromBelow, 6)->geometry);
}

TEST(GeometriesTests, queryCounts) {
  const Geometries g{kTriangle, kSphere, kSquareB};
  // ============ Equivalence Partitions Tests ==============
  // TC01: a closest-hit query tests every shape once, and visits no hierarchy node
  QueryCounts counts;
  (void)g.closestHit(kDownAtOrigin, INFINITE_DISTANCE, &counts);
  EXPECT_EQ((QueryCounts{3, 0}), counts);
  // TC02: counts add up over queries
  (void)g.closestHit(Ray(Point(0, 0, 100), Vector(0, 0, 1)), INFINITE_DISTANCE, &counts);
  EXPECT_EQ((QueryCounts{6, 0}), counts);
  // TC03: a walk stopped at the first hit (the triangle, shape 0) tested one shape
  QueryCounts walk;
  g.forEachHit(
      kDownAtOrigin, INFINITE_DISTANCE, [](const Hit&) { return false; }, &walk);
  EXPECT_EQ(1u, walk.shapeTests);
  // =============== Boundary Values Tests ==================
  // TC11: no counts given: nothing to add to, nothing breaks
  EXPECT_TRUE(g.closestHit(kDownAtOrigin).has_value());
  // TC12: an empty collection tests nothing
  QueryCounts none;
  (void)Geometries().closestHit(kDownAtOrigin, INFINITE_DISTANCE, &none);
  EXPECT_EQ(QueryCounts{}, none);
}

TEST(GeometriesTests, addAndAccess) {
  // TC01: add returns each shape's index; size, empty and indexing follow
  Geometries g;
  EXPECT_TRUE(g.empty());
  EXPECT_EQ(g.add(kSphere), 0u);
  EXPECT_EQ(g.add(kTriangle), 1u);
  EXPECT_EQ(g.size(), 2u);
  EXPECT_FALSE(g.empty());
  EXPECT_TRUE(std::holds_alternative<Triangle>(g[1]));
  // TC02: the variadic add appends several shapes in order
  g.add(kSquareA, kSquareB, Plane(Point(0, 0, -10), Vector(0, 0, 1)));
  EXPECT_EQ(g.size(), 5u);
  EXPECT_EQ(g.shapes().size(), 5u);
  EXPECT_TRUE(std::holds_alternative<Plane>(g[4]));
  // TC03: the added plane is intersected (its hit is the farthest)
  const std::vector<Point> points = g.findIntersections(kDownAtOrigin);
  ASSERT_EQ(points.size(), 5u);
  EXPECT_TRUE(test::near(points.back(), Point(0, 0, -10)));
}

TEST(GeometriesTests, geometryVariantDispatch) {
  // TC01: the free queries work on the variant for every kind of shape
  const Ray ray(Point(0.25, 0.25, 5), Vector(0, 0, -1));
  const Ray zAxis(Point(0, 0, 0), Vector(0, 0, 1));
  EXPECT_TRUE(hits(Geometry(Sphere(Point(0.25, 0.25, 0), 1)), ray,
                   {Point(0.25, 0.25, 1), Point(0.25, 0.25, -1)}));
  EXPECT_TRUE(hits(Geometry(Plane(Point(0, 0, 0), Vector(0, 0, 1))), ray, {Point(0.25, 0.25, 0)}));
  EXPECT_TRUE(hits(Geometry(Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0))), ray,
                   {Point(0.25, 0.25, 0)}));
  EXPECT_TRUE(
      hits(Geometry(Polygon({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)})), ray,
           {Point(0.25, 0.25, 0)}));
  EXPECT_TRUE(hits(Geometry(Tube(1, zAxis)), Ray(Point(-2, 0, 1), Vector(1, 0, 0)),
                   {Point(-1, 0, 1), Point(1, 0, 1)}));
  EXPECT_TRUE(
      hits(Geometry(Cylinder(1, zAxis, 2)), ray, {Point(0.25, 0.25, 2), Point(0.25, 0.25, 0)}));
}

}  // namespace
}  // namespace rt
