// Tests of the shadow query: the product of the blockers' kT along a shadow ray, its range and
// its early stop.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "RecordingShapes.h"
#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "geometries/Sphere.h"
#include "geometries/Triangle.h"
#include "intersections/Geometries.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"
#include "primitives/Double3.h"
#include "primitives/Ray.h"
#include "shadows/ShadowQuery.h"
#include "support/SameBits.h"
#include "support/TestRandom.h"

namespace rt {
namespace {

using test::sameBits;

constexpr double CUT_OFF = 0.001;

Material transparent(const Double3& kT) {
  Material m;
  m.kT = kT;
  return m;
}

/// A horizontal triangle at height z, around the z axis, with the given kT.
Triangle sheet(double z) { return Triangle(Point(-5, -5, z), Point(5, -5, z), Point(0, 5, z)); }

/// The shadow ray of every test: from the origin straight up (+z), the light at z = 100.
const Ray up(Point::ZERO, Vector(0, 0, 1));

Transmittance query(const LitScene& s, double tMin = 0, double tMax = 100,
                    const Double3& weight = Double3::ONE) {
  return ShadowQuery(s.geometries, s, CUT_OFF)(up, tMin, tMax, weight);
}

/// The scene's shapes, reporting the hits of forEachHit in the reverse of the linear scan's
/// order (the last shape first, each shape's crossings far to near): what an acceleration
/// structure may do.
class ReversedShapes final : public Intersectable {
 public:
  explicit ReversedShapes(const Geometries& g) : g_(g) {}
  std::optional<Hit> closestHit(const Ray& ray, double tMax,
                                QueryCounts* counts) const noexcept override {
    return g_.closestHit(ray, tMax, counts);
  }
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts) const override {
    std::vector<Hit> hits;
    g_.forEachHit(
        ray, tMax,
        [&](const Hit& h) {
          hits.push_back(h);
          return true;
        },
        counts);
    for (auto it = hits.rbegin(); it != hits.rend(); ++it)
      if (!visit(*it)) return false;
    return true;
  }

 private:
  const Geometries& g_;
};

/// A fixed list of hits, reported by forEachHit in the list's order (those in (0, tMax]):
/// duplicates and any order, as a structure that finds a shape in two places may report them.
class ListedHits final : public Intersectable {
 public:
  explicit ListedHits(std::vector<Hit> hits) : hits_(std::move(hits)) {}
  std::optional<Hit> closestHit(const Ray&, double tMax, QueryCounts*) const noexcept override {
    std::optional<Hit> best;
    for (const Hit& h : hits_)
      if (h.t > 0 && h.t <= tMax && (!best || h.t < best->t)) best = h;
    return best;
  }
  bool forEachHit(const Ray&, double tMax, HitVisitor visit, QueryCounts*) const override {
    for (const Hit& h : hits_)
      if (h.t > 0 && h.t <= tMax && !visit(h)) return false;
    return true;
  }

 private:
  std::vector<Hit> hits_;
};

TEST(ShadowQueryTests, blockers) {
  // ============ Equivalence Partitions Tests ==============
  {
    // TC01: nothing between the point and the light: fully lit
    LitScene s;
    s.add(sheet(-10), Color::BLACK, transparent(Double3(0)));  // below the point
    const Transmittance t = query(s);
    EXPECT_EQ(Double3::ONE, t.factor);
    EXPECT_EQ(0, t.crossings);
    EXPECT_FALSE(t.stoppedEarly);
  }
  {
    // TC02: an opaque blocker (kT = 0): fully shadowed, the walk stops at it
    LitScene s;
    s.add(sheet(50), Color::BLACK, transparent(Double3(0)));
    const Transmittance t = query(s);
    EXPECT_EQ(Double3::ZERO, t.factor);
    EXPECT_EQ(1, t.crossings);
    EXPECT_TRUE(t.stoppedEarly);
  }
  {
    // TC03: a triangle of kT 0.5 is crossed once: 0.5
    LitScene s;
    s.add(sheet(50), Color::BLACK, transparent(Double3(0.5)));
    const Transmittance t = query(s);
    EXPECT_EQ(0.5, t.factor.x);
    EXPECT_EQ(0.5, t.factor.y);
    EXPECT_EQ(0.5, t.factor.z);
    EXPECT_EQ(1, t.crossings);
  }
  {
    // TC04: a sphere of kT 0.5 is crossed twice (in and out), as in the course: 0.5² = 0.25
    LitScene s;
    s.add(Sphere(Point(0, 0, 50), 10), Color::BLACK, transparent(Double3(0.5)));
    const Transmittance t = query(s);
    EXPECT_EQ(Double3(0.25, 0.25, 0.25), t.factor);
    EXPECT_EQ(2, t.crossings);
  }
  {
    // TC05: per-channel kT, two blockers: (0.5,0.4,0.2)·(0.5,0.5,0.5) = (0.25,0.2,0.1)
    LitScene s;
    s.add(sheet(30), Color::BLACK, transparent(Double3(0.5, 0.4, 0.2)));
    s.add(sheet(60), Color::BLACK, transparent(Double3(0.5)));
    const Transmittance t = query(s);
    EXPECT_EQ(Double3(0.25, 0.2, 0.1), t.factor);
    EXPECT_EQ(2, t.crossings);
  }
  {
    // TC06: an opaque blocker beyond the light (z = 150 > 100) does not shadow
    LitScene s;
    s.add(sheet(150), Color::BLACK, transparent(Double3(0)));
    EXPECT_EQ(Double3::ONE, query(s).factor);
  }

  // =============== Boundary Values Tests ==================
  {
    // TC11: a blocker exactly at tMax counts (the range is inclusive, as the course's maxDistance)
    LitScene s;
    s.add(sheet(100), Color::BLACK, transparent(Double3(0)));
    EXPECT_EQ(Double3::ZERO, query(s).factor);
  }
  {
    // TC12: a blocker before tMin (within ε of the origin) is the surface itself: ignored
    LitScene s;
    s.add(sheet(1e-7), Color::BLACK, transparent(Double3(0)));
    EXPECT_EQ(Double3::ONE, query(s, 1e-6).factor);
  }
  {
    // TC13: an empty range (tMax < tMin, a light closer than 2ε): nothing in between
    LitScene s;
    s.add(sheet(50), Color::BLACK, transparent(Double3(0)));
    const Transmittance t = query(s, 1e-6, 1e-7);
    EXPECT_EQ(Double3::ONE, t.factor);
    EXPECT_EQ(0, t.crossings);
  }
  {
    // TC14: a directional light: the range has no end, a blocker far away shadows
    LitScene s;
    s.add(sheet(1e9), Color::BLACK, transparent(Double3(0)));
    EXPECT_EQ(Double3::ZERO, query(s, 0, INFINITE_DISTANCE).factor);
  }
}

TEST(ShadowQueryTests, earlyStop) {
  // ============ Equivalence Partitions Tests ==============
  {
    // TC01: a chain of 8 sheets of kT 0.2: 0.2^4 = 0.0016 goes on, 0.2^5 = 0.00032 < 0.001
    // stops: exactly 5 crossings are multiplied, the result is ZERO
    LitScene s;
    for (int i = 1; i <= 8; ++i) s.add(sheet(10.0 * i), Color::BLACK, transparent(Double3(0.2)));
    const Transmittance t = query(s);
    EXPECT_EQ(5, t.crossings);
    EXPECT_TRUE(t.stoppedEarly);
    EXPECT_EQ(Double3::ZERO, t.factor);
  }
  {
    // TC02: a chain of 9 opaque sheets: the first one found ends the walk
    LitScene s;
    for (int i = 1; i <= 9; ++i) s.add(sheet(10.0 * i), Color::BLACK, transparent(Double3(0)));
    const Transmittance t = query(s);
    EXPECT_EQ(1, t.crossings);
    EXPECT_TRUE(t.stoppedEarly);
  }
  {
    // TC03: the course's lowerThan needs all three channels below the cut-off: a red-only kT
    // of 0.9 keeps the walk going through all 9 sheets (0.9^9 = 0.387... in red)
    LitScene s;
    for (int i = 1; i <= 9; ++i) {
      s.add(sheet(10.0 * i), Color::BLACK, transparent(Double3(0.9, 0, 0)));
    }
    const Transmittance t = query(s);
    EXPECT_EQ(9, t.crossings);
    EXPECT_FALSE(t.stoppedEarly);
    EXPECT_NEAR(std::pow(0.9, 9), t.factor.x, 1e-15);
    EXPECT_EQ(0, t.factor.y);
    EXPECT_EQ(0, t.factor.z);
  }
  {
    // TC04: the path weight counts: kT 0.05 with weight 0.01 gives 5e-4 < 0.001: ZERO
    LitScene s;
    s.add(sheet(50), Color::BLACK, transparent(Double3(0.05)));
    s.add(sheet(70), Color::BLACK, transparent(Double3(0.5)));
    const Transmittance t = query(s, 0, 100, Double3(0.01));
    EXPECT_EQ(Double3::ZERO, t.factor);
    EXPECT_TRUE(t.stoppedEarly);
    EXPECT_EQ(Double3(0.05), query(s, 0, 60).factor);  // with weight 1 the same sheet: 0.05
  }

  // =============== Boundary Values Tests ==================
  {
    // TC11: kT 0.1 three times: 0.1·0.1·0.1 is 0.0010000000000000002 in doubles, not below
    // 0.001, so the walk goes on to the fourth sheet
    LitScene s;
    for (int i = 1; i <= 4; ++i) s.add(sheet(10.0 * i), Color::BLACK, transparent(Double3(0.1)));
    const Transmittance t = query(s);
    EXPECT_EQ(4, t.crossings);
    EXPECT_TRUE(t.stoppedEarly);
  }
}

TEST(ShadowQueryTests, sameBitsInAnyOrder) {
  // Three factors whose product depends on the order of multiplication in doubles:
  // (0.7·0.9)·0.45 = 0.28350000000000003 and (0.45·0.9)·0.7 = 0.2835.
  ASSERT_NE(0.7 * 0.9 * 0.45, 0.45 * 0.9 * 0.7);
  LitScene s;
  s.add(sheet(20), Color::BLACK, transparent(Double3(0.7)));
  s.add(sheet(40), Color::BLACK, transparent(Double3(0.9)));
  s.add(sheet(60), Color::BLACK, transparent(Double3(0.45)));
  const ReversedShapes reversed(s.geometries);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the linear scan and a walk in the reverse order give the same bits: the canonical
  // order (shape index, t), i.e. (0.7·0.9)·0.45
  const Transmittance forward = query(s);
  const Transmittance backward = ShadowQuery(reversed, s, CUT_OFF)(up, 0, 100, Double3::ONE);
  EXPECT_TRUE(sameBits(forward.factor, backward.factor));
  EXPECT_EQ(0.7 * 0.9 * 0.45, forward.factor.x);
  EXPECT_EQ(3, backward.crossings);
  // TC02: a sphere crossed twice and a sheet, in both orders
  LitScene t;
  t.add(sheet(70), Color::BLACK, transparent(Double3(0.3, 0.6, 0.9)));
  t.add(Sphere(Point(0, 0, 40), 10), Color::BLACK, transparent(Double3(0.7, 0.8, 0.9)));
  const ReversedShapes reversedT(t.geometries);
  EXPECT_TRUE(sameBits(query(t).factor,
                       ShadowQuery(reversedT, t, CUT_OFF)(up, 0, 100, Double3::ONE).factor));
  // =============== Boundary Values Tests ==================
  // TC11: more crossings than the query keeps on the stack (20 > CAPACITY = 16): the product is
  // still taken in the canonical order, found by repeated walks
  LitScene many;
  for (int i = 1; i <= 20; ++i)
    many.add(sheet(4.0 * i), Color::BLACK,
             transparent(Double3(0.99 - 0.002 * i, 0.98 - 0.001 * i, 0.97)));
  const ReversedShapes reversedMany(many.geometries);
  Double3 expected = Double3::ONE;
  for (int i = 1; i <= 20; ++i)
    expected = expected * Double3(0.99 - 0.002 * i, 0.98 - 0.001 * i, 0.97);
  const Transmittance a = query(many);
  const Transmittance b = ShadowQuery(reversedMany, many, CUT_OFF)(up, 0, 100, Double3::ONE);
  EXPECT_TRUE(sameBits(expected, a.factor));
  EXPECT_TRUE(sameBits(expected, b.factor));
  EXPECT_EQ(20, b.crossings);
  // TC12: the walks of the repeated search are counted: more shape tests than one walk's
  QueryCounts one, repeated;
  (void)ShadowQuery(many.geometries, s, 0)(Ray(Point(100, 100, 0), Vector(0, 0, 1)), 0, 100,
                                           Double3::ONE, &one);
  (void)ShadowQuery(many.geometries, many, CUT_OFF)(up, 0, 100, Double3::ONE, &repeated);
  EXPECT_EQ(20u, one.shapeTests);
  EXPECT_EQ(20u * 22u, repeated.shapeTests);  // the first walk, 20 searches, one that finds none
}

TEST(ShadowQueryTests, brighteningBlockersNeverStopEarly) {
  // A kT above 1 (allowed: a coefficient is any non-negative number) could raise the product
  // again, so no partial product may cut the light: only the final one decides.
  LitScene s;
  s.add(sheet(20), Color::BLACK, transparent(Double3(0.0005)));
  s.add(sheet(40), Color::BLACK, transparent(Double3(4)));
  // ============ Equivalence Partitions Tests ==============
  // TC01: 0.0005·4 = 0.002 is above the cut-off: the light passes, at 0.002
  const Transmittance t = query(s);
  EXPECT_FALSE(t.stoppedEarly);
  EXPECT_EQ(2, t.crossings);
  EXPECT_EQ(Double3(0.002), t.factor);
  // =============== Boundary Values Tests ==================
  // TC11: the same first sheet alone is below the cut-off: cut (after the whole walk)
  LitScene dim;
  dim.add(sheet(20), Color::BLACK, transparent(Double3(0.0005)));
  dim.add(sheet(40), Color::BLACK, transparent(Double3(1.5)));
  const Transmittance d = query(dim);
  EXPECT_EQ(Double3::ZERO, d.factor);
  EXPECT_FALSE(d.stoppedEarly);
}

/// Π kT of the hits in [tMin, tMax] in the canonical order, worked out here: the hits sorted by
/// (shape, t), their kT multiplied left to right.
Double3 canonicalByHand(const LitScene& s, std::vector<Hit> hits, double tMin, double tMax) {
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return a.geometry != b.geometry ? a.geometry < b.geometry : a.t < b.t;
  });
  Double3 product = Double3::ONE;
  for (const Hit& h : hits)
    if (h.t >= tMin && h.t <= tMax) product = product * s.appearanceOf(h.geometry).material.kT;
  return product;
}

TEST(ShadowQueryTests, beyondCapacityInAnyOrder) {
  // 20 shapes of slightly different kT, shape i crossed at t = 4(i + 1); shape 3 crossed a
  // second time (t = 13) and shape 7's crossing reported twice (the same t), as a structure
  // holding a shape in two places may: 22 crossings, more than CAPACITY = 16.
  LitScene s;
  for (int i = 0; i < 20; ++i)
    s.add(sheet(4.0 * (i + 1)), Color::BLACK,
          transparent(Double3(0.99 - 0.002 * i, 0.98 - 0.001 * i, 0.97 + 0.0005 * i)));
  std::vector<Hit> hits;
  for (std::uint32_t i = 0; i < 20; ++i) hits.push_back(Hit{4.0 * (i + 1), i});
  hits.push_back(Hit{13, 3});
  hits.push_back(Hit{32, 7});
  const Double3 expected = canonicalByHand(s, hits, 0, 100);
  test::TestRandom shuffler(2026);
  // ============ Equivalence Partitions Tests ==============
  // TC01: eight orders of the 22 crossings: the repeated search gives the canonical product,
  // the duplicate counted twice, every time (and the orders' own products differ from it)
  bool someOrderDiffers = false;
  for (int round = 0; round < 8; ++round) {
    shuffler.shuffle(hits.begin(), hits.end());
    Double3 walkOrder = Double3::ONE;
    for (const Hit& h : hits) walkOrder = walkOrder * s.appearanceOf(h.geometry).material.kT;
    someOrderDiffers = someOrderDiffers || !sameBits(walkOrder, expected);
    const ListedHits listed(hits);
    const Transmittance t = ShadowQuery(listed, s, CUT_OFF)(up, 0, 100, Double3::ONE);
    EXPECT_TRUE(sameBits(expected, t.factor)) << round;
    EXPECT_EQ(22, t.crossings) << round;
    EXPECT_FALSE(t.stoppedEarly) << round;
  }
  EXPECT_TRUE(someOrderDiffers);
  // TC02: hits before tMin (a shape 0 hit at t = 0.5, tMin = 1) join neither walk's product
  std::vector<Hit> withNear = hits;
  withNear.push_back(Hit{0.5, 0});
  const ListedHits near(withNear);
  const Transmittance n = ShadowQuery(near, s, CUT_OFF)(up, 1, 100, Double3::ONE);
  EXPECT_TRUE(sameBits(expected, n.factor));
  EXPECT_EQ(22, n.crossings);

  // =============== Boundary Values Tests ==================
  // TC11: CAPACITY crossings (kept on the stack) and CAPACITY + 1 (searched anew), each with the
  // duplicate, found far to near: both the canonical product worked out by hand
  for (const int count : {ShadowQuery::CAPACITY, ShadowQuery::CAPACITY + 1}) {
    std::vector<Hit> some;
    for (std::uint32_t i = 0; static_cast<int>(some.size()) < count - 1; ++i)
      some.push_back(Hit{4.0 * (i + 1), i});
    some.push_back(Hit{32, 7});
    std::reverse(some.begin(), some.end());
    const ListedHits listed(some);
    const Transmittance t = ShadowQuery(listed, s, CUT_OFF)(up, 0, 100, Double3::ONE);
    EXPECT_TRUE(sameBits(canonicalByHand(s, some, 0, 100), t.factor)) << count;
    EXPECT_EQ(count, t.crossings);
  }
}

TEST(ShadowQueryTests, cutOffMargin) {
  const double stopBelow = CUT_OFF * (1 - ShadowQuery::MARGIN);
  // =============== Boundary Values Tests ==================
  // TC11: a product within the margin, below the cut-off but not below cutOff·(1 − MARGIN): the
  // walk is not stopped, the final product is cut (ZERO)
  {
    LitScene s;
    s.add(sheet(50), Color::BLACK, transparent(Double3(CUT_OFF * (1 - ShadowQuery::MARGIN / 2))));
    const Transmittance t = query(s);
    EXPECT_EQ(Double3::ZERO, t.factor);
    EXPECT_FALSE(t.stoppedEarly);
    EXPECT_EQ(1, t.crossings);
  }
  // TC12: the next double below cutOff·(1 − MARGIN): the walk stops at it
  {
    LitScene s;
    s.add(sheet(50), Color::BLACK, transparent(Double3(std::nextafter(stopBelow, 0.0))));
    s.add(sheet(60), Color::BLACK, transparent(Double3(0.5)));
    const Transmittance t = query(s);
    EXPECT_EQ(Double3::ZERO, t.factor);
    EXPECT_TRUE(t.stoppedEarly);
    EXPECT_EQ(1, t.crossings);
  }
  // TC13: the cut-off itself is not below the cut-off: the light passes at 0.001
  {
    LitScene s;
    s.add(sheet(50), Color::BLACK, transparent(Double3(CUT_OFF)));
    const Transmittance t = query(s);
    EXPECT_TRUE(sameBits(Double3(CUT_OFF), t.factor));
    EXPECT_FALSE(t.stoppedEarly);
  }
}

/*
 * The scene of the LightOccluders tests, along the ray `up` (from the origin along +z):
 *
 *   z = 80   opaque sheet (triangle, kT 0)
 *   z = 60   square (polygon), kT (0.45,0.7,0.9)
 *   z = 35, 45  sphere of radius 5 at z = 40, kT (0.9,0.45,0.7), crossed twice
 *   z = 20   sheet (triangle), kT (0.7,0.9,0.45)
 *
 * Towards a light at z = 70 the factor is k0·k1·k1·k2; at z = 100 the opaque sheet cuts it.
 */
LitScene occludersScene() {
  LitScene s;
  s.add(sheet(20), Color::BLACK, transparent(Double3(0.7, 0.9, 0.45)));
  s.add(Sphere(Point(0, 0, 40), 5), Color::BLACK, transparent(Double3(0.9, 0.45, 0.7)));
  s.add(Polygon{Point(-5, -5, 60), Point(5, -5, 60), Point(5, 5, 60), Point(-5, 5, 60)},
        Color::BLACK, transparent(Double3(0.45, 0.7, 0.9)));
  s.add(sheet(80), Color::BLACK, transparent(Double3(0)));
  return s;
}

TEST(ShadowQueryTests, lightOccludersSeam) {
  using test::CountingShapes;
  using test::RecordingOccluders;
  const LitScene s = occludersScene();
  const Double3 k0(0.7, 0.9, 0.45), k1(0.9, 0.45, 0.7), k2(0.45, 0.7, 0.9);
  const Double3 expected = k0 * k1 * k1 * k2;
  const ShadowQuery plain(s.geometries, s, CUT_OFF);
  const Transmittance reference = plain(up, 0, 70, Double3::ONE);
  ASSERT_TRUE(sameBits(expected, reference.factor));
  ASSERT_EQ(4, reference.crossings);
  const RecordingOccluders occluders(s.geometries);
  const ShadowQuery seam(occluders, s, CUT_OFF);

  // ============ Equivalence Partitions Tests ==============
  // TC01: a ray aimed at light 0 goes through crossingsTowards with light 0, never forEachHit;
  // the same bits as the linear scan, and the walk's cost reaches the counts it is given
  QueryCounts counts;
  const Transmittance t0 = seam(up, 0, 70, Double3::ONE, &counts, 0);
  EXPECT_TRUE(sameBits(reference.factor, t0.factor));
  EXPECT_EQ(4, t0.crossings);
  EXPECT_EQ(std::vector<std::uint32_t>{0}, occluders.lights);
  EXPECT_EQ(0, occluders.forEachHitCalls);
  EXPECT_EQ(4u, counts.shapeTests);
  // TC02: a ray aimed at light 1: light 1 is asked for
  const Transmittance t1 = seam(up, 0, 70, Double3::ONE, nullptr, 1);
  EXPECT_TRUE(sameBits(reference.factor, t1.factor));
  EXPECT_EQ((std::vector<std::uint32_t>{0, 1}), occluders.lights);
  EXPECT_EQ(0, occluders.forEachHitCalls);
  // TC03: the opaque sheet in the range: ZERO, stopped early, through the occluders as well
  const Transmittance cut = seam(up, 0, 100, Double3::ONE, nullptr, 1);
  EXPECT_EQ(Double3::ZERO, cut.factor);
  EXPECT_TRUE(cut.stoppedEarly);
  EXPECT_EQ(Double3::ZERO, plain(up, 0, 100, Double3::ONE).factor);
  EXPECT_EQ(3u, occluders.lights.size());
  // TC04: a ray aimed at no light (NO_LIGHT, the default) walks the shapes with forEachHit
  const Transmittance none = seam(up, 0, 70, Double3::ONE);
  EXPECT_TRUE(sameBits(reference.factor, none.factor));
  EXPECT_EQ(1, occluders.forEachHitCalls);
  EXPECT_EQ(3u, occluders.lights.size());
  // TC05: shapes that are no LightOccluders are walked with forEachHit, whatever the light
  const CountingShapes counting(s.geometries);
  const Transmittance walked =
      ShadowQuery(counting, s, CUT_OFF)(up, 0, 70, Double3::ONE, nullptr, 1);
  EXPECT_TRUE(sameBits(reference.factor, walked.factor));
  EXPECT_EQ(1, counting.forEachHitCalls);
  // TC06: the flat shapes' crossings handed over at another t of [tMin, tMax] (the contract
  // allows it: the triangle's and the polygon's): the same factor, bit for bit, and the same
  // answer when the opaque sheet is in the range
  for (const test::FlatT flat :
       {test::FlatT::AT_T_MIN, test::FlatT::AT_T_MAX, test::FlatT::MIDDLE}) {
    const RecordingOccluders moved(s.geometries, flat);
    const ShadowQuery q(moved, s, CUT_OFF);
    const Transmittance t = q(up, 1e-6, 70, Double3::ONE, nullptr, 0);
    EXPECT_TRUE(sameBits(expected, t.factor)) << static_cast<int>(flat);
    EXPECT_EQ(4, t.crossings) << static_cast<int>(flat);
    const Transmittance c = q(up, 1e-6, 100, Double3::ONE, nullptr, 0);
    EXPECT_EQ(Double3::ZERO, c.factor) << static_cast<int>(flat);
    EXPECT_TRUE(c.stoppedEarly) << static_cast<int>(flat);
    EXPECT_EQ(0, moved.forEachHitCalls);
  }
  // TC07: the cut-off reached through the occluders, flat shapes moved: 8 sheets of kT 0.2 stop
  // the walk at the fifth crossing, as the linear scan does
  LitScene chain;
  for (int i = 1; i <= 8; ++i) chain.add(sheet(10.0 * i), Color::BLACK, transparent(Double3(0.2)));
  const RecordingOccluders chainOccluders(chain.geometries, test::FlatT::MIDDLE);
  const Transmittance stopped =
      ShadowQuery(chainOccluders, chain, CUT_OFF)(up, 0, 100, Double3::ONE, nullptr, 2);
  EXPECT_EQ(Double3::ZERO, stopped.factor);
  EXPECT_TRUE(stopped.stoppedEarly);
  EXPECT_EQ(5, stopped.crossings);

  // =============== Boundary Values Tests ==================
  // TC11: an empty range (tMax < tMin): nothing is asked of the shapes at all
  const Transmittance empty = seam(up, 1e-6, 1e-7, Double3::ONE, nullptr, 0);
  EXPECT_EQ(Double3::ONE, empty.factor);
  EXPECT_EQ(3u, occluders.lights.size());
  EXPECT_EQ(1, occluders.forEachHitCalls);
  // TC12: more crossings than CAPACITY through the occluders: one crossingsTowards, then the
  // canonical search walks the shapes with forEachHit (20 searches and one that finds none),
  // and the product is the canonical one
  LitScene many;
  for (int i = 1; i <= 20; ++i)
    many.add(sheet(4.0 * i), Color::BLACK,
             transparent(Double3(0.99 - 0.002 * i, 0.98 - 0.001 * i, 0.97)));
  const RecordingOccluders manyOccluders(many.geometries);
  const Transmittance m =
      ShadowQuery(manyOccluders, many, CUT_OFF)(up, 0, 100, Double3::ONE, nullptr, 4);
  Double3 manyExpected = Double3::ONE;
  for (int i = 1; i <= 20; ++i)
    manyExpected = manyExpected * Double3(0.99 - 0.002 * i, 0.98 - 0.001 * i, 0.97);
  EXPECT_TRUE(sameBits(manyExpected, m.factor));
  EXPECT_EQ(20, m.crossings);
  EXPECT_EQ(std::vector<std::uint32_t>{4}, manyOccluders.lights);
  EXPECT_EQ(21, manyOccluders.forEachHitCalls);
}

}  // namespace
}  // namespace rt
