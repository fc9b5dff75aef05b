// Stage 3, beyond the course: triangle meshes as primitives. A mesh triangle's hits are those of
// a `Triangle` of the same corners, bit for bit, alone and inside Geometries (closestHit,
// forEachHit, findGeoIntersections, the counts), ties and shared edges included; the numbering
// of primitives (shapes first, then the meshes' triangles, shapes added after a mesh moving its
// triangles up), Primitives::meshTriangle, partOf, the normals, and addMesh's refusals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geometries/UtahTeapot.h"
#include "intersections/Geometries.h"
#include "intersections/Intersect.h"
#include "intersections/Primitives.h"
#include "support/SameBits.h"
#include "support/TestRandom.h"

namespace rt {
namespace {

using test::sameBits;
using ::testing::ThrowsMessage;
using Indices = TriangleMesh::Indices;

/// True when a and b are the same doubles, component by component.
/// Uniform numbers, points and directions: stream (x, y) of seed 15 (support/TestRandom.h).
class Draw : public test::TestRandom {
 public:
  Draw(std::uint32_t x, std::uint32_t y) : TestRandom(15, x, y) {}
};

/// 60 triangles over 24 random vertices in the box [-2, 2]^3, some of them of zero area (a
/// repeated index), which the mesh drops.
std::shared_ptr<const TriangleMesh> randomMesh() {
  Draw draw(0, 1);
  std::vector<Point> vertices;
  for (int i = 0; i < 24; ++i) vertices.emplace_back(draw.inBox(Double3(-2), Double3(2)));
  std::vector<Indices> triangles;
  for (int t = 0; t < 60; ++t) {
    auto index = [&] { return static_cast<std::uint32_t>(draw.uniform(0, 24)); };
    triangles.push_back({index(), index(), index()});
  }
  return std::make_shared<const TriangleMesh>(std::move(vertices), std::move(triangles));
}

/// Triangle t of mesh as a course shape.
Triangle triangleOf(const TriangleMesh& mesh, std::size_t t) {
  const std::array<Point, 3> c = mesh.corners(t);
  return Triangle(c[0], c[1], c[2]);
}

std::string rootsText(const Roots& roots) {
  std::ostringstream os;
  os.precision(17);
  os << "{";
  for (double t : roots) os << " " << t;
  os << " }";
  return os.str();
}

::testing::AssertionResult sameRoots(const Roots& mesh, const Roots& shape) {
  bool same = mesh.size() == shape.size();
  for (int i = 0; same && i < mesh.size(); ++i) same = mesh[i] == shape[i];
  if (same) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "mesh triangle " << rootsText(mesh) << ", Triangle " << rootsText(shape);
}

/// For every triangle of mesh, rays aimed at points around it (its barycentric coordinates
/// drawn from [-0.25, 1.25], so that many miss just outside an edge), rays from its corners
/// and from points on its plane, and rays in any direction: the roots equal a Triangle's.
/// Returns how many rays hit.
std::size_t expectSameRootsAsTriangles(const TriangleMesh& mesh, std::uint32_t seed,
                                       int raysPerTriangle) {
  std::size_t hits = 0;
  int failures = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Triangle shape = triangleOf(mesh, t);
    const std::array<Point, 3> c = mesh.corners(t);
    Draw draw(seed, static_cast<std::uint32_t>(t));
    for (int k = 0; k < raysPerTriangle; ++k) {
      const double b1 = draw.uniform(-0.25, 1.25), b2 = draw.uniform(-0.25, 1.25);
      const Double3 target = c[0].xyz() * (1 - b1 - b2) + c[1].xyz() * b1 + c[2].xyz() * b2;
      const Double3 away = draw.direction();
      Double3 origin = target + away * draw.uniform(0.5, 10);
      Double3 direction = target - origin;
      switch (k % 4) {
        case 1:  // from a corner, in any direction
          origin = c[k % 3].xyz();
          direction = draw.direction();
          break;
        case 2:  // from a point of the triangle's plane, towards the aimed point's neighbourhood
          origin = target;
          direction = draw.direction();
          break;
        default:
          break;
      }
      const Ray ray{Point(origin), Vector(direction)};
      const Roots roots = intersectRoots(mesh, t, ray);
      const ::testing::AssertionResult same = sameRoots(roots, intersectRoots(shape, ray));
      if (!same && ++failures <= 5)
        ADD_FAILURE() << "triangle " << t << ", " << ray << ": " << same.message();
      hits += roots.empty() ? 0 : 1;
    }
  }
  EXPECT_EQ(failures, 0);
  return hits;
}

TEST(MeshIntersectionTests, rootsEqualTheTrianglesBitForBit) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: random triangles in general position (zero-area ones dropped by the mesh), 400 rays
  // each: the same roots, and a good part of the rays hit
  const std::shared_ptr<const TriangleMesh> random = randomMesh();
  ASSERT_GT(random->droppedTriangles(), 0u);
  ASSERT_GT(random->triangleCount(), 40u);
  // (about a tenth of the rays hit: more than a twentieth is asked)
  EXPECT_GT(expectSameRootsAsTriangles(*random, 1, 400), random->triangleCount() * 400 / 20);
  // TC02: the teapot's 992 triangles (shared vertices, small and thin triangles near the poles,
  // axis-aligned bottom), 40 rays each
  const TriangleMesh teapot = utahTeapot(4);
  EXPECT_GT(expectSameRootsAsTriangles(teapot, 2, 40), 992 * 40 / 20);
  // =============== Boundary Values Tests ==================
  // TC11: a ray in the triangle's plane and a ray parallel to it: no root, as for a Triangle
  const TriangleMesh square({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)},
                            {{0, 1, 2}, {0, 2, 3}});
  for (const Ray& ray :
       {Ray(Point(-1, 0.25, 0), Vector(1, 0, 0)), Ray(Point(-1, 0.25, 1), Vector(1, 0, 0))}) {
    EXPECT_TRUE(intersectRoots(square, 0, ray).empty()) << ray;
    EXPECT_TRUE(
        sameRoots(intersectRoots(square, 0, ray), intersectRoots(triangleOf(square, 0), ray)));
  }
  // TC12: a ray starting on the triangle does not hit it there (t = 0 is not a root)
  const Ray fromInside(Point(0.75, 0.25, 0), Vector(0, 0, 1));
  EXPECT_TRUE(intersectRoots(square, 0, fromInside).empty());
  // TC13: the root is exact where it can be: from (0.75, 0.25, 5) straight down, t = 5
  const Roots down = intersectRoots(square, 0, Ray(Point(0.75, 0.25, 5), Vector(0, 0, -1)));
  ASSERT_EQ(down.size(), 1);
  EXPECT_EQ(down[0], 5.0);
}

/// The shapes of the equivalence scenes (around the teapot: z up, 0 <= z <= 3.15): a sphere
/// inside the teapot, the floor it stands on (its bottom triangles lie in that plane: exact ties),
/// a wall, and a triangle that is the teapot's triangle 500 (a tie between a shape and a mesh
/// triangle).
std::vector<Geometry> shapesAround(const TriangleMesh& teapot) {
  return {Sphere(Point(0, 0, 1.5), 1), Plane(Point(0, 0, 0), Vector(0, 0, 1)),
          Polygon({Point(-5, 3, -1), Point(5, 3, -1), Point(5, 3, 4), Point(-5, 3, 4)}),
          triangleOf(teapot, 500)};
}

using HitList = std::vector<std::pair<double, std::uint32_t>>;

/// Every hit forEachHit visits, in the order visited.
HitList visited(const Geometries& g, const Ray& ray, double tMax, QueryCounts* counts = nullptr) {
  HitList hits;
  g.forEachHit(
      ray, tMax,
      [&hits](const Hit& h) {
        hits.emplace_back(h.t, h.geometry);
        return true;
      },
      counts);
  return hits;
}

/// Every query of meshes and shapes on the ray: closestHit (the same t bits and number),
/// forEachHit (the same hits in the same order, the same counts, and the same stop after
/// stopAfter hits), findGeoIntersections (the same points' bits).
::testing::AssertionResult sameAnswers(const Geometries& meshes, const Geometries& shapes,
                                       const Ray& ray, double tMax, std::uint32_t stopAfter) {
  QueryCounts meshCounts, shapeCounts;
  const std::optional<Hit> a = meshes.closestHit(ray, tMax, &meshCounts);
  const std::optional<Hit> b = shapes.closestHit(ray, tMax, &shapeCounts);
  if (a.has_value() != b.has_value() || (a && (a->t != b->t || a->geometry != b->geometry)))
    return ::testing::AssertionFailure() << "closestHit differs for " << ray << " tMax " << tMax;
  if (visited(meshes, ray, tMax, &meshCounts) != visited(shapes, ray, tMax, &shapeCounts))
    return ::testing::AssertionFailure() << "forEachHit differs for " << ray;
  std::uint32_t meshCalls = 0, shapeCalls = 0;
  const bool meshComplete = meshes.forEachHit(
      ray, tMax, [&](const Hit&) { return ++meshCalls < stopAfter; }, &meshCounts);
  const bool shapeComplete = shapes.forEachHit(
      ray, tMax, [&](const Hit&) { return ++shapeCalls < stopAfter; }, &shapeCounts);
  if (meshCalls != shapeCalls || meshComplete != shapeComplete)
    return ::testing::AssertionFailure() << "forEachHit stops differently for " << ray;
  if (meshCounts != shapeCounts)
    return ::testing::AssertionFailure()
           << "counts differ for " << ray << ": " << meshCounts.shapeTests << " against "
           << shapeCounts.shapeTests;
  const std::vector<GeoPoint> pa = meshes.findGeoIntersections(ray, tMax);
  const std::vector<GeoPoint> pb = shapes.findGeoIntersections(ray, tMax);
  bool same = pa.size() == pb.size();
  for (std::size_t i = 0; same && i < pa.size(); ++i)
    same = pa[i].geometry == pb[i].geometry && pa[i].t == pb[i].t &&
           sameBits(pa[i].point.xyz(), pb[i].point.xyz());
  if (!same) return ::testing::AssertionFailure() << "findGeoIntersections differs for " << ray;
  return ::testing::AssertionSuccess();
}

TEST(MeshIntersectionTests, geometriesWithMeshesAnswerAsWithTriangleShapes) {
  // The scene with meshes: four shapes, the teapot, a sphere added after it, then a random mesh.
  // The same scene of shapes: the five shapes, then every triangle of the two meshes as a
  // Triangle, in order; so primitive p of the first is shape p of the second.
  const auto teapot = std::make_shared<const TriangleMesh>(utahTeapot(4));
  const std::shared_ptr<const TriangleMesh> random = randomMesh();
  const Sphere after(Point(2.5, -1, 2), 0.75);
  Geometries meshes, shapes;
  for (const Geometry& s : shapesAround(*teapot)) {
    meshes.add(s);
    shapes.add(s);
  }
  EXPECT_EQ(meshes.addMesh(teapot), 0u);
  meshes.add(after);
  EXPECT_EQ(meshes.addMesh(random), 1u);
  shapes.add(after);
  for (const auto& mesh : {teapot, random})
    for (std::size_t t = 0; t < mesh->triangleCount(); ++t) shapes.add(triangleOf(*mesh, t));
  ASSERT_EQ(meshes.primitiveCount(), shapes.size());
  ASSERT_EQ(meshes.size(), 5u);

  const Double3 lo(-4, -3, -1), hi(4, 3, 4), centre = (lo + hi) / 2;
  int failures = 0, checked = 0, hits = 0;
  auto check = [&](const Ray& ray, double tMax, std::uint32_t stopAfter) {
    const ::testing::AssertionResult same = sameAnswers(meshes, shapes, ray, tMax, stopAfter);
    if (!same && ++failures <= 5) ADD_FAILURE() << same.message();
    ++checked;
  };
  for (std::uint32_t k = 0; k < 1500; ++k) {
    Draw draw(3, k);
    Double3 origin, direction;
    switch (k % 3) {
      case 0:  // from outside, towards a point of the box
        origin = centre + draw.direction() * 12;
        direction = draw.inBox(lo, hi) - origin;
        break;
      case 1:  // from inside the box, any direction
        origin = draw.inBox(lo, hi);
        direction = draw.direction();
        break;
      default: {  // from below, straight up through the floor and the teapot's bottom
        const double x = draw.uniform(-1.5, 1.5);
        origin = Double3(x, draw.uniform(-1.5, 1.5), -2);
        direction = Double3(0, 0, 1);
      }
    }
    const double tMax = k % 4 == 3 ? draw.uniform(0, 15) : INFINITE_DISTANCE;
    const Ray ray{Point(origin), Vector(direction)};
    const auto stopAfter = static_cast<std::uint32_t>(1 + k % 3);
    check(ray, tMax, stopAfter);
    if (const std::optional<Hit> hit = meshes.closestHit(ray, tMax)) {
      ++hits;
      check(ray, hit->t, stopAfter);                                    // tMax exactly at the hit
      check(Ray(ray.point(hit->t), ray.direction()), tMax, stopAfter);  // relaunched from it
    }
  }
  EXPECT_EQ(failures, 0) << "of " << checked << " queries";
  // TC01: most rays hit something, so the comparison is not of empty answers
  EXPECT_GT(hits, 1000);
}

TEST(MeshIntersectionTests, tiesAndSharedEdges) {
  // A unit square in z = 0 as a mesh of two triangles sharing the diagonal (0,0)-(1,1), each
  // wound to face +z, and the same two triangles as Triangle shapes.
  const auto square = std::make_shared<const TriangleMesh>(
      std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)},
      std::vector<Indices>{{0, 1, 2}, {0, 2, 3}});
  Geometries meshes, shapes;
  meshes.addMesh(square);
  shapes.add(triangleOf(*square, 0), triangleOf(*square, 1));
  auto closest = [](const Geometries& g, const Ray& ray) { return g.closestHit(ray); };
  // ============ Equivalence Partitions Tests ==============
  // TC01: a ray just beside the diagonal hits one triangle only, the same in both scenes
  const Ray belowDiagonal(Point(0.5 + 1e-6, 0.5, 1), Vector(0, 0, -1));
  ASSERT_TRUE(closest(meshes, belowDiagonal).has_value());
  EXPECT_EQ(closest(meshes, belowDiagonal)->geometry, 0u);
  EXPECT_EQ(meshes.findGeoIntersections(belowDiagonal).size(), 1u);
  EXPECT_EQ(shapes.findGeoIntersections(belowDiagonal).size(), 1u);
  // TC02: a shape equal to a mesh triangle ties with it at the same t: the shape wins (its
  // number is smaller), and every query lists both, the shape first
  Geometries tie;
  tie.addMesh(square);
  tie.add(triangleOf(*square, 1));
  const Ray aboveSecond(Point(0.25, 0.75, 2), Vector(0, 0, -1));
  ASSERT_TRUE(tie.closestHit(aboveSecond).has_value());
  EXPECT_EQ(tie.closestHit(aboveSecond)->geometry, 0u);
  EXPECT_EQ(tie.closestHit(aboveSecond)->t, 2.0);
  const std::vector<GeoPoint> both = tie.findGeoIntersections(aboveSecond);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].geometry, 0u);  // the shape
  EXPECT_EQ(both[1].geometry, 2u);  // mesh triangle 1, after the shape and mesh triangle 0
  EXPECT_EQ(both[0].t, both[1].t);
  // TC03: a mesh holding one triangle twice (wound both ways): the first copy wins the tie
  const auto twice = std::make_shared<const TriangleMesh>(
      std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)},
      std::vector<Indices>{{0, 2, 1}, {0, 1, 2}});
  Geometries doubled;
  doubled.addMesh(twice);
  const Ray down(Point(0.25, 0.25, 1), Vector(0, 0, -1));
  ASSERT_TRUE(doubled.closestHit(down).has_value());
  EXPECT_EQ(doubled.closestHit(down)->geometry, 0u);
  EXPECT_EQ(doubled.findGeoIntersections(down).size(), 2u);
  // =============== Boundary Values Tests ==================
  // TC11: a ray through the shared edge's midpoint: the course's rule (a hit on an edge is a
  // miss) holds for both triangles, in the mesh as for the Triangle shapes: no hit at all, where
  // a Polygon of the whole square is hit
  const Ray onEdge(Point(0.5, 0.5, 1), Vector(0, 0, -1));
  EXPECT_FALSE(closest(meshes, onEdge).has_value());
  EXPECT_FALSE(closest(shapes, onEdge).has_value());
  EXPECT_TRUE(meshes.findGeoIntersections(onEdge).empty());
  const Geometries polygon{
      Polygon({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)})};
  EXPECT_TRUE(polygon.closestHit(onEdge).has_value());
  // TC12: a ray through a vertex both triangles share, (1,1,0), slanted: no hit, alike
  const Ray onVertex(Point(0.5, 0.25, 1), Vector(0.5, 0.75, -1));
  EXPECT_FALSE(closest(meshes, onVertex).has_value());
  EXPECT_FALSE(closest(shapes, onVertex).has_value());
  // TC13: a slanted ray through the edge, at (0.7, 0.7, 0): no hit either, alike
  const Ray slantedOnEdge(Point(0, 0.2, 1), Vector(0.35, 0.25, -0.5));
  EXPECT_TRUE(meshes.findGeoIntersections(slantedOnEdge).empty());
  EXPECT_TRUE(shapes.findGeoIntersections(slantedOnEdge).empty());
}

/// A mesh of n copies of one triangle over three vertices: many primitives in 12 bytes each.
std::shared_ptr<const TriangleMesh> copiesOfOneTriangle(std::size_t n) {
  return std::make_shared<const TriangleMesh>(
      std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)},
      std::vector<Indices>(n, Indices{0, 1, 2}));
}

TEST(MeshIntersectionTests, numbering) {
  const auto four = std::make_shared<const TriangleMesh>(
      std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)},
      std::vector<Indices>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  const std::shared_ptr<const TriangleMesh> two = copiesOfOneTriangle(2);
  // ============ Equivalence Partitions Tests ==============
  // TC01: a mesh added first, then two shapes, then a second mesh: the shapes are numbered 0
  // and 1, the first mesh's triangles 2 to 5, the second's 6 and 7; the meshes are 0 and 1
  Geometries g;
  EXPECT_EQ(g.addMesh(four), 0u);
  EXPECT_EQ(g.primitiveCount(), 4u);
  EXPECT_EQ(g.add(Sphere(Point(5, 0, 0), 1)), 0u);
  EXPECT_EQ(g.add(Sphere(Point(-5, 0, 0), 1)), 1u);
  EXPECT_EQ(g.addMesh(two), 1u);
  EXPECT_EQ(g.size(), 2u);
  EXPECT_EQ(g.triangleCount(), 6u);
  EXPECT_EQ(g.primitiveCount(), 8u);
  ASSERT_EQ(g.meshes().size(), 2u);
  EXPECT_EQ(g.meshes()[0].first, 0u);
  EXPECT_EQ(g.meshes()[1].first, 4u);
  EXPECT_EQ(g.meshes()[1].mesh, two);  // shared, not copied
  const Primitives p = g.primitives();
  EXPECT_EQ(p.size(), 8u);
  EXPECT_EQ(p.shapeCount(), 2u);
  EXPECT_TRUE(p.isShape(1));
  EXPECT_FALSE(p.isShape(2));
  auto meshTriangle = [&p](std::uint32_t primitive) {
    const MeshTriangle m = p.meshTriangle(primitive);
    return std::pair(m.mesh, m.triangle);
  };
  EXPECT_EQ(meshTriangle(2), std::pair(0u, 0u));
  EXPECT_EQ(meshTriangle(5), std::pair(0u, 3u));
  EXPECT_EQ(meshTriangle(6), std::pair(1u, 0u));
  EXPECT_EQ(meshTriangle(7), std::pair(1u, 1u));
  // TC02: partOf: a shape is its own part; a mesh triangle's part is size() + its mesh
  EXPECT_EQ(g.partOf(0), 0u);
  EXPECT_EQ(g.partOf(1), 1u);
  EXPECT_EQ(g.partOf(2), 2u);
  EXPECT_EQ(g.partOf(5), 2u);
  EXPECT_EQ(g.partOf(6), 3u);
  EXPECT_EQ(g.partOf(7), 3u);
  // TC03: the numbers in the hits: the first mesh's triangle 3 (facing (1,1,1)) is primitive 5;
  // behind it, in z = 0, its triangle 0 (primitive 2) and the second mesh's two copies of the
  // same triangle (6 and 7) tie, listed by number; the primitives' roots are the mesh's
  const Ray towardsOrigin(Point(1, 1, 1), Vector(-1, -1, -1.01));
  const std::vector<GeoPoint> hits = g.findGeoIntersections(towardsOrigin);
  ASSERT_EQ(hits.size(), 4u);
  EXPECT_EQ(hits[0].geometry, 5u);
  EXPECT_EQ(hits[1].geometry, 2u);
  EXPECT_EQ(hits[2].geometry, 6u);
  EXPECT_EQ(hits[3].geometry, 7u);
  EXPECT_EQ(hits[1].t, hits[3].t);
  EXPECT_EQ(g.closestHit(towardsOrigin)->geometry, 5u);
  EXPECT_TRUE(sameRoots(p.roots(5, towardsOrigin), intersectRoots(*four, 3, towardsOrigin)));
  EXPECT_TRUE(sameRoots(p.roots(0, towardsOrigin), intersectRoots(g[0], towardsOrigin)));
  // TC04: a copy of the collection shares the meshes and numbers the same
  const Geometries copy = g;
  EXPECT_EQ(copy.meshes()[0].mesh, four);
  EXPECT_EQ(copy.closestHit(towardsOrigin)->geometry, 5u);
  // =============== Boundary Values Tests ==================
  // TC11: the first and the last mesh triangle of a scene without shapes; a span of shapes
  // converts to a view with no meshes
  Geometries only;
  only.addMesh(four);
  only.addMesh(two);
  EXPECT_EQ(only.primitives().meshTriangle(0).mesh, 0u);
  EXPECT_EQ(only.primitives().meshTriangle(5).mesh, 1u);
  EXPECT_EQ(only.primitives().meshTriangle(5).triangle, 1u);
  const Primitives shapesOnly(g.shapes());
  EXPECT_EQ(shapesOnly.size(), 2u);
  EXPECT_TRUE(shapesOnly.meshes().empty());
}

TEST(MeshIntersectionTests, normals) {
  const auto flat = std::make_shared<const TriangleMesh>(
      std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)},
      std::vector<Indices>{{0, 1, 2}});
  const auto smooth = std::make_shared<const TriangleMesh>(
      std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)},
      std::vector<Indices>{{0, 1, 2}}, std::vector<Double3>{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}});
  Geometries g;
  g.add(Sphere(Point(0, 0, 10), 1));
  g.addMesh(flat);
  g.addMesh(smooth);
  const Vector fallback(0, -1, 0);
  // ============ Equivalence Partitions Tests ==============
  // TC01: a shape's normals are the shape's: the sphere's at its top
  EXPECT_TRUE(sameBits(g.hitNormal(0, Point(0, 0, 11), fallback).xyz(), Double3(0, 0, 1)));
  EXPECT_TRUE(sameBits(g.normalAt(0, Point(0, 0, 11)).xyz(), Double3(0, 0, 1)));
  // TC02: a flat mesh triangle's is its flat normal, wherever on it, and never the fallback
  EXPECT_TRUE(sameBits(g.hitNormal(1, Point(0.2, 0.3, 0), fallback).xyz(), Double3(0, 0, 1)));
  EXPECT_TRUE(sameBits(g.normalAt(1, Point(0.2, 0.3, 0)).xyz(), Double3(0, 0, 1)));
  // TC03: a smooth mesh triangle's is interpolated: at the corner (1,0,0) the normal x, at the
  // middle of the edge from (1,0,0) to (0,1,0) (1,1,0)/sqrt(2); both queries the same bits
  EXPECT_TRUE(sameBits(g.hitNormal(2, Point(1, 0, 0), fallback).xyz(), Double3(1, 0, 0)));
  const Vector middle = g.hitNormal(2, Point(0.5, 0.5, 0), fallback);
  EXPECT_DOUBLE_EQ(middle.x(), std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(middle.y(), std::sqrt(0.5));
  EXPECT_TRUE(sameBits(g.normalAt(2, Point(0.5, 0.5, 0)).xyz(), middle.xyz()));
  // =============== Boundary Values Tests ==================
  // TC11: where a shape's normal is undefined (the sphere's centre) hitNormal gives the
  // fallback and normalAt throws, as for the shape alone
  EXPECT_TRUE(sameBits(g.hitNormal(0, Point(0, 0, 10), fallback).xyz(), fallback.xyz()));
  EXPECT_THROW(g.normalAt(0, Point(0, 0, 10)), std::invalid_argument);
}

TEST(MeshIntersectionTests, addMeshRefusals) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a null mesh, nothing added
  Geometries g;
  EXPECT_THAT([&] { g.addMesh(nullptr); },
              ThrowsMessage<std::invalid_argument>("Geometries::addMesh: the mesh is null"));
  EXPECT_TRUE(g.meshes().empty());
  EXPECT_EQ(g.primitiveCount(), 0u);
}

TEST(MeshIntersectionTests, primitiveLimit) {
  // The limit, MAX_PRIMITIVES = 2^32 - 1, reached without 4e9 triangles of memory: one mesh of
  // 2^20 copies of a triangle (12 MiB) added 4095 times (it is shared, not copied), then smaller
  // meshes up to the limit.
  static_assert(Geometries::MAX_PRIMITIVES == 0xFFFF'FFFFu);
  const std::shared_ptr<const TriangleMesh> big = copiesOfOneTriangle(std::size_t{1} << 20);
  Geometries g;
  for (int i = 0; i < 4095; ++i) g.addMesh(big);
  ASSERT_EQ(g.primitiveCount(), 4095u << 20);  // 2^32 - 2^20
  g.addMesh(copiesOfOneTriangle((std::size_t{1} << 20) - 2));
  ASSERT_EQ(g.primitiveCount(), Geometries::MAX_PRIMITIVES - 1);
  // =============== Boundary Values Tests ==================
  // TC11: one primitive short of the limit, a mesh of two triangles would make 2^32: refused,
  // naming the sizes, and nothing added
  EXPECT_THAT([&] { g.addMesh(copiesOfOneTriangle(2)); },
              ThrowsMessage<std::length_error>(
                  "Geometries::addMesh: a mesh of 2 triangles would make 4294967296 primitives, "
                  "at most 4294967295"));
  EXPECT_EQ(g.meshes().size(), 4096u);
  EXPECT_EQ(g.primitiveCount(), Geometries::MAX_PRIMITIVES - 1);
  // TC12: a mesh of one triangle fills the last number exactly: it is accepted, and the last
  // primitive, 2^32 - 2, is its triangle 0
  EXPECT_EQ(g.addMesh(copiesOfOneTriangle(1)), 4096u);
  EXPECT_EQ(g.primitiveCount(), Geometries::MAX_PRIMITIVES);
  const MeshTriangle last = g.primitives().meshTriangle(Geometries::MAX_PRIMITIVES - 1);
  EXPECT_EQ(last.mesh, 4096u);
  EXPECT_EQ(last.triangle, 0u);
  EXPECT_EQ(g.partOf(Geometries::MAX_PRIMITIVES - 1), 4096u);
  // TC13: at the limit, a shape is refused too, naming what is there
  EXPECT_THAT([&] { g.add(Sphere(Point(0, 0, 0), 1)); },
              ThrowsMessage<std::length_error>(
                  "Geometries: no room for another shape (0 shapes and 4294967295 mesh "
                  "triangles, at most 4294967295)"));
  EXPECT_EQ(g.size(), 0u);
}

TEST(MeshIntersectionTests, queryCounts) {
  // Two shapes and a mesh of four triangles (the tetrahedron of the numbering test).
  const auto four = std::make_shared<const TriangleMesh>(
      std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)},
      std::vector<Indices>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  Geometries g;
  g.add(Sphere(Point(0.25, 0.25, 5), 1), Sphere(Point(9, 9, 9), 1));
  g.addMesh(four);
  const Ray down(Point(0.25, 0.25, 10), Vector(0, 0, -1));
  // ============ Equivalence Partitions Tests ==============
  // TC01: the closest hit tests every shape and every triangle: 2 + 4 tests, no nodes
  QueryCounts closest;
  ASSERT_EQ(g.closestHit(down, INFINITE_DISTANCE, &closest)->geometry, 0u);
  EXPECT_EQ(closest, (QueryCounts{6, 0}));
  // TC02: every hit: the same 6 tests (4 hits: the sphere twice, triangles 3 and 0)
  QueryCounts all;
  int calls = 0;
  EXPECT_TRUE(g.forEachHit(
      down, INFINITE_DISTANCE, [&](const Hit&) { return ++calls > 0; }, &all));
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(all, (QueryCounts{6, 0}));
  // =============== Boundary Values Tests ==================
  // TC11: a walk stopped at its third hit, the mesh's triangle 0 (primitive 2): the tests made
  // until then, 2 shapes and 1 triangle
  QueryCounts stopped;
  calls = 0;
  EXPECT_FALSE(g.forEachHit(
      down, INFINITE_DISTANCE, [&](const Hit&) { return ++calls < 3; }, &stopped));
  EXPECT_EQ(stopped, (QueryCounts{3, 0}));
}

}  // namespace
}  // namespace rt
