// mini2: the conservative slab test (SlabRay.h) against the box (0,0,0)..(2,2,2): hits, misses
// and the boundaries: parallel rays inside, outside and on a slab's bound (0·∞ = NaN), grazing
// an edge and a corner, tMax at or before the entry, a box behind the ray, a flat box, tiny
// direction components; and rays aimed at points of the faces never miss.
#include <gtest/gtest.h>

#include <cmath>

#include "bvh/SlabRay.h"

#include "RandomScenes.h"

namespace rt {
namespace {

const Aabb kBox(Double3(0, 0, 0), Double3(2, 2, 2));

/// The slab test of the ray from `from` along `dir`; entry set on a hit.
bool hits(const Double3& from, const Double3& dir, double tMax = INFINITE_DISTANCE,
          double* entry = nullptr, const Aabb& box = kBox) {
  double t = -1;
  const bool hit = slabHit(SlabRay(Ray(Point(from), Vector(dir))), box, tMax, t);
  if (entry != nullptr) *entry = t;
  return hit;
}

/// t is the exact value v rounded down by at most a few ulps (the test's 1 − 2γ(3) scaling).
::testing::AssertionResult justBelow(double t, double v) {
  if (t <= v && t >= v * (1 - 1e-15)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "t = " << t << ", expected just below " << v;
}

TEST(SlabTests, partitions) {
  double entry;
  // ============ Equivalence Partitions Tests ==============
  // TC01: from outside, through the box: enters at t = 1 (rounded down)
  EXPECT_TRUE(hits(Double3(-1, 1, 1), Double3(1, 0, 0), INFINITE_DISTANCE, &entry));
  EXPECT_TRUE(justBelow(entry, 1));
  // TC02: from outside, passing beside the box
  EXPECT_FALSE(hits(Double3(-1, 3, 1), Double3(1, 0.1, 0)));
  // TC03: starting inside: a hit with entry 0
  EXPECT_TRUE(hits(Double3(1, 1, 1), Double3(-1, 2, 3), INFINITE_DISTANCE, &entry));
  EXPECT_EQ(entry, 0);
  // TC04: the box behind the ray
  EXPECT_FALSE(hits(Double3(3, 1, 1), Double3(1, 0, 0)));
  // TC05: tMax before the box
  EXPECT_FALSE(hits(Double3(-1, 1, 1), Double3(1, 0, 0), 0.5));
  // TC06: an oblique ray through the corner region: from (-1,-1,-1) along (1,1,1), entry √3
  EXPECT_TRUE(hits(Double3(-1, -1, -1), Double3(1, 1, 1), INFINITE_DISTANCE, &entry));
  EXPECT_NEAR(entry, std::sqrt(3.0), 1e-14);
  // TC07: a ray running towards lower coordinates enters through the upper bound: t = 1
  EXPECT_TRUE(hits(Double3(3, 1, 1), Double3(-1, 0, 0), INFINITE_DISTANCE, &entry));
  EXPECT_TRUE(justBelow(entry, 1));
}

TEST(SlabTests, boundaries) {
  double entry;
  // =============== Boundary Values Tests ==================
  // TC11: parallel to the y and z slabs, inside them: a hit
  EXPECT_TRUE(hits(Double3(-1, 0.5, 1.5), Double3(1, 0, 0)));
  // TC12: parallel to the y slab, outside it (1/d_y = ∞ puts the slab at t = -∞..-∞): a miss
  EXPECT_FALSE(hits(Double3(-1, 3, 1), Double3(1, 0, 0)));
  EXPECT_FALSE(hits(Double3(-1, -0.5, 1), Double3(1, 0, 0)));
  // TC13: parallel to the y slab, exactly on its bounds (0·∞ = NaN leaves the interval as it
  // is): a hit, on the lower and the upper bound, for +0 and -0 components
  EXPECT_TRUE(hits(Double3(-1, 0, 1), Double3(1, 0, 0)));
  EXPECT_TRUE(hits(Double3(-1, 2, 1), Double3(1, 0, 0)));
  EXPECT_TRUE(hits(Double3(-1, 0, 1), Double3(1, -0.0, 0)));
  EXPECT_TRUE(hits(Double3(-1, 2, 1), Double3(1, -0.0, -0.0)));
  // TC14: grazing an edge (the line y = 2, z = 2): bounds included, a hit
  EXPECT_TRUE(hits(Double3(-1, 2, 2), Double3(1, 0, 0)));
  // TC15: touching only the corner (2,2,2): from (3,1,3) along (-1,1,-1), at t = √3
  EXPECT_TRUE(hits(Double3(3, 1, 3), Double3(-1, 1, -1), INFINITE_DISTANCE, &entry));
  EXPECT_TRUE(justBelow(entry, std::sqrt(3.0)));
  // TC16: tMax exactly at the entry: a hit (inclusive); just before it: a miss
  EXPECT_TRUE(hits(Double3(-1, 1, 1), Double3(1, 0, 0), 1));
  EXPECT_FALSE(hits(Double3(-1, 1, 1), Double3(1, 0, 0), 1 - 1e-9));
  // TC17: starting on a face, going out: touches the box at t = 0
  EXPECT_TRUE(hits(Double3(2, 1, 1), Double3(1, 0, 0), INFINITE_DISTANCE, &entry));
  EXPECT_EQ(entry, 0);
  // TC18: the box ends just behind the head: a miss
  EXPECT_FALSE(hits(Double3(2 + 1e-9, 1, 1), Double3(1, 0, 0)));
  // TC19: a flat box (a rectangle in z = 1): crossed at t = 1, and a ray inside its plane hits
  const Aabb flat(Double3(0, 0, 1), Double3(2, 2, 1));
  EXPECT_TRUE(hits(Double3(1, 1, 0), Double3(0, 0, 1), INFINITE_DISTANCE, &entry, flat));
  EXPECT_TRUE(justBelow(entry, 1));
  EXPECT_TRUE(hits(Double3(-1, 1, 1), Double3(1, 0, 0), INFINITE_DISTANCE, nullptr, flat));
  EXPECT_FALSE(hits(Double3(-1, 1, 1.5), Double3(1, 0, 0), INFINITE_DISTANCE, nullptr, flat));
  // TC20: tiny direction components: y = 1e-200 changes nothing inside the slab; outside it,
  // the slab would be reached at t ≈ 5e199, long after the x slab is left
  EXPECT_TRUE(hits(Double3(-1, 1, 1), Double3(1, 1e-200, 0)));
  EXPECT_FALSE(hits(Double3(-1, 2.5, 1), Double3(1, -1e-200, 0)));
  // TC21: a NaN tMax finds nothing
  EXPECT_FALSE(hits(Double3(-1, 1, 1), Double3(1, 0, 0), std::nan("")));
}

TEST(SlabTests, raysAimedAtTheFacesNeverMiss) {
  // TC01: 10000 rays from random origins around a random box, each aimed at a random point of
  // one of its faces (or an edge, or a corner): all hit, with an entry before the aimed point
  test::Random random(11);
  int misses = 0, late = 0;
  for (int i = 0; i < 10000; ++i) {
    const Double3 lo = random.inCube(-10, 10);
    const Aabb box(lo, lo + random.inCube(0, 5));
    Double3 target = random.inBox(box);
    const int axis = random.integer(0, 2);
    const bool upper = random.chance(0.5);
    (axis == 0   ? target.x
     : axis == 1 ? target.y
                 : target.z) = component(upper ? box.hi : box.lo, axis);
    if (random.chance(0.2)) target = random.chance(0.5) ? box.lo : box.hi;  // a corner
    const Double3 toOrigin = random.direction();
    const Double3 origin = target + toOrigin * random.uniform(0.1, 50);
    if (origin.x == target.x && origin.y == target.y && origin.z == target.z) continue;
    const Ray ray(Point(origin), Vector(target - origin));
    double entry;
    if (!slabHit(SlabRay(ray), box, INFINITE_DISTANCE, entry)) {
      ++misses;
    } else if (entry > std::sqrt((target - origin).lengthSquared()) * (1 + 1e-15)) {
      ++late;
    }
  }
  EXPECT_EQ(misses, 0);
  EXPECT_EQ(late, 0);
}

}  // namespace
}  // namespace rt
