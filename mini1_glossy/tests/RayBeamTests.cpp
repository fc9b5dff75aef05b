// Mini project 1: the beam generator. How many rays a beam has, where they go (inside the cone,
// one per cell, jittered inside it, on the right side of the surface) and the frame it is laid
// out in.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "glossy/Frame.h"
#include "glossy/RayBeam.h"
#include "support/AllocationCounter.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;

std::vector<Vector> beam(const Vector& main, const Vector& n, const BeamSettings& s,
                         std::uint64_t seed = 1) {
  RandomStream random(seed, 0, 0, 0);
  std::vector<Vector> rays;
  const int count = forEachBeamRay(main, n, s, random, [&](const Vector& d) { rays.push_back(d); });
  EXPECT_EQ(static_cast<int>(rays.size()), count);
  return rays;
}

TEST(FrameTests, orthonormalForEveryDirection) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a general direction: u, v, w unit, orthogonal, right-handed (u × v = w)
  // =============== Boundary Values Tests ==================
  // TC11..TC16: the six axes, ±Y included (the reference report's frame failed for −Y), and a
  // direction just off −Z (where the formula's s + w.z is smallest)
  const Double3 dirs[] = {Vector(1, 2, 3).normalized().xyz(),
                          Double3(0, 1, 0),
                          Double3(0, -1, 0),
                          Double3(1, 0, 0),
                          Double3(-1, 0, 0),
                          Double3(0, 0, 1),
                          Double3(0, 0, -1),
                          Vector(1e-9, 0, -1).normalized().xyz()};
  for (const Double3& w : dirs) {
    const Frame f = Frame::around(w);
    EXPECT_NEAR(1, f.u.lengthSquared(), 1e-15) << w;
    EXPECT_NEAR(1, f.v.lengthSquared(), 1e-15) << w;
    EXPECT_NEAR(0, f.u.dot(f.v), 1e-15) << w;
    EXPECT_NEAR(0, f.u.dot(w), 1e-15) << w;
    EXPECT_NEAR(0, f.v.dot(w), 1e-15) << w;
    EXPECT_NEAR(0, (f.u.cross(f.v) - w).lengthSquared(), 1e-30) << w;
  }
}

TEST(RayBeamTests, cellCount) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the cells whose centres are inside the inscribed circle, ≈ π/4·N²: 80 for the reference
  // report's N = 10 (the reference report's grid, not cell-centred, kept 79), 21 for 5, 316 for 20
  EXPECT_EQ(80, beamCellCount(10));
  EXPECT_EQ(21, beamCellCount(5));
  EXPECT_EQ(316, beamCellCount(20));
  // =============== Boundary Values Tests ==================
  // TC11: N = 1: one; N = 2 and 3: every cell (the corners' centres are inside)
  EXPECT_EQ(1, beamCellCount(1));
  EXPECT_EQ(4, beamCellCount(2));
  EXPECT_EQ(9, beamCellCount(3));
  // TC12: the largest grid
  EXPECT_EQ(3228, beamCellCount(BeamSettings::MAX_GRID));
}

TEST(RayBeamTests, rayCount) {
  const Vector up(0, 0, 1);  // the main ray along the normal: no sample is on the wrong side
  // ============ Equivalence Partitions Tests ==============
  // TC01: N = 10, r = 0.2, d = 12 (the galaxy's glass): 80 rays, none of them the main ray
  // traced again
  EXPECT_EQ(80u, beam(up, up, {12, 0.2, 10}).size());
  // TC02: N = 5 and a wide cone: 21
  EXPECT_EQ(21u, beam(up, up, {1, 0.9, 5}).size());
  // =============== Boundary Values Tests ==================
  // TC11: N = 1: exactly one ray, the main one
  const std::vector<Vector> one = beam(up, up, {12, 0.2, 1});
  ASSERT_EQ(1u, one.size());
  EXPECT_EQ(up, one[0]);
  // TC12: radius 0: exactly one ray, the main one, whatever N
  const std::vector<Vector> zero = beam(up, up, {12, 0, 10});
  ASSERT_EQ(1u, zero.size());
  EXPECT_EQ(up, zero[0]);
  // TC13: N = 2: the four cells
  EXPECT_EQ(4u, beam(up, up, {1, 0.5, 2}).size());
}

TEST(RayBeamTests, everyRayInItsCellInsideTheCone) {
  // The main ray along (1,2,-3) off a surface of normal (0,0,-1) (it goes down, away from it).
  const Vector main = Vector(1, 2, -3).normalized();
  const Vector n(0, 0, -1);
  const BeamSettings s{5, 0.5, 8};
  const double size = 2 * s.radius / s.grid;
  const Frame f = Frame::around(main.xyz());
  const std::vector<Vector> rays = beam(main, n, s);
  // TC01: one ray per cell whose centre is inside the circle, jittered inside that cell: the
  // ray meets the target plane (distance 5 along main) inside the cell
  ASSERT_EQ(static_cast<std::size_t>(beamCellCount(8)), rays.size());
  std::set<std::pair<int, int>> cells;
  for (const Vector& d : rays) {
    const double t = s.distance / d.dot(main);
    const Double3 local = d.xyz() * t - main.xyz() * s.distance;
    const double x = local.dot(f.u), y = local.dot(f.v);
    EXPECT_NEAR(0, local.dot(main.xyz()), 1e-12);  // on the target plane
    const int i = static_cast<int>(std::floor((x + s.radius) / size));
    const int j = static_cast<int>(std::floor((y + s.radius) / size));
    ASSERT_GE(i, 0);
    ASSERT_LT(i, s.grid);
    ASSERT_GE(j, 0);
    ASSERT_LT(j, s.grid);
    EXPECT_TRUE(cellInBeam(i, j, s.grid)) << i << "," << j;
    EXPECT_TRUE(cells.insert({i, j}).second) << "cell " << i << "," << j << " twice";
    // TC02: inside the cone of the circle widened by half a cell's diagonal: the angle to the
    // main ray is at most atan((r + s·√2/2)/d)
    const double bound = std::atan((s.radius + size * std::numbers::sqrt2 / 2) / s.distance);
    EXPECT_LE(std::acos(std::min(1.0, d.dot(main))), bound);
    // TC03: on the main ray's side of the surface (n·d and n·main of the same sign)
    EXPECT_GT(d.dot(n) * main.dot(n), 0);
  }
}

TEST(RayBeamTests, wrongSideSamplesAreDropped) {
  // A glossy reflection just above the surface (5° of elevation), a beam 20° wide: the samples
  // below the surface are dropped, the others kept
  const Vector n(0, 0, 1);
  const double elevation = 5 * std::numbers::pi / 180;
  const Vector main(std::cos(elevation), 0, std::sin(elevation));
  const BeamSettings s{1, std::tan(10 * std::numbers::pi / 180), 10};
  const std::vector<Vector> rays = beam(main, n, s);
  // ============ Equivalence Partitions Tests ==============
  // TC01: some dropped (fewer than the 80 cells), some kept, every kept one above the surface
  EXPECT_LT(rays.size(), 80u);
  EXPECT_GT(rays.size(), 20u);
  for (const Vector& d : rays) EXPECT_GT(d.z(), 0);
  // =============== Boundary Values Tests ==================
  // TC11: a narrow beam below the surface (refraction into it): all 12 cells kept, all below
  const Vector under(std::cos(elevation), 0, -std::sin(elevation));
  const std::vector<Vector> narrow = beam(under, n, {1, 1e-6, 4});
  for (const Vector& d : narrow) EXPECT_LT(d.z(), 0);
  EXPECT_EQ(12u, narrow.size());  // beamCellCount(4): the corner cells are outside
  // TC12: a main ray along the surface: every sample is on a side the main ray is not on, so
  // the main ray alone comes back
  const std::vector<Vector> grazing = beam(Vector(1, 0, 0), n, {1, 0.5, 4});
  ASSERT_EQ(1u, grazing.size());  // n·main = 0: no sample has the main ray's (zero) side
  EXPECT_EQ(Vector(1, 0, 0), grazing[0]);
}

TEST(RayBeamTests, deterministicAndCheap) {
  const Vector up(0, 0, 1);
  // TC01: the same stream gives the same beam; another seed another beam
  const std::vector<Vector> a = beam(up, up, {12, 0.2, 10}, 7), b = beam(up, up, {12, 0.2, 10}, 7);
  const std::vector<Vector> c = beam(up, up, {12, 0.2, 10}, 8);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(sameBits(a[k], b[k])) << k;
  EXPECT_NE(a[0].x(), c[0].x());
  // TC02: two numbers per kept cell
  RandomStream r(1, 0, 0, 0);
  forEachBeamRay(up, up, {12, 0.2, 10}, r, [](const Vector&) {});
  EXPECT_EQ(160u, r.dimension());
  // TC03: no allocation
  double sum = 0;
  RandomStream q(1, 0, 0, 0);
  EXPECT_EQ(0, testing::allocationsDuring([&] {
              forEachBeamRay(up, up, {12, 0.2, 10}, q, [&](const Vector& d) { sum += d.z(); });
            }));
  EXPECT_GT(sum, 79);
}

}  // namespace
}  // namespace rt
