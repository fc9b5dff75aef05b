// Stage 3: the rules every Intersectable applies to a shape's roots (HitRules.h): the nearest
// hit as the smallest (t, geometry) pair within tMax, offered in any order, and the forEachHit
// walk over one shape's roots.
#include <gtest/gtest.h>

#include <initializer_list>
#include <vector>

#include "intersections/HitRules.h"

namespace rt {
namespace {

Roots rootsOf(std::initializer_list<double> ts) {
  Roots roots;
  for (double t : ts) roots.add(t);
  return roots;
}

TEST(HitRulesTests, nearestHit) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the nearest root of the nearest shape wins, whatever the order of the offers
  NearestHit forward(INFINITE_DISTANCE);
  forward.offer(rootsOf({2, 5}), 0);
  forward.offer(rootsOf({1, 3}), 1);
  NearestHit backward(INFINITE_DISTANCE);
  backward.offer(rootsOf({1, 3}), 1);
  backward.offer(rootsOf({2, 5}), 0);
  ASSERT_TRUE(forward.hit().has_value());
  EXPECT_EQ(forward.hit()->t, 1.0);
  EXPECT_EQ(forward.hit()->geometry, 1u);
  EXPECT_EQ(backward.hit()->t, 1.0);
  EXPECT_EQ(backward.hit()->geometry, 1u);
  // TC02: a shape whose nearest root is beyond tMax does not count (nor do its later roots)
  NearestHit limited(1.5);
  limited.offer(rootsOf({2, 3}), 0);
  EXPECT_FALSE(limited.hit().has_value());
  EXPECT_EQ(limited.t(), INFINITE_DISTANCE);
  // TC03: no roots, no hit
  NearestHit none(INFINITE_DISTANCE);
  none.offer(Roots(), 4);
  EXPECT_FALSE(none.hit().has_value());
  // =============== Boundary Values Tests ==================
  // TC11: two shapes at exactly the same t: the smaller index wins, offered in either order
  NearestHit tieLate(INFINITE_DISTANCE);
  tieLate.offer(rootsOf({2}), 7);
  tieLate.offer(rootsOf({2}), 3);
  EXPECT_EQ(tieLate.hit()->geometry, 3u);
  NearestHit tieEarly(INFINITE_DISTANCE);
  tieEarly.offer(rootsOf({2}), 3);
  tieEarly.offer(rootsOf({2}), 7);
  EXPECT_EQ(tieEarly.hit()->geometry, 3u);
  // TC12: a root exactly at tMax counts (inclusive)
  NearestHit atMax(2);
  atMax.offer(rootsOf({2}), 0);
  EXPECT_TRUE(atMax.hit().has_value());
}

TEST(HitRulesTests, visitHits) {
  std::vector<Hit> seen;
  auto collect = [&seen](const Hit& h) {
    seen.push_back(h);
    return true;
  };
  // TC01: every root within tMax is visited, ascending, with the shape's index
  EXPECT_TRUE(visitHits(rootsOf({3, 1}), 5, INFINITE_DISTANCE, collect));
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].t, 1.0);
  EXPECT_EQ(seen[1].t, 3.0);
  EXPECT_EQ(seen[1].geometry, 5u);
  // TC02: roots beyond tMax are not visited
  seen.clear();
  EXPECT_TRUE(visitHits(rootsOf({1, 3}), 0, 2, collect));
  EXPECT_EQ(seen.size(), 1u);
  // TC03: a visitor that stops: one visit, false returned
  int calls = 0;
  EXPECT_FALSE(visitHits(rootsOf({1, 3}), 0, INFINITE_DISTANCE, [&calls](const Hit&) {
    ++calls;
    return false;
  }));
  EXPECT_EQ(calls, 1);
  // TC11: a root exactly at tMax is visited
  seen.clear();
  EXPECT_TRUE(visitHits(rootsOf({1, 3}), 0, 3, collect));
  EXPECT_EQ(seen.size(), 2u);
}

}  // namespace
}  // namespace rt
