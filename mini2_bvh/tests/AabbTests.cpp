// mini2: the Aabb type (empty box, union, surface area, centroid, longest axis, containment)
// and the FloatBox a query stores (rounded outwards, padded for the solvers' rounding).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "bvh/Aabb.h"
#include "bvh/FloatBox.h"

namespace rt {
namespace {

const Aabb kBox(Double3(0, 0, 0), Double3(1, 2, 3));

TEST(AabbTests, emptyAndExpand) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the default box is empty: no area, holds no point
  const Aabb empty;
  EXPECT_TRUE(empty.isEmpty());
  EXPECT_EQ(empty.surfaceArea(), 0);
  EXPECT_FALSE(empty.contains(Double3(0, 0, 0)));
  // TC02: expanding by points gives their box
  Aabb box;
  box.expand(Double3(1, -2, 3)).expand(Double3(-1, 2, 0));
  EXPECT_EQ(box, Aabb(Double3(-1, -2, 0), Double3(1, 2, 3)));
  // TC03: the union of two overlapping boxes
  EXPECT_EQ(unite(kBox, Aabb(Double3(-1, 1, 1), Double3(0.5, 5, 2))),
            Aabb(Double3(-1, 0, 0), Double3(1, 5, 3)));
  // =============== Boundary Values Tests ==================
  // TC11: one point: a box of zero size, not empty
  Aabb point;
  point.expand(Double3(4, 5, 6));
  EXPECT_FALSE(point.isEmpty());
  EXPECT_EQ(point, Aabb(Double3(4, 5, 6), Double3(4, 5, 6)));
  // TC12: the union with an empty box changes nothing, either way round
  EXPECT_EQ(unite(kBox, Aabb()), kBox);
  EXPECT_EQ(unite(Aabb(), kBox), kBox);
}

TEST(AabbTests, measures) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: surface area 2(1·2 + 2·3 + 3·1) = 22, centroid (0.5, 1, 1.5), extent (1, 2, 3)
  EXPECT_EQ(kBox.surfaceArea(), 22);
  EXPECT_EQ(kBox.centroid().x, 0.5);
  EXPECT_EQ(kBox.centroid().y, 1);
  EXPECT_EQ(kBox.centroid().z, 1.5);
  EXPECT_EQ(kBox.extent().z, 3);
  // TC02: the longest axis is each axis in turn
  EXPECT_EQ(Aabb(Double3(0), Double3(3, 1, 2)).longestAxis(), 0);
  EXPECT_EQ(Aabb(Double3(0), Double3(1, 3, 2)).longestAxis(), 1);
  EXPECT_EQ(kBox.longestAxis(), 2);
  // =============== Boundary Values Tests ==================
  // TC11: a flat box (a rectangle in z = 0) has the area of its two faces: 2·(2·3) = 12
  EXPECT_EQ(Aabb(Double3(0, 0, 0), Double3(2, 3, 0)).surfaceArea(), 12);
  // TC12: a segment's box has no area
  EXPECT_EQ(Aabb(Double3(0, 0, 0), Double3(5, 0, 0)).surfaceArea(), 0);
  // TC13: equal extents: the lower axis is the longest
  EXPECT_EQ(Aabb(Double3(0), Double3(2, 2, 2)).longestAxis(), 0);
  EXPECT_EQ(Aabb(Double3(0), Double3(1, 2, 2)).longestAxis(), 1);
  // TC14: component() reads x, y and z
  EXPECT_EQ(component(Double3(7, 8, 9), 0), 7);
  EXPECT_EQ(component(Double3(7, 8, 9), 1), 8);
  EXPECT_EQ(component(Double3(7, 8, 9), 2), 9);
}

TEST(AabbTests, contains) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a point inside, a point outside
  EXPECT_TRUE(kBox.contains(Double3(0.5, 1, 1)));
  EXPECT_FALSE(kBox.contains(Double3(0.5, 1, 4)));
  // TC02: a box inside, a box partly outside
  EXPECT_TRUE(kBox.contains(Aabb(Double3(0.1), Double3(0.9))));
  EXPECT_FALSE(kBox.contains(Aabb(Double3(0.5), Double3(1.5))));
  // =============== Boundary Values Tests ==================
  // TC11: points on a face, an edge and a corner are inside (bounds included)
  EXPECT_TRUE(kBox.contains(Double3(1, 1, 1)));
  EXPECT_TRUE(kBox.contains(Double3(1, 2, 1)));
  EXPECT_TRUE(kBox.contains(Double3(1, 2, 3)));
  // TC12: the box holds itself and the empty box
  EXPECT_TRUE(kBox.contains(kBox));
  EXPECT_TRUE(kBox.contains(Aabb()));
}

TEST(FloatBoxTests, enclosing) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: bounds that are floats stay exactly as they are
  const FloatBox exact = FloatBox::enclosing(Aabb(Double3(-1.5, 0, 2), Double3(0.25, 8, 1024)));
  EXPECT_EQ(exact.widen(), Aabb(Double3(-1.5, 0, 2), Double3(0.25, 8, 1024)));
  // TC02: 0.1 is no float: lo rounds down and hi up, to neighbouring floats
  const FloatBox tenth = FloatBox::enclosing(Aabb(Double3(0.1), Double3(0.1)));
  EXPECT_LT(tenth.lo[0], 0.1);
  EXPECT_GT(tenth.hi[0], 0.1);
  EXPECT_EQ(std::nextafter(tenth.lo[0], 1.0f), tenth.hi[0]);
  // TC03: negative bounds round outwards too (lo down, hi up)
  const FloatBox negative = FloatBox::enclosing(Aabb(Double3(-0.1), Double3(-0.1)));
  EXPECT_LT(negative.lo[1], -0.1);
  EXPECT_GT(negative.hi[1], -0.1);
  // =============== Boundary Values Tests ==================
  // TC11: bounds beyond the float range become ±∞ on the outside, FLT_MAX on the inside
  const FloatBox huge = FloatBox::enclosing(Aabb(Double3(-1e39), Double3(1e39)));
  EXPECT_EQ(huge.lo[2], -std::numeric_limits<float>::infinity());
  EXPECT_EQ(huge.hi[2], std::numeric_limits<float>::infinity());
  const FloatBox far = FloatBox::enclosing(Aabb(Double3(1e39), Double3(1e40)));
  EXPECT_EQ(far.lo[0], FLT_MAX);
}

TEST(FloatBoxTests, conservativeBox) {
  // TC01: the exact box padded by 2^-20 of its largest coordinate (here 2: 2^-19), exactly
  const FloatBox padded = conservativeBox(Aabb(Double3(1, 1, 1), Double3(2, 2, 2)));
  EXPECT_EQ(padded.lo[0], 1 - 0x1p-19);
  EXPECT_EQ(padded.hi[2], 2 + 0x1p-19);
  // TC02: a negative coordinate counts by its size: the margin of (-8, ..) is 2^-17
  const FloatBox negative = conservativeBox(Aabb(Double3(-8, 0, 0), Double3(1, 1, 1)));
  EXPECT_EQ(negative.lo[0], -8 - 0x1p-17);
  EXPECT_EQ(negative.lo[1], -0x1p-17);
  // TC11: a box at the origin of size 0 stays a point
  const FloatBox origin = conservativeBox(Aabb(Double3(0), Double3(0)));
  EXPECT_EQ(origin.widen(), Aabb(Double3(0), Double3(0)));
}

}  // namespace
}  // namespace rt
