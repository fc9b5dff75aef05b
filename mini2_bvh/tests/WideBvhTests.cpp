// mini2: the wide BVH. The float box test never loses a box that the double test keeps
// (FloatRay.h's claim, on random and on touching rays), the directed roundings it is built on,
// and the collapse: every binary leaf once, boxes kept, the slots in order, and what it saves
// in nodes visited. The answers themselves are EquivalenceTests' and TilePoolTests' (the same
// bits as the linear scan, on every scene and thread count).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "bvh/Bvh.h"
#include "bvh/FloatRay.h"
#include "bvh/SlabRay.h"
#include "bvh/WideBvh.h"
#include "camera/Camera.h"
#include "geometries/UtahTeapot.h"
#include "glossy/Galaxy.h"
#include "support/AllocationCounter.h"

#include "RandomScenes.h"

namespace rt {
namespace {

constexpr float FMAX = std::numeric_limits<float>::max();
constexpr float FINF = std::numeric_limits<float>::infinity();

/// The reference for floatBelow: the nearest float, stepped down with std::nextafter when above.
float slowBelow(double x) {
  if (x >= FMAX) return FMAX;
  if (x < -FMAX) return -FINF;
  const auto f = static_cast<float>(x);
  return f > x ? std::nextafter(f, -FINF) : f;
}

TEST(WideBvhTests, directedRoundings) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: random doubles of every magnitude and sign: floatBelow is the largest float <= x,
  // floatAbove the smallest >= x, as the library's nextafter finds them
  test::Random random(31);
  for (int i = 0; i < 20000; ++i) {
    const double mantissa = random.uniform(-1, 1);
    const double x = mantissa * std::ldexp(1.0, random.integer(-160, 140));
    ASSERT_EQ(floatBelow(x), slowBelow(x)) << x;
    ASSERT_EQ(floatAbove(x), -slowBelow(-x)) << x;
    ASSERT_LE(floatBelow(x), x);
    ASSERT_GE(floatAbove(x), x);
  }
  // =============== Boundary Values Tests ==================
  // TC11: floats are their own roundings; ±0; the smallest subnormal's half on both sides;
  // the float range's ends and beyond
  EXPECT_EQ(floatBelow(1.5), 1.5f);
  EXPECT_EQ(floatAbove(-2.0), -2.0f);
  EXPECT_EQ(floatBelow(0.0), 0.0f);
  EXPECT_EQ(floatAbove(0.0), 0.0f);
  const float tiny = std::numeric_limits<float>::denorm_min();
  EXPECT_EQ(floatBelow(-1e-50), -tiny);
  EXPECT_EQ(floatAbove(1e-50), tiny);
  EXPECT_EQ(floatBelow(1e-50), 0.0f);
  EXPECT_EQ(floatBelow(0.1), 0.099999994f);  // 0.1f = 0.100000001490116... is above 0.1
  EXPECT_EQ(floatAbove(0.1), 0.1f);
  EXPECT_EQ(floatBelow(1e39), FMAX);
  EXPECT_EQ(floatAbove(1e39), FINF);
  EXPECT_EQ(floatBelow(-1e39), -FINF);
  EXPECT_EQ(floatAbove(-1e39), -FMAX);
  EXPECT_EQ(floatAbove(static_cast<double>(FMAX)), FMAX);
}

/// The float test of one box by a lone ray, as the wide walk does it lane by lane.
bool floatHit(const FloatRay& r, const FloatBox& box, float limit, float& entry) {
  float tNear = 0, tFar = limit;
  for (int a = 0; a < 3; ++a) {
    const float nearB = r.negative[a] ? box.hi[a] : box.lo[a];
    const float farB = r.negative[a] ? box.lo[a] : box.hi[a];
    const float tIn = (nearB - r.originIn[a]) * r.invIn[a];
    const float tOut = (farB - r.originOut[a]) * r.invOut[a];
    tNear = tIn > tNear ? tIn : tNear;
    tFar = tOut < tFar ? tOut : tFar;
  }
  entry = tNear;
  return tNear <= tFar;
}

/// The exact test, in long double with the box widened by 1e-12 of its scale: a box that the
/// real-number test hits is hit here too (long double's rounding is far inside the widening).
bool wideExactHit(const Ray& ray, const FloatBox& box, double tMax) {
  long double tNear = 0, tFar = tMax;
  const Double3& o = ray.head().xyz();
  const Double3& d = ray.direction().xyz();
  const double oa[3] = {o.x, o.y, o.z}, da[3] = {d.x, d.y, d.z};
  for (int a = 0; a < 3; ++a) {
    const long double pad =
        1e-12L * std::max(1.0L, std::abs(static_cast<long double>(box.hi[a])) +
                                    std::abs(static_cast<long double>(box.lo[a])));
    const long double lo = box.lo[a] - pad, hi = box.hi[a] + pad;
    if (da[a] == 0) {
      if (oa[a] < lo || oa[a] > hi) return false;
      continue;
    }
    long double t0 = (lo - oa[a]) / da[a], t1 = (hi - oa[a]) / da[a];
    if (t0 > t1) std::swap(t0, t1);
    tNear = std::max(tNear, t0);
    tFar = std::min(tFar, t1);
  }
  return tNear <= tFar;
}

TEST(WideBvhTests, floatBoxTestIsConservative) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: random float boxes and rays (from outside, from inside, axis-parallel, tMax finite
  // and infinite): whenever the double slab test of the binary BVH says hit, so does the float
  // test, entering no later than the double entry (rounded up to float); and it says hit for
  // every box that the exact test hits with a margin (long double, box widened by 1e-12)
  test::Random random(47);
  int doubleHits = 0, floatOnly = 0;
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::ldexp(1.0, random.integer(-20, 40));
    const Double3 c = random.inCube(-1, 1) * scale;
    const Double3 e = random.inCube(0, 1) * scale * 0.3;
    const FloatBox box = FloatBox::enclosing(Aabb(c - e, c + e));
    Double3 origin = random.inBox(Aabb(Double3(-2 * scale), Double3(2 * scale)));
    Double3 dir = random.direction();
    switch (i % 4) {
      case 1:
        dir = Double3(0, 0, random.chance(0.5) ? 1 : -1);
        break;  // along an axis
      case 2:   // parallel to the plane y = 0
        if (std::hypot(dir.x, dir.z) > 1e-3)
          dir = Double3(dir.x, 0, dir.z) / std::hypot(dir.x, dir.z);
        break;
      case 3:
        origin = Double3(box.lo[0], random.uniform(box.lo[1], box.hi[1]), box.hi[2]);
        break;
      default:
        break;
    }
    const Ray ray{Point(origin), Vector(dir)};
    const double tMax = random.chance(0.5) ? INFINITE_DISTANCE : random.uniform(0, 4 * scale);
    double doubleEntry;
    const bool viaDouble = slabHit(SlabRay(ray), box, tMax, doubleEntry);
    float entry;
    const bool viaFloat = floatHit(FloatRay(ray), box, floatLimit(tMax), entry);
    if (viaDouble) {
      ++doubleHits;
      ASSERT_TRUE(viaFloat) << "ray " << i;
      ASSERT_LE(entry, floatAbove(doubleEntry)) << "ray " << i;
    } else if (viaFloat) {
      ++floatOnly;  // allowed: conservative
    }
    if (wideExactHit(ray, box, tMax)) {
      ASSERT_TRUE(viaFloat) << "ray " << i;
    }
  }
  EXPECT_GT(doubleHits, 20000);
  // Conservative, but not blind: the float test says hit for a box the double test misses
  // rarely (within a few float roundings of an edge).
  EXPECT_LT(floatOnly, doubleHits / 100);

  // =============== Boundary Values Tests ==================
  // TC11: rays that touch a box exactly: along a face, through an edge, from a corner, from a
  // face's plane outwards; the box [1, 2]^3 (floats), each ray hits it in real numbers
  const FloatBox unit{{1, 1, 1}, {2, 2, 2}};
  const struct {
    Double3 origin, direction;
  } touching[] = {
      {{0, 1, 1.5}, {1, 0, 0}},        // along the face y = 1
      {{0, 0, 1.5}, {1, 1, 0}},        // through the edge x = y = 1
      {{2, 2, 2}, {1, 0, 0}},          // from a corner, outwards
      {{1, 1.5, 1.5}, {-1, 0, 0}},     // from the face x = 1, away from the box
      {{3, 3, 3}, {-1, -1, -1}},       // at the corner (2, 2, 2), diagonally
      {{1.5, 1.5, 1e30}, {0, 0, -1}},  // from far away along z
      {{-1e38, 1.5, 1.5}, {1, 0, 0}},  // from beyond ORIGIN_RANGE
      {{1.5, 1, 1.5}, {1, -0.0, 0}},   // on the face y = 1, a direction component −0
  };
  for (const auto& t : touching) {
    const Ray ray{Point(t.origin), Vector(t.direction)};
    float entry;
    EXPECT_TRUE(floatHit(FloatRay(ray), unit, floatLimit(INFINITE_DISTANCE), entry))
        << t.origin.x << " " << t.origin.y << " " << t.origin.z;
  }
  // TC12: a limit just short of the box: the float limit is rounded up, the box 1 away along x
  // is kept for tMax = 1 (entered exactly at 1) and dropped for tMax = 0.99
  const Ray alongX{Point(0, 1.5, 1.5), Vector(1, 0, 0)};
  float entry;
  EXPECT_TRUE(floatHit(FloatRay(alongX), unit, floatLimit(1.0), entry));
  EXPECT_EQ(entry, 1 - 0x1p-21f);  // 1 − 8·2^-24: the inverse direction narrowed by WIDEN
  EXPECT_FALSE(floatHit(FloatRay(alongX), unit, floatLimit(0.99), entry));
}

TEST(WideBvhTests, collapseKeepsEveryLeafAndBox) {
  // TC01: the galaxy of the report (1065 shapes): every binary leaf is one slot of one wide
  // node, with its box and primitives; interior slots hold their child node's slots' boxes; the
  // slots of a node run along its axis in the binary tree's order (a leaf's primitives in the
  // order the binary tree stored them)
  const GalaxySetup g = galaxy(GalaxyParams{.diffusion = false});
  const Geometries& scene = g.scene.geometries;
  const Bvh binary(scene);
  const WideBvh wide(scene);
  std::vector<std::vector<std::uint32_t>> binaryLeaves, wideLeaves, inOrder;
  for (const BvhNode& n : binary.nodes())
    if (n.isLeaf()) {
      const auto s = binary.leafShapes(n);
      binaryLeaves.emplace_back(s.begin(), s.end());
    }
  int interiorSlots = 0;
  for (const WideNode& n : wide.nodes()) {
    EXPECT_GE(n.used, 2);
    EXPECT_LE(n.used, WideNode::WIDTH);
    for (int k = 0; k < WideNode::WIDTH; ++k) {
      if (k >= n.used) {
        EXPECT_EQ(n.kind[k], WideNode::Kind::Empty);
        EXPECT_EQ(n.lo[0][k], FINF);
        EXPECT_EQ(n.hi[0][k], -FINF);
        continue;
      }
      if (n.kind[k] == WideNode::Kind::Interior) {
        ++interiorSlots;
        const WideNode& child = wide.nodes()[n.child[k]];
        FloatBox inner = FloatBox::empty();
        for (int j = 0; j < child.used; ++j) inner.expand(child.box(j));
        for (int a = 0; a < 3; ++a) {
          EXPECT_LE(n.lo[a][k], inner.lo[a]);
          EXPECT_GE(n.hi[a][k], inner.hi[a]);
        }
        continue;
      }
      const auto s = wide.leafShapes(n, k);
      EXPECT_EQ(s.size(), n.count[k]);
      wideLeaves.emplace_back(s.begin(), s.end());
    }
  }
  // Every leaf once; and walked depth first, slots in order, in the binary tree's order.
  std::vector<std::vector<std::uint32_t>> sortedWide = wideLeaves, sortedBinary = binaryLeaves;
  std::sort(sortedWide.begin(), sortedWide.end());
  std::sort(sortedBinary.begin(), sortedBinary.end());
  EXPECT_EQ(sortedWide, sortedBinary);
  auto walk = [&](auto& self, const WideNode& n) -> void {
    for (int k = 0; k < n.used; ++k) {
      if (n.kind[k] == WideNode::Kind::Interior) {
        self(self, wide.nodes()[n.child[k]]);
      } else {
        const auto s = wide.leafShapes(n, k);
        inOrder.emplace_back(s.begin(), s.end());
      }
    }
  };
  walk(walk, wide.nodes()[0]);
  EXPECT_EQ(inOrder, binaryLeaves);
  EXPECT_EQ(interiorSlots + 1, static_cast<int>(wide.nodes().size()));  // a tree: one parent each
  EXPECT_EQ(binary.nodes().size(), 757u);
  EXPECT_EQ(wide.nodes().size(), 186u);
  EXPECT_EQ(wide.leaves().size(), 379u);  // (757 + 1) / 2
  EXPECT_EQ(binary.depth(), 11);
  EXPECT_EQ(wide.depth(), 6);
  EXPECT_EQ(wide.memoryBytes(), binary.memoryBytes() - 757 * sizeof(BvhNode) +
                                    186 * sizeof(WideNode) + 379 * sizeof(WideBvh::Leaf));
}

TEST(WideBvhTests, fewerNodesPerRay) {
  // TC01: the galaxy's camera rays at 128 x 72 and a shadow-like ray from each hit: the same
  // answers and exact tests as the binary tree for every-hit queries, a quarter of the nodes
  // (the counts are exact: the walk is deterministic)
  const GalaxySetup g = galaxy(GalaxyParams{.diffusion = false});
  const Geometries& scene = g.scene.geometries;
  const Bvh binary(scene);
  const WideBvh wide(scene);
  const Camera camera = g.camera.builder().build();
  QueryCounts binaryClosest, wideClosest, binaryEvery, wideEvery;
  for (int i = 0; i < 72; ++i)
    for (int j = 0; j < 128; ++j) {
      const Ray ray = camera.constructRay(128, 72, j, i);
      const auto a = binary.closestHit(ray, INFINITE_DISTANCE, &binaryClosest);
      const auto b = wide.closestHit(ray, INFINITE_DISTANCE, &wideClosest);
      ASSERT_EQ(a.has_value(), b.has_value());
      if (!a) continue;
      ASSERT_EQ(a->geometry, b->geometry);
      ASSERT_EQ(a->t, b->t);
      const Ray up(ray.point(a->t), Vector(0.3, 1, 0.2));
      int hitsA = 0, hitsB = 0;
      binary.forEachHit(
          up, 100, [&](const Hit&) { return ++hitsA > 0; }, &binaryEvery);
      wide.forEachHit(
          up, 100, [&](const Hit&) { return ++hitsB > 0; }, &wideEvery);
      ASSERT_EQ(hitsA, hitsB);
    }
  EXPECT_EQ(wideEvery.shapeTests, binaryEvery.shapeTests);
  EXPECT_LT(4 * wideEvery.nodesVisited, binaryEvery.nodesVisited + binaryEvery.nodesVisited / 10);
  EXPECT_LT(3 * wideClosest.nodesVisited, binaryClosest.nodesVisited);
  RecordProperty("binary closest nodes", std::to_string(binaryClosest.nodesVisited));
  RecordProperty("wide closest nodes", std::to_string(wideClosest.nodesVisited));
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

/// Every query of a scene traced as packets (the queries grouped in runs of 1 to 19 rays) with
/// the given instruction set: the same hits, bit for bit, as closestHit one ray at a time.
void expectPacketsAnswerAsOne(const Geometries& scene, const std::vector<test::Query>& queries,
                              WideBvh::Simd simd, double tMax) {
  const WideBvh wide(scene);
  std::vector<Ray> rays;
  for (const test::Query& q : queries) rays.push_back(q.ray);
  std::vector<std::optional<Hit>> hits(rays.size());
  std::size_t at = 0;
  for (std::size_t run = 1; at < rays.size(); run = run % 19 + 1) {
    const std::size_t n = std::min(run, rays.size() - at);
    wide.closestHits(std::span(rays).subspan(at, n), tMax, std::span(hits).subspan(at, n), nullptr,
                     simd);
    at += n;
  }
  int differences = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const std::optional<Hit> one = wide.closestHit(rays[i], tMax);
    const bool same = one.has_value() == hits[i].has_value() &&
                      (!one || (one->t == hits[i]->t && one->geometry == hits[i]->geometry));
    if (!same && ++differences <= 3) ADD_FAILURE() << "ray " << i;
  }
  EXPECT_EQ(differences, 0);
}

TEST(WideBvhTests, packetsAnswerAsSingleRays) {
  const Aabb box(Double3(-30), Double3(30));
  // ============ Equivalence Partitions Tests ==============
  // TC01: every bounded kind, planes and tubes, copies (exact ties), a mesh; rays of every kind
  // (from outside, inside, along axes, parallel to planes, from grid points) with both
  // instruction sets and an infinite and a finite tMax. The AVX2 lanes are asked for on every
  // machine: where the processor lacks AVX2, closestHits runs the SSE2 lanes instead.
  test::Random random(61);
  Geometries scene;
  test::addMixedShapes(scene, random, 700, box);
  test::addUnbounded(scene, box);
  test::addCopies(scene, random, 100);
  scene.addMesh(test::movedMesh(utahTeapot(5), Double3(2, 0, -1)));
  const std::vector<test::Query> queries = test::randomQueries(random, 3000, box);
  for (const WideBvh::Simd simd : {WideBvh::Simd::Sse2, WideBvh::Simd::Avx2}) {
    SCOPED_TRACE(simd == WideBvh::Simd::Sse2 ? "SSE2" : "AVX2");
    expectPacketsAnswerAsOne(scene, queries, simd, INFINITE_DISTANCE);
    expectPacketsAnswerAsOne(scene, queries, simd, 25);
  }
  // TC02: a beam: 80 rays from one point of the galaxy's glass, as mini 1 casts them
  const GalaxySetup g = galaxy(GalaxyParams{.diffusion = false});
  const WideBvh wide(g.scene.geometries);
  std::vector<Ray> beam;
  const Point from(4, 8, 25);
  for (int i = 0; i < 80; ++i)
    beam.emplace_back(from, Vector(Double3(0.02 * (i % 9 - 4), 0.02 * (i / 9 - 4), -1)));
  std::vector<std::optional<Hit>> hits(beam.size());
  QueryCounts packet, single;
  wide.closestHits(beam, INFINITE_DISTANCE, hits, &packet);
  for (std::size_t i = 0; i < beam.size(); ++i) {
    const auto one = wide.closestHit(beam[i], INFINITE_DISTANCE, &single);
    ASSERT_EQ(one.has_value(), hits[i].has_value()) << i;
    if (one) {
      EXPECT_TRUE(one->t == hits[i]->t && one->geometry == hits[i]->geometry) << i;
    }
  }
  // The beam looks into the glass box from the front: every ray hits it.
  EXPECT_EQ(std::count_if(hits.begin(), hits.end(), [](const auto& h) { return h.has_value(); }),
            80);
  EXPECT_GT(packet.nodesVisited, 0u);
  // TC03: what a tracer gets through Intersectable: the packets (their counts, which are not
  // closestHit's ray by ray), the same hits
  EXPECT_NE(packet, single);
  const Intersectable& seam = wide;
  std::vector<std::optional<Hit>> viaSeam(beam.size());
  QueryCounts seamCounts;
  seam.closestHits(beam, INFINITE_DISTANCE, viaSeam, &seamCounts);
  EXPECT_EQ(packet, seamCounts);
  for (std::size_t i = 0; i < beam.size(); ++i)
    EXPECT_TRUE(viaSeam[i] && viaSeam[i]->t == hits[i]->t &&
                viaSeam[i]->geometry == hits[i]->geometry)
        << i;
  // =============== Boundary Values Tests ==================
  // TC11: no ray; one ray; an empty scene (no tree)
  wide.closestHits({}, INFINITE_DISTANCE, {});
  std::optional<Hit> one;
  wide.closestHits(std::span(beam).first(1), INFINITE_DISTANCE, std::span(&one, 1));
  EXPECT_EQ(one.has_value(), hits[0].has_value());
  const Geometries empty;
  const WideBvh none(empty);
  none.closestHits(std::span(beam).first(3), INFINITE_DISTANCE, std::span(hits).first(3));
  EXPECT_FALSE(hits[0] || hits[1] || hits[2]);
}

TEST(WideBvhTests, packetsAllocateNothing) {
  test::Random random(62);
  const Aabb box(Double3(-30), Double3(30));
  Geometries scene;
  test::addMixedShapes(scene, random, 300, box);
  const WideBvh wide(scene);
  std::vector<Ray> rays;
  for (const test::Query& q : test::randomQueries(random, 200, box)) rays.push_back(q.ray);
  std::vector<std::optional<Hit>> hits(rays.size());
  const long allocations = testing::allocationsDuring([&] {
    for (const WideBvh::Simd simd : {WideBvh::Simd::Sse2, WideBvh::Simd::Avx2})
      wide.closestHits(rays, INFINITE_DISTANCE, hits, nullptr, simd);
  });
  EXPECT_EQ(allocations, 0);
}

}  // namespace
}  // namespace rt
