// Tests of ShadowCrossings: one shadow ray's crossings handed over by a walk in any order, their
// product in the canonical order (shape index, t), the early stops (an opaque blocker, the
// cut-off with its margin), the hits before tMin, and the crossings beyond CAPACITY.
//
// The hits are made by hand (Hit{t, shape}); only the scene's looks are read (kT of shape i).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <vector>

#include "geometries/Sphere.h"
#include "intersections/Intersectable.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"
#include "primitives/Double3.h"
#include "shadows/ShadowCrossings.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;

constexpr double CUT_OFF = 0.001;
constexpr double T_MIN = 1e-6;
/// ShadowCrossings keeps a reference to the path weight: these outlive every test.
const Double3 UNIT_WEIGHT = Double3::ONE;

Material transparent(const Double3& kT) {
  Material m;
  m.kT = kT;
  return m;
}

/// A scene whose shape i has kT kTs[i] (the shapes are never intersected).
LitScene withKT(const std::vector<Double3>& kTs) {
  LitScene s;
  for (const Double3& k : kTs) s.add(Sphere(Point::ZERO, 1), Color::BLACK, transparent(k));
  return s;
}

std::array<std::uint64_t, 3> bitsOf(const Double3& a) {
  std::array<std::uint64_t, 3> bits;
  std::memcpy(bits.data(), &a, sizeof a);
  return bits;
}

TEST(ShadowCrossingsTests, sameBitsInEveryOrder) {
  const std::vector<Double3> k = {{0.7, 0.93, 0.61},
                                  {0.9, 0.45, 0.77},
                                  {0.45, 0.7, 0.83},
                                  {0.33, 0.81, 0.9},
                                  {0.61, 0.57, 0.3}};
  const LitScene s = withKT(k);
  // Six crossings whose order along the ray is not the shapes' order; shape 2 (a sphere) is
  // crossed twice.
  const std::vector<Hit> hits = {{5, 3}, {12, 2}, {18, 2}, {25, 0}, {31, 4}, {40, 1}};
  // The canonical order written out: by shape, then t, multiplied left to right.
  const Double3 expected = k[0] * k[1] * k[2] * k[2] * k[3] * k[4];
  // The test has teeth: the order along the ray gives other bits, and so do some of the orders
  // a walk may find the hits in.
  ASSERT_FALSE(sameBits(expected, k[3] * k[2] * k[2] * k[0] * k[4] * k[1]));
  std::vector<int> order = {0, 1, 2, 3, 4, 5};
  std::set<std::array<std::uint64_t, 3>> walkOrderProducts;
  do {
    Double3 p = Double3::ONE;
    for (int i : order) p = p * k[hits[i].geometry];
    walkOrderProducts.insert(bitsOf(p));
  } while (std::next_permutation(order.begin(), order.end()));
  ASSERT_GT(walkOrderProducts.size(), 1u);

  // ============ Equivalence Partitions Tests ==============
  // TC01: all 720 orders of the six hits, with the cut-off allowed to stop early (every kT at
  // most 1) and not: every add goes on, six crossings, none lost, the same bits every time
  for (const bool productOnlyFalls : {true, false}) {
    int orders = 0, wrong = 0;
    std::sort(order.begin(), order.end());
    do {
      ShadowCrossings c(s, CUT_OFF, productOnlyFalls, T_MIN, UNIT_WEIGHT);
      bool goOn = true;
      for (int i : order) goOn = c.add(hits[i]) && goOn;
      const Double3 product = c.product();
      if (!goOn || c.count() != 6 || c.stoppedEarly() || c.overflow() ||
          !sameBits(expected, product)) {
        if (wrong++ == 0)
          ADD_FAILURE() << "productOnlyFalls " << productOnlyFalls
                        << ", first wrong order: " << product.str() << " instead of "
                        << expected.str();
      }
      ++orders;
    } while (std::next_permutation(order.begin(), order.end()));
    EXPECT_EQ(720, orders);
    EXPECT_EQ(0, wrong) << "productOnlyFalls " << productOnlyFalls;
  }

  // =============== Boundary Values Tests ==================
  // TC11: no crossing at all: the product is exactly (1,1,1)
  ShadowCrossings none(s, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
  EXPECT_TRUE(sameBits(Double3::ONE, none.product()));
  EXPECT_EQ(0, none.count());
  // TC12: the same shape crossed twice at the same t (a hit reported twice) counts twice
  ShadowCrossings twice(s, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
  EXPECT_TRUE(twice.add(Hit{7, 1}));
  EXPECT_TRUE(twice.add(Hit{7, 1}));
  EXPECT_TRUE(sameBits(k[1] * k[1], twice.product()));
  EXPECT_EQ(2, twice.count());
}

TEST(ShadowCrossingsTests, canonicalOrder) {
  using C = ShadowCrossings::Crossing;
  // ============ Equivalence Partitions Tests ==============
  // TC01: a smaller shape index comes first, whatever the t
  EXPECT_TRUE(ShadowCrossings::before(C{0, 50}, C{1, 5}));
  EXPECT_FALSE(ShadowCrossings::before(C{1, 5}, C{0, 50}));
  // TC02: the same shape: the smaller t first
  EXPECT_TRUE(ShadowCrossings::before(C{2, 5}, C{2, 6}));
  EXPECT_FALSE(ShadowCrossings::before(C{2, 6}, C{2, 5}));
  // =============== Boundary Values Tests ==================
  // TC11: the same crossing is not before itself (a strict order)
  EXPECT_FALSE(ShadowCrossings::before(C{2, 5}, C{2, 5}));
}

TEST(ShadowCrossingsTests, opaqueBlocker) {
  const LitScene s = withKT({Double3(0.7), Double3(0), Double3(0.5), Double3(0, 0.5, 0.5)});
  // ============ Equivalence Partitions Tests ==============
  // TC01: a crossing of kT 0.7, then an opaque one (kT 0): add says stop at the opaque one
  {
    ShadowCrossings c(s, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    EXPECT_TRUE(c.add(Hit{5, 0}));
    EXPECT_FALSE(c.stoppedEarly());
    EXPECT_FALSE(c.add(Hit{10, 1}));
    EXPECT_TRUE(c.stoppedEarly());
    EXPECT_EQ(2, c.count());
  }
  // TC02: an opaque blocker stops even when the cut-off may not (some kT above 1), and first
  {
    ShadowCrossings c(s, CUT_OFF, false, T_MIN, UNIT_WEIGHT);
    EXPECT_FALSE(c.add(Hit{30, 1}));
    EXPECT_TRUE(c.stoppedEarly());
    EXPECT_EQ(1, c.count());
  }
  // =============== Boundary Values Tests ==================
  // TC11: opaque in one channel only, (0,0.5,0.5), is no blocker: the walk goes on, and with
  // productOnlyFalls the partial product (0,0.5,0.5) is not below the cut-off in every channel
  for (const bool productOnlyFalls : {true, false}) {
    ShadowCrossings c(s, CUT_OFF, productOnlyFalls, T_MIN, UNIT_WEIGHT);
    EXPECT_TRUE(c.add(Hit{5, 3}));
    EXPECT_TRUE(c.add(Hit{6, 2}));
    EXPECT_FALSE(c.stoppedEarly());
    EXPECT_TRUE(sameBits(Double3(0, 0.25, 0.25), c.product()));
  }
  // TC12: an opaque hit before tMin (the surface itself) is ignored
  {
    ShadowCrossings c(s, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    EXPECT_TRUE(c.add(Hit{T_MIN / 2, 1}));
    EXPECT_FALSE(c.stoppedEarly());
    EXPECT_EQ(0, c.count());
    EXPECT_TRUE(sameBits(Double3::ONE, c.product()));
  }
}

TEST(ShadowCrossingsTests, hitsBeforeTMin) {
  const LitScene s = withKT({Double3(0.5), Double3(0.3, 0.6, 0.9), Double3(0.7)});
  // ============ Equivalence Partitions Tests ==============
  // TC01: hits before tMin are ignored: add goes on, nothing is counted, the product unchanged
  ShadowCrossings c(s, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
  EXPECT_TRUE(c.add(Hit{T_MIN / 10, 0}));
  EXPECT_TRUE(c.add(Hit{20, 1}));
  EXPECT_TRUE(c.add(Hit{T_MIN / 2, 2}));
  EXPECT_EQ(1, c.count());
  EXPECT_TRUE(sameBits(Double3(0.3, 0.6, 0.9), c.product()));
  // =============== Boundary Values Tests ==================
  // TC11: a hit exactly at tMin is a crossing; the largest t below it is not
  ShadowCrossings at(s, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
  EXPECT_TRUE(at.add(Hit{std::nextafter(T_MIN, 0.0), 2}));
  EXPECT_EQ(0, at.count());
  EXPECT_TRUE(at.add(Hit{T_MIN, 0}));
  EXPECT_EQ(1, at.count());
  EXPECT_TRUE(sameBits(Double3(0.5), at.product()));
}

TEST(ShadowCrossingsTests, cutOff) {
  const double stopBelow = CUT_OFF * (1 - ShadowCrossings::MARGIN);
  // ============ Equivalence Partitions Tests ==============
  // TC01: kT 0.2 again and again: 0.2^4 = 0.0016 goes on, 0.2^5 = 0.00032 < 0.001 stops
  const LitScene fifth = withKT(std::vector<Double3>(8, Double3(0.2)));
  {
    ShadowCrossings c(fifth, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    for (std::uint32_t i = 0; i < 4; ++i) EXPECT_TRUE(c.add(Hit{10.0 + i, i})) << i;
    EXPECT_FALSE(c.add(Hit{14, 4}));
    EXPECT_TRUE(c.stoppedEarly());
    EXPECT_EQ(5, c.count());
  }
  // TC02: without productOnlyFalls (a kT above 1 somewhere) a partial product never stops the
  // walk: all eight go on, and the product is 0.2^8 in the canonical order
  {
    ShadowCrossings c(fifth, CUT_OFF, false, T_MIN, UNIT_WEIGHT);
    for (std::uint32_t i = 8; i-- > 0;) EXPECT_TRUE(c.add(Hit{10.0 + i, i})) << i;
    EXPECT_FALSE(c.stoppedEarly());
    EXPECT_EQ(8, c.count());
    Double3 expected = Double3::ONE;
    for (int i = 0; i < 8; ++i) expected = expected * Double3(0.2);
    EXPECT_TRUE(sameBits(expected, c.product()));
  }
  // TC03: the path weight counts: kT 0.05 times a weight of 0.01 is 5e-4: stop; weight 1 not
  const LitScene dim = withKT({Double3(0.05)});
  {
    const Double3 weight(0.01);
    ShadowCrossings c(dim, CUT_OFF, true, T_MIN, weight);
    EXPECT_FALSE(c.add(Hit{10, 0}));
    EXPECT_TRUE(c.stoppedEarly());
    ShadowCrossings one(dim, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    EXPECT_TRUE(one.add(Hit{10, 0}));
    EXPECT_FALSE(one.stoppedEarly());
  }
  // TC04: the course's lowerThan needs every channel below: (1e-4,1e-4,0.5) goes on
  {
    const LitScene blue = withKT({Double3(1e-4, 1e-4, 0.5)});
    ShadowCrossings c(blue, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    EXPECT_TRUE(c.add(Hit{10, 0}));
    EXPECT_FALSE(c.stoppedEarly());
  }

  // =============== Boundary Values Tests ==================
  // TC11: a product of exactly cutOff·(1 − MARGIN) is not below it: go on; the next double
  // below it stops
  {
    const LitScene at = withKT({Double3(stopBelow), Double3(std::nextafter(stopBelow, 0.0))});
    ShadowCrossings c(at, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    EXPECT_TRUE(c.add(Hit{10, 0}));
    EXPECT_FALSE(c.stoppedEarly());
    ShadowCrossings below(at, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    EXPECT_FALSE(below.add(Hit{10, 1}));
    EXPECT_TRUE(below.stoppedEarly());
  }
  // TC12: within the margin (the cut-off itself, and half a margin below it): the walk goes on;
  // the final product decides (ShadowQuery cuts below cutOff, ShadowQueryTests)
  for (const double kT : {CUT_OFF, CUT_OFF * (1 - ShadowCrossings::MARGIN / 2)}) {
    const LitScene near = withKT({Double3(kT)});
    ShadowCrossings c(near, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    EXPECT_TRUE(c.add(Hit{10, 0})) << kT;
    EXPECT_FALSE(c.stoppedEarly()) << kT;
    EXPECT_TRUE(sameBits(Double3(kT), c.product())) << kT;
  }
  // TC13: the weighted product exactly at the stop goes on: kT 1, weight cutOff·(1 − MARGIN)
  {
    const LitScene clear = withKT({Double3(1)});
    const Double3 weight(stopBelow);
    ShadowCrossings c(clear, CUT_OFF, true, T_MIN, weight);
    EXPECT_TRUE(c.add(Hit{10, 0}));
    const Double3 lower(std::nextafter(stopBelow, 0.0));
    ShadowCrossings d(clear, CUT_OFF, true, T_MIN, lower);
    EXPECT_FALSE(d.add(Hit{10, 0}));
  }
}

TEST(ShadowCrossingsTests, capacity) {
  // CAPACITY + 1 shapes of slightly different kT (so that the order of the product matters)
  constexpr int N = ShadowCrossings::CAPACITY + 1;
  std::vector<Double3> k;
  for (int i = 0; i < N; ++i) k.emplace_back(0.99 - 0.003 * i, 0.97 - 0.002 * i, 0.95 + 0.001 * i);
  const LitScene s = withKT(k);
  // ============ Equivalence Partitions Tests ==============
  // TC01: CAPACITY crossings, found far to near: all kept, the product in the canonical order
  {
    ShadowCrossings c(s, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    for (int i = ShadowCrossings::CAPACITY; i-- > 0;)
      EXPECT_TRUE(c.add(Hit{1.0 + i, static_cast<std::uint32_t>(i)}));
    EXPECT_FALSE(c.overflow());
    EXPECT_EQ(ShadowCrossings::CAPACITY, c.count());
    Double3 expected = Double3::ONE;
    for (int i = 0; i < ShadowCrossings::CAPACITY; ++i) expected = expected * k[i];
    EXPECT_TRUE(sameBits(expected, c.product()));
  }
  // =============== Boundary Values Tests ==================
  // TC11: one crossing more than CAPACITY: the walk goes on (add true), every crossing is
  // counted, and overflow says the product lacks some (ShadowQuery then searches them anew)
  {
    ShadowCrossings c(s, CUT_OFF, true, T_MIN, UNIT_WEIGHT);
    for (int i = 0; i < N; ++i) {
      EXPECT_TRUE(c.add(Hit{1.0 + i, static_cast<std::uint32_t>(i)}));
      EXPECT_EQ(i == N - 1, c.overflow()) << i;
    }
    EXPECT_EQ(N, c.count());
    EXPECT_FALSE(c.stoppedEarly());
  }
  // TC12: an opaque blocker after an overflow still decides the answer
  {
    std::vector<Double3> more = k;
    more.push_back(Double3(0));
    const LitScene t = withKT(more);
    ShadowCrossings c(t, CUT_OFF, false, T_MIN, UNIT_WEIGHT);
    for (int i = 0; i < N; ++i) c.add(Hit{1.0 + i, static_cast<std::uint32_t>(i)});
    EXPECT_FALSE(c.add(Hit{100, static_cast<std::uint32_t>(N)}));
    EXPECT_TRUE(c.stoppedEarly());
  }
}

}  // namespace
}  // namespace rt
