// EmbreeScene (include/embree/EmbreeScene.h) against the project's linear Geometries: the same
// closest hits and the same every-hit sets on rays that are no near-ties, tMax respected, an
// early stop, no allocation per query, an empty scene; and a tiny galaxy through Embree, whose
// pixels differ from the BVH's in the few (float) places measured.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "bvh/WideBvh.h"
#include "camera/Camera.h"
#include "embree/EmbreeScene.h"
#include "glossy/BeamTracer.h"
#include "glossy/Galaxy.h"
#include "glossy/Samplers.h"
#include "parallel/TilePool.h"
#include "support/AllocationCounter.h"
#include "support/TestRandom.h"

namespace rt {
namespace {

/// A sphere, a triangle, a quad (a polygon of 4 vertices), a pentagon (5 vertices: Embree's user
/// geometry), a cylinder (user geometry), a plane and a tube (outside Embree), apart from each
/// other so that no ray of the grid below is near a tie.
Geometries smallScene() {
  Geometries g;
  g.add(Sphere(Point(0, 0, -10), 1.5));                                                        // 0
  g.add(Triangle(Point(3, -1, -8), Point(6, -1, -8), Point(4.5, 2, -8)));                      // 1
  g.add(Polygon({Point(-6, -1, -9), Point(-3, -1, -9), Point(-3, 2, -9), Point(-6, 2, -9)}));  // 2
  g.add(Polygon({Point(-1, 3, -7), Point(1, 3, -7), Point(1.6, 4.5, -7), Point(0, 5.6, -7),
                 Point(-1.6, 4.5, -7)}));                         // 3
  g.add(Cylinder(1, Ray(Point(0, -5, -9), Vector(0, 0, 1)), 2));  // 4
  g.add(Plane(Point(0, 0, -20), Vector(0, 0, 1)));                // 5
  g.add(Tube(0.3, Ray(Point(-5.5, 0, -4), Vector(0, 1, 0))));     // 6
  return g;
}

/// Rays from (0, 0, 5) through a 41 x 41 grid of points on z = -8 over [-8, 8]².
std::vector<Ray> gridRays() {
  std::vector<Ray> rays;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j)
      rays.emplace_back(Point(0.01, 0.02, 5), Vector(-8 + 0.4 * i, -8 + 0.4 * j, -13));
  return rays;
}

std::uint64_t bits(double t) { return std::bit_cast<std::uint64_t>(t); }

std::multiset<std::pair<std::uint32_t, std::uint64_t>> everyHit(const Intersectable& s,
                                                                const Ray& ray, double tMax) {
  std::multiset<std::pair<std::uint32_t, std::uint64_t>> hits;
  s.forEachHit(ray, tMax, [&](const Hit& h) {
    hits.insert({h.geometry, bits(h.t)});
    return true;
  });
  return hits;
}

// ============ Equivalence Partitions Tests ==============
// TC01: what goes where: one sphere, one triangle, one quad to Embree's native geometries; the
// pentagon and the cylinder to its user geometry; the plane and the tube outside
TEST(EmbreeTests, census) {
  const Geometries g = smallScene();
  const EmbreeScene embree(g);
  const EmbreeScene::Census c = embree.census();
  EXPECT_EQ(c.spheres, 1u);
  EXPECT_EQ(c.triangles, 1u);
  EXPECT_EQ(c.quads, 1u);
  EXPECT_EQ(c.user, 2u);
  EXPECT_EQ(c.unbounded, 2u);
  EXPECT_STREQ(EmbreeScene::version(), "3.13.5");
}

// TC02: closestHit is the linear scan's, the same shape and the same bits of t, on every ray of
// the grid; every shape is hit by some ray
TEST(EmbreeTests, closestHitIsTheLinearScans) {
  const Geometries g = smallScene();
  const EmbreeScene embree(g);
  std::set<std::uint32_t> seen;
  int hits = 0;
  for (const Ray& ray : gridRays()) {
    const std::optional<Hit> expected = g.closestHit(ray);
    const std::optional<Hit> actual = embree.closestHit(ray);
    ASSERT_EQ(expected.has_value(), actual.has_value());
    if (!expected) continue;
    ++hits;
    seen.insert(expected->geometry);
    EXPECT_EQ(actual->geometry, expected->geometry);
    EXPECT_EQ(bits(actual->t), bits(expected->t));
  }
  EXPECT_EQ(hits, 41 * 41);  // the plane behind everything
  EXPECT_EQ(seen, (std::set<std::uint32_t>{0, 1, 2, 3, 4, 5, 6}));
}

// TC03: forEachHit reports the linear scan's hits (shape and bits of t), with tMax infinite and
// with tMax between the shapes (z = -8.5 from the rays' origin: about 13.5)
TEST(EmbreeTests, forEachHitIsTheLinearScans) {
  const Geometries g = smallScene();
  const EmbreeScene embree(g);
  std::size_t total = 0;
  for (const double tMax : {INFINITE_DISTANCE, 13.5})
    for (const Ray& ray : gridRays()) {
      const auto expected = everyHit(g, ray, tMax);
      EXPECT_EQ(everyHit(embree, ray, tMax), expected);
      total += expected.size();
    }
  EXPECT_EQ(total, 2335u);
}

// TC04: tMax respected by closestHit: a limit before the sphere leaves only what is nearer
// (nothing); exactly at the sphere's t, the sphere (inclusive)
TEST(EmbreeTests, closestHitRespectsTMax) {
  const Geometries g = smallScene();
  const EmbreeScene embree(g);
  const Ray ray(Point(0, 0, 5), Vector(0, 0, -1));
  const std::optional<Hit> sphere = g.closestHit(ray);
  ASSERT_TRUE(sphere);
  ASSERT_EQ(sphere->geometry, 0u);
  EXPECT_EQ(bits(sphere->t), bits(13.5));
  EXPECT_FALSE(embree.closestHit(ray, 13.0));
  const std::optional<Hit> at = embree.closestHit(ray, sphere->t);
  ASSERT_TRUE(at);
  EXPECT_EQ(at->geometry, 0u);
  EXPECT_EQ(bits(at->t), bits(sphere->t));
}

// TC05: forEachHit stops when visit says so: one visit, false returned
TEST(EmbreeTests, forEachHitStopsWhenVisitSaysSo) {
  const Geometries g = smallScene();
  const EmbreeScene embree(g);
  const Ray ray(Point(0, 0, 5), Vector(0, 0, -1));  // the sphere twice, the plane
  EXPECT_EQ(everyHit(embree, ray, INFINITE_DISTANCE).size(), 3u);
  int visits = 0;
  EXPECT_FALSE(embree.forEachHit(ray, INFINITE_DISTANCE, [&](const Hit&) {
    ++visits;
    return false;
  }));
  EXPECT_EQ(visits, 1);
  // stopped at the second hit
  visits = 0;
  EXPECT_FALSE(embree.forEachHit(ray, INFINITE_DISTANCE, [&](const Hit&) { return ++visits < 2; }));
  EXPECT_EQ(visits, 2);
  EXPECT_TRUE(embree.forEachHit(ray, INFINITE_DISTANCE, [](const Hit&) { return true; }));
}

// TC06: counts: the exact tests made (the plane and the tube, then Embree's one candidate, the
// sphere's front: its back lies beyond the ray's new far end), no node visits
TEST(EmbreeTests, counts) {
  const Geometries g = smallScene();
  const EmbreeScene embree(g);
  QueryCounts counts;
  (void)embree.closestHit(Ray(Point(0, 0, 5), Vector(0, 0, -1)), INFINITE_DISTANCE, &counts);
  EXPECT_EQ(counts, (QueryCounts{.shapeTests = 2 + 1, .nodesVisited = 0}));
}

// TC07: no allocation per query, closest hit or every hit, over the whole grid
TEST(EmbreeTests, noAllocationPerQuery) {
  const Geometries g = smallScene();
  const EmbreeScene embree(g);
  const std::vector<Ray> rays = gridRays();
  (void)embree.closestHit(rays[0]);  // whatever a first query sets up
  double sum = 0;
  const long allocations = testing::allocationsDuring([&] {
    for (const Ray& ray : rays) {
      if (const std::optional<Hit> h = embree.closestHit(ray)) sum += h->t;
      embree.forEachHit(ray, INFINITE_DISTANCE, [&](const Hit& h) {
        sum += h.t;
        return true;
      });
    }
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(sum, 0);
}

// =============== Boundary Values Tests ==================
// TC11: an empty scene: no hit, every-hit complete with no visit
TEST(EmbreeTests, emptyScene) {
  const Geometries g;
  const EmbreeScene embree(g);
  const Ray ray(Point(0, 0, 0), Vector(0, 0, -1));
  EXPECT_FALSE(embree.closestHit(ray));
  EXPECT_TRUE(embree.forEachHit(ray, INFINITE_DISTANCE, [](const Hit&) { return false; }));
  EXPECT_EQ(embree.census().spheres + embree.census().unbounded, 0u);
}

// TC12: only unbounded shapes: nothing goes to Embree, the plane still answers
TEST(EmbreeTests, onlyUnboundedShapes) {
  const Geometries g{Plane(Point(0, 0, -3), Vector(0, 0, 1))};
  const EmbreeScene embree(g);
  const std::optional<Hit> h = embree.closestHit(Ray(Point(0, 0, 0), Vector(0, 0, -1)));
  ASSERT_TRUE(h);
  EXPECT_EQ(h->geometry, 0u);
  EXPECT_EQ(bits(h->t), bits(3.0));
}

// TC08: the small galaxy (7 arms of 12 stars; shared faces: its boxes' polygons hit at the same
// exact t), 2000 random rays from around it: every closest hit and every set of hits is the
// linear scan's (the ties go to the smaller index, as the project's rule says)
TEST(EmbreeTests, galaxyRaysAreTheLinearScans) {
  const GalaxySetup setup = galaxy(GalaxyParams{.arms = 7, .perArm = 12});
  const Geometries& g = setup.scene.geometries;
  const EmbreeScene embree(g);
  test::TestRandom random(7);
  int closestDiffer = 0, setsDiffer = 0, hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const Double3 o = random.inCube(-1, 1);
    const Ray ray(Point(40 * o.x, 10 + 10 * o.y, 40 * o.z), Vector(random.inCube(-1, 1)));
    const std::optional<Hit> a = g.closestHit(ray), b = embree.closestHit(ray);
    hits += a ? 1 : 0;
    if (a.has_value() != b.has_value() ||
        (a && (a->geometry != b->geometry || bits(a->t) != bits(b->t))))
      ++closestDiffer;
    if (everyHit(g, ray, INFINITE_DISTANCE) != everyHit(embree, ray, INFINITE_DISTANCE))
      ++setsDiffer;
  }
  EXPECT_EQ(closestDiffer, 0);
  EXPECT_EQ(setsDiffer, 0);
  EXPECT_GT(hits, 1000);
}

// TC13: a small galaxy (7 arms of 12 stars), 64 x 36 from "inside", one thread, its beams of
// 2 x 2 rays: rendered through Embree, the pixels whose 8-bit colours differ from the wide BVH's
// image (which is the linear scan's, bit for bit): as measured, none (every hit checked and
// ordered exactly; no ray of this image grazes an edge where float and double disagree).
// Deterministic: one thread, one build.
TEST(EmbreeTests, tinyGalaxyDiffersInThePixelsMeasured) {
  GalaxySetup setup = galaxy(GalaxyParams{.arms = 7, .perArm = 12});
  for (Appearance& a : setup.scene.appearances)
    if (a.material.refractedBeam.isBeam())
      a.material.reflectedBeam = a.material.refractedBeam =
          BeamSettings{.distance = 12, .radius = 0.3, .grid = 2};
  CameraSpec view = setup.views[2].camera;
  view.nX = 64;
  view.nY = 36;
  const LitScene& scene = setup.scene;
  const WideBvh wide(scene.geometries);
  const EmbreeScene embree(scene.geometries);
  const BeamTracer throughWide(scene, &wide), throughEmbree(scene, &embree);
  const CenterSampler sampler;
  Camera camera = view.builder().build();
  Image a(view.nX, view.nY), b(view.nX, view.nY);
  renderImage({camera, throughWide, sampler}, a, {.threads = 1});
  renderImage({camera, throughEmbree, sampler}, b, {.threads = 1});
  int differing = 0;
  for (int y = 0; y < view.nY; ++y)
    for (int x = 0; x < view.nX; ++x)
      differing += a.pixel(x, y).toRgb8() != b.pixel(x, y).toRgb8() ? 1 : 0;
  EXPECT_EQ(differing, 0);
}

}  // namespace
}  // namespace rt
