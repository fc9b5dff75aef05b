// Stage 3: the per-shape solvers' root list (ascending, t > 0 after alignZero, stack storage)
// and the inclusive maximum-distance test shared by both queries.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "intersections/Intersect.h"

namespace rt {
namespace {

TEST(RootsTests, add) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: positive roots are kept in ascending order whatever the order of adding
  Roots roots;
  roots.add(3);
  roots.add(1);
  roots.add(2);
  ASSERT_EQ(roots.size(), 3);
  EXPECT_EQ(roots[0], 1.0);
  EXPECT_EQ(roots[1], 2.0);
  EXPECT_EQ(roots[2], 3.0);
  // TC02: negative roots (behind the head) are dropped
  Roots behind;
  behind.add(-1);
  EXPECT_TRUE(behind.empty());
  // TC03: NaN (no crossing) is dropped
  behind.add(std::nan(""));
  EXPECT_TRUE(behind.empty());
  // =============== Boundary Values Tests ==================
  // TC11: zero and a root that isZero (rounding noise at the head) are dropped
  Roots tiny;
  tiny.add(0);
  tiny.add(1e-13);
  tiny.add(-1e-13);
  EXPECT_TRUE(tiny.empty());
  // TC12: a root of exactly 2^-40 is kept
  tiny.add(std::ldexp(1.0, -40));
  EXPECT_EQ(tiny.size(), 1);
  // TC13: up to CAPACITY roots are kept; the range-for sees them in order
  Roots full;
  for (int i = Roots::CAPACITY; i >= 1; --i) full.add(i);
  EXPECT_EQ(full.size(), Roots::CAPACITY);
  double previous = 0;
  for (double t : full) {
    EXPECT_GT(t, previous);
    previous = t;
  }
}

TEST(RootsTests, withinDistance) {
  // TC01: inside and beyond the maximum distance
  EXPECT_TRUE(withinDistance(1, 2));
  EXPECT_FALSE(withinDistance(3, 2));
  // TC02: an infinite maximum distance accepts everything
  EXPECT_TRUE(withinDistance(1e300, INFINITE_DISTANCE));
  // TC11: exactly at the maximum distance (inclusive)
  EXPECT_TRUE(withinDistance(2, 2));
  // TC12: beyond it by rounding noise (isZero) still counts, by 1e-9 does not
  EXPECT_TRUE(withinDistance(2 + 1e-13, 2));
  EXPECT_FALSE(withinDistance(2 + 1e-9, 2));
}

}  // namespace
}  // namespace rt
