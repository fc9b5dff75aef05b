// mini2: the regular grid's build (its resolution, the cells each shape is listed in) on small
// hand-made scenes, the 3D-DDA's cell sequence for rays of each kind, each shape tested once per
// ray however many cells it spans, and the cells counted as visited nodes.
#include "grid/Grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "geometries/Plane.h"
#include "geometries/Sphere.h"
#include "geometries/Triangle.h"

namespace rt {
namespace {

using Cells = std::vector<std::array<int, 3>>;

/// Eight spheres of radius 1 at (±3, ±3, ±3): the box [-4, 4]³ (padded by a few millionths),
/// 8·8 = 64 cells aimed at, 4 per axis, cells of width 2 (borders at about -4, -2, 0, 2, 4).
Geometries eightCorners() {
  Geometries g;
  for (int x : {-3, 3})
    for (int y : {-3, 3})
      for (int z : {-3, 3}) g.add(Sphere(Point(x, y, z), 1));
  return g;
}

/// Spheres of radius 1 at (-10, 0, 0) and (10, 0, 0), and a triangle along the whole scene in
/// z = 0: the box [-11, 11] x [-1, 1] x [-1, 1].
Geometries twoSpheresAndABeam() {
  Geometries g;
  g.add(Sphere(Point(-10, 0, 0), 1), Sphere(Point(10, 0, 0), 1),
        Triangle(Point(-11, 0, 0), Point(11, 0, 0), Point(0, 1, 0)));
  return g;
}

TEST(GridTests, resolutionAndCells) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: one sphere: a cube of 8 cells (2·∛1 = 2 per axis), the sphere in all of them
  {
    Geometries one;
    one.add(Sphere(Point(0, 0, 0), 1));
    const Grid grid(one);
    EXPECT_EQ(grid.resolution(), (std::array<int, 3>{2, 2, 2}));
    EXPECT_EQ(grid.cellCount(), 8u);
    EXPECT_EQ(grid.entryCount(), 8u);
    EXPECT_EQ(grid.cellShapes(1, 0, 1), (std::vector<std::uint32_t>{0}));
  }
  // TC02: two spheres far apart along x: 16 cells aimed at; y and z (2 wide against 22) round to
  // one cell, so all 16 go along x (cells 1.375 wide); each sphere, 2 wide, in 2 cells
  {
    Geometries two;
    two.add(Sphere(Point(-10, 0, 0), 1), Sphere(Point(10, 0, 0), 1));
    const Grid grid(two);
    EXPECT_EQ(grid.resolution(), (std::array<int, 3>{16, 1, 1}));
    EXPECT_EQ(grid.entryCount(), 4u);
    EXPECT_EQ(grid.cellShapes(0, 0, 0), (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(grid.cellShapes(1, 0, 0), (std::vector<std::uint32_t>{0}));
    EXPECT_TRUE(grid.cellShapes(2, 0, 0).empty());
    EXPECT_TRUE(grid.cellShapes(13, 0, 0).empty());
    EXPECT_EQ(grid.cellShapes(14, 0, 0), (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(grid.cellShapes(15, 0, 0), (std::vector<std::uint32_t>{1}));
  }
  // TC03: a shape spanning many cells: 24 cells along x (11/12 wide); the triangle is in every
  // one, each sphere in 3 (2 / (11/12) = 2.2 cells wide)
  {
    const Geometries scene = twoSpheresAndABeam();
    const Grid grid(scene);
    EXPECT_EQ(grid.resolution(), (std::array<int, 3>{24, 1, 1}));
    EXPECT_EQ(grid.entryCount(), 24u + 3 + 3);
    EXPECT_EQ(grid.cellShapes(2, 0, 0), (std::vector<std::uint32_t>{0, 2}));
    EXPECT_EQ(grid.cellShapes(12, 0, 0), (std::vector<std::uint32_t>{2}));
    EXPECT_EQ(grid.cellShapes(21, 0, 0), (std::vector<std::uint32_t>{1, 2}));
  }
  // TC04: eight spheres at the corners of a cube: 4 cells per axis; each sphere's box ends on
  // the borders at ±2 and the margin takes it just across them, so each sphere is in the 2 x 2 x
  // 2 cells of its corner, and each cell holds one sphere
  {
    const Geometries scene = eightCorners();
    const Grid grid(scene);
    EXPECT_EQ(grid.resolution(), (std::array<int, 3>{4, 4, 4}));
    EXPECT_EQ(grid.entryCount(), 64u);
    EXPECT_EQ(grid.cellShapes(0, 0, 0), (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(grid.cellShapes(3, 3, 3), (std::vector<std::uint32_t>{7}));
    EXPECT_EQ(grid.cellShapes(1, 2, 1), (std::vector<std::uint32_t>{2}));  // (-3, 3, -3)
    EXPECT_EQ(grid.cellShapes(2, 1, 2), (std::vector<std::uint32_t>{5}));  // (3, -3, 3)
  }
  // =============== Boundary Values Tests ==================
  // TC11: no shape at all: no cell, every query answers nothing and visits nothing
  {
    const Geometries none;
    const Grid grid(none);
    EXPECT_EQ(grid.resolution(), (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(grid.cellCount(), 0u);
    QueryCounts counts;
    EXPECT_FALSE(grid.closestHit(Ray(Point(0, 0, 0), Vector(1, 0, 0)), INFINITE_DISTANCE, &counts)
                     .has_value());
    EXPECT_EQ(counts, (QueryCounts{0, 0}));
  }
  // TC12: only unbounded shapes: no cell; the plane is tested on its own
  {
    Geometries planes;
    planes.add(Plane(Point(0, -1, 0), Vector(0, 1, 0)));
    const Grid grid(planes);
    EXPECT_EQ(grid.cellCount(), 0u);
    ASSERT_EQ(grid.unboundedShapes().size(), 1u);
    QueryCounts counts;
    const auto hit = grid.closestHit(Ray(Point(0, 0, 0), Vector(0, -1, 0)), 10, &counts);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->t, 1.0);
    EXPECT_EQ(counts, (QueryCounts{1, 0}));
  }
  // TC13: a flat scene (one triangle in z = 0, its box a few millionths thick): z rounds to one
  // cell, and the 8 cells go to x and y
  {
    Geometries flat;
    flat.add(Triangle(Point(0, 0, 0), Point(4, 0, 0), Point(0, 4, 0)));
    const Grid grid(flat);
    const std::array<int, 3> n = grid.resolution();
    EXPECT_EQ(n[2], 1);
    EXPECT_EQ(n[0], 3);  // round(√8) = 3
    EXPECT_EQ(n[1], 3);
  }
}

TEST(GridTests, cellSequence) {
  const Geometries scene = eightCorners();
  const Grid grid(scene);
  // ============ Equivalence Partitions Tests ==============
  // TC01: along +x at y = z = 1: the row of cells y = z = 2, in order
  EXPECT_EQ(grid.cellsAlong(Ray(Point(-10, 1, 1), Vector(1, 0, 0))),
            (Cells{{0, 2, 2}, {1, 2, 2}, {2, 2, 2}, {3, 2, 2}}));
  // TC02: along -x: the same row backwards
  EXPECT_EQ(grid.cellsAlong(Ray(Point(10, -1, 1), Vector(-1, 0, 0))),
            (Cells{{3, 1, 2}, {2, 1, 2}, {1, 1, 2}, {0, 1, 2}}));
  // TC03: a diagonal in z = 1, y = x + 0.5: it crosses each y border before the x border
  EXPECT_EQ(grid.cellsAlong(Ray(Point(-5, -4.5, 1), Vector(1, 1, 0))),
            (Cells{{0, 0, 2}, {0, 1, 2}, {1, 1, 2}, {1, 2, 2}, {2, 2, 2}, {2, 3, 2}, {3, 3, 2}}));
  // TC04: the main diagonal through the cells' corners: the three borders are crossed at the
  // same t, and the walk steps x, then y, then z (the lowest axis first on a tie)
  EXPECT_EQ(grid.cellsAlong(Ray(Point(-10, -10, -10), Vector(1, 1, 1))), (Cells{{0, 0, 0},
                                                                                {1, 0, 0},
                                                                                {1, 1, 0},
                                                                                {1, 1, 1},
                                                                                {2, 1, 1},
                                                                                {2, 2, 1},
                                                                                {2, 2, 2},
                                                                                {3, 2, 2},
                                                                                {3, 3, 2},
                                                                                {3, 3, 3}}));
  // TC05: starting inside, at (1, 1, 1), down z: from its own cell out through z = -4
  EXPECT_EQ(grid.cellsAlong(Ray(Point(1, 1, 1), Vector(0, 0, -1))),
            (Cells{{2, 2, 2}, {2, 2, 1}, {2, 2, 0}}));
  // TC06: parallel to the faces y = const (direction (2, 0, 1)): x and z borders alternate
  EXPECT_EQ(grid.cellsAlong(Ray(Point(-4.5, 1, -3), Vector(2, 0, 1))),
            (Cells{{0, 2, 0}, {0, 2, 1}, {1, 2, 1}, {2, 2, 1}, {2, 2, 2}, {3, 2, 2}}));
  // =============== Boundary Values Tests ==================
  // TC11: missing the box (above it): no cell
  EXPECT_TRUE(grid.cellsAlong(Ray(Point(-10, 10, 0), Vector(1, 0, 0))).empty());
  // TC12: pointing away from the box: no cell
  EXPECT_TRUE(grid.cellsAlong(Ray(Point(-10, 1, 1), Vector(-1, 0, 0))).empty());
  // TC13: tMax: the next cell begins at t ≈ 1 (x = 2); tMax 0.5 stops before it, 1.5 after it
  EXPECT_EQ(grid.cellsAlong(Ray(Point(1, 1, 1), Vector(1, 0, 0)), 0.5), (Cells{{2, 2, 2}}));
  EXPECT_EQ(grid.cellsAlong(Ray(Point(1, 1, 1), Vector(1, 0, 0)), 1.5),
            (Cells{{2, 2, 2}, {3, 2, 2}}));
  // TC14: a box entered beyond tMax: no cell
  EXPECT_TRUE(grid.cellsAlong(Ray(Point(-10, 1, 1), Vector(1, 0, 0)), 5).empty());
}

TEST(GridTests, eachShapeTestedOncePerRay) {
  const Geometries scene = twoSpheresAndABeam();
  const Grid grid(scene);
  // A ray rising slowly in z across the whole box: through both spheres and, at x = 0, the
  // triangle, which is listed in all 24 cells the ray crosses.
  const Ray ray(Point(-12, 0.1, -0.5), Vector(24, 0, 1));
  // ============ Equivalence Partitions Tests ==============
  // TC01: every hit: 24 cells, 3 tests (the linear scan's 3), 5 hits (two per sphere)
  QueryCounts all;
  int hits = 0;
  EXPECT_TRUE(grid.forEachHit(
      ray, INFINITE_DISTANCE,
      [&hits](const Hit&) {
        ++hits;
        return true;
      },
      &all));
  EXPECT_EQ(hits, 5);
  EXPECT_EQ(all, (QueryCounts{3, 24}));
  // TC02: the closest hit: the first sphere at x ≈ -10.89, in the first cell (x < -10.08); that
  // cell's triangle and sphere are tested, and the walk stops there
  QueryCounts closest;
  const auto hit = grid.closestHit(ray, INFINITE_DISTANCE, &closest);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->geometry, 0u);
  EXPECT_EQ(closest, (QueryCounts{2, 1}));
  EXPECT_EQ(hit->t, scene.closestHit(ray)->t);
  // =============== Boundary Values Tests ==================
  // TC11: stopped at the first hit: one visit, forEachHit says it was stopped
  int calls = 0;
  EXPECT_FALSE(grid.forEachHit(ray, INFINITE_DISTANCE, [&calls](const Hit&) {
    ++calls;
    return false;
  }));
  EXPECT_EQ(calls, 1);
}

/// Every hit forEachHit visits, sorted.
std::vector<std::pair<double, std::uint32_t>> allHits(const Intersectable& shapes, const Ray& ray,
                                                      double tMax) {
  std::vector<std::pair<double, std::uint32_t>> hits;
  shapes.forEachHit(ray, tMax, [&hits](const Hit& h) {
    hits.emplace_back(h.t, h.geometry);
    return true;
  });
  std::sort(hits.begin(), hits.end());
  return hits;
}

TEST(GridTests, raysAlongBordersAndThroughCornersAnswerAsTheList) {
  // Spheres of radius 0.5 at the integer points of [0, 5]³, touching each other, and copies of
  // the first 20 (exact ties): 12 cells per axis, about 0.5 wide, so the spheres' centres and
  // their points of contact lie on (or within rounding of) cell borders.
  Geometries lattice;
  for (int x = 0; x <= 5; ++x)
    for (int y = 0; y <= 5; ++y)
      for (int z = 0; z <= 5; ++z) lattice.add(Sphere(Point(x, y, z), 0.5));
  for (std::uint32_t i = 0; i < 20; ++i) lattice.add(Geometry(lattice.shapes()[i]));
  const Grid grid(lattice);
  ASSERT_EQ(grid.resolution(), (std::array<int, 3>{12, 12, 12}));
  std::vector<Ray> rays;
  // ============ Equivalence Partitions Tests ==============
  // TC01: along each axis, both ways, on the lines through centres, contact points and borders
  for (double a = -0.5; a <= 5.5; a += 0.25)
    for (double b : {0.0, 0.5, 2.0, 2.25, 5.5}) {
      rays.emplace_back(Point(-3, a, b), Vector(1, 0, 0));
      rays.emplace_back(Point(8, b, a), Vector(-1, 0, 0));
      rays.emplace_back(Point(a, -3, b), Vector(0, 1, 0));
      rays.emplace_back(Point(b, a, 8), Vector(0, 0, -1));
    }
  // TC02: diagonals through the lattice's points and the cells' corners
  for (double a : {0.0, 0.5, 1.0, 2.5})
    for (const Vector& d : {Vector(1, 1, 1), Vector(1, 1, 0), Vector(1, -1, 1), Vector(0, 1, -1)})
      rays.emplace_back(Point(a, a, a) - d * 10, d);
  // TC03: starting inside, on a border and at a centre, in every axis direction
  for (const Point& p : {Point(2, 2, 2), Point(2.5, 2.5, 2.5), Point(1, 2.5, 3)})
    for (const Vector& d : {Vector(1, 0, 0), Vector(0, -1, 0), Vector(0, 0, 1), Vector(1, 1, 1)})
      rays.emplace_back(p, d);
  int checked = 0;
  for (const Ray& ray : rays) {
    const auto expected = lattice.closestHit(ray);
    for (double tMax : {INFINITE_DISTANCE, expected ? expected->t : 1.0, 3.0}) {
      const auto want = lattice.closestHit(ray, tMax);
      const auto got = grid.closestHit(ray, tMax);
      ASSERT_EQ(want.has_value(), got.has_value()) << ray << " tMax " << tMax;
      if (want) {
        EXPECT_EQ(got->t, want->t) << ray << " tMax " << tMax;
        EXPECT_EQ(got->geometry, want->geometry) << ray << " tMax " << tMax;
      }
      EXPECT_EQ(allHits(grid, ray, tMax), allHits(lattice, ray, tMax)) << ray << " tMax " << tMax;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 3 * (25 * 5 * 4 + 16 + 12));
}

}  // namespace
}  // namespace rt
