// Tests of ShadowTracer: a lit point, a fully shadowed one, partial shadows with their exact
// factors, a blocker beyond the light, directional lights, the k-weighted cut-off, and the
// course's fixed offset letting light leak at a small scale.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "RecordingShapes.h"
#include "geometries/Plane.h"
#include "geometries/Sphere.h"
#include "geometries/Triangle.h"
#include "lighting/LightSource.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"
#include "lighting/PhongTracer.h"
#include "primitives/Color.h"
#include "shadows/RayOffset.h"
#include "shadows/ShadowTracer.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;

/// Makes the protected parts of the tracer reachable from the tests.
struct Probe : ShadowTracer {
  using ShadowTracer::HitContext;
  using ShadowTracer::makeContext;
  using ShadowTracer::ShadowTracer;
  using ShadowTracer::transmittance;
};

Material diffuse(double kD) {
  Material m;
  m.kD = Double3(kD);
  return m;
}

Material transparent(double kT) {
  Material m;
  m.kT = Double3(kT);
  return m;
}

/*
 * The test scene: a diffuse floor z = 0 (emission (10,20,30), kD 0.5), ambient (10,10,10), a
 * point light of (100,100,100) with no attenuation at L = (0,0,100). A shaded point P = (x,0,0)
 * is looked at by a ray from (x-10, 0, 5) (it passes under every blocker).
 *
 *                 * L (0,0,100)
 *                 |
 *               -----  blocker at z = 50 (triangle around the z axis)
 *                 |
 *   eye  \        |
 *          \      |
 *   ========P============ floor z = 0
 *
 * Lit: colour = ambient + emission + I·kD·|n·l| with l = normalize(P - L), n = (0,0,1).
 * At P = (0,0,0): |n·l| = 1, so lit = (10,10,10) + (10,20,30) + 100·0.5·1 = (70,80,90) and
 * shadowed = (20,30,40).
 */
LitScene floorScene() {
  LitScene s;
  s.ambientLight = AmbientLight(Color(10, 10, 10), 1);
  s.add(Plane(Point::ZERO, Vector(0, 0, 1)), Color(10, 20, 30), diffuse(0.5));
  s.addLight(PointLight(Color(100, 100, 100), Point(0, 0, 100)));
  return s;
}

Triangle blockerAt(double z) { return Triangle(Point(-5, -5, z), Point(5, -5, z), Point(0, 5, z)); }

Color shade(const RayTracer& tracer, double x) {
  const Point p(x, 0, 0);
  const Point eye(x - 10, 0, 5);
  return tracer.traceRay(Ray(eye, p - eye));
}

TEST(ShadowTracerTests, traceRay) {
  // ============ Equivalence Partitions Tests ==============
  {
    // TC01: a lit point: nothing between it and the light; at (30,0,0), |n·l| = 100/√10900
    LitScene s = floorScene();
    s.add(blockerAt(50), Color::BLACK, transparent(0));  // the shadow ray passes it at x = 15
    const ShadowTracer tracer(s);
    const double lit = 100 * 0.5 * 100 / std::sqrt(10900.0);
    const Color c = shade(tracer, 30);
    EXPECT_NEAR(20 + lit, c.r(), 1e-9);
    EXPECT_NEAR(30 + lit, c.g(), 1e-9);
    EXPECT_NEAR(40 + lit, c.b(), 1e-9);
  }
  {
    // TC02: fully shadowed by an opaque triangle: emission + ambient only, exactly
    LitScene s = floorScene();
    s.add(blockerAt(50), Color::BLACK, transparent(0));
    EXPECT_EQ(Color(20, 30, 40), shade(ShadowTracer(s), 0));
    // ... where the stage-5 tracer, which has no shadows, lights it fully
    EXPECT_EQ(Color(70, 80, 90), shade(PhongTracer(s), 0));
  }
  {
    // TC03: behind a triangle of kT 0.5: (20,30,40) + 0.5·50
    LitScene s = floorScene();
    s.add(blockerAt(50), Color::BLACK, transparent(0.5));
    EXPECT_EQ(Color(45, 55, 65), shade(ShadowTracer(s), 0));
  }
  {
    // TC04: behind a sphere of kT 0.5, crossed twice: (20,30,40) + 0.25·50
    LitScene s = floorScene();
    s.add(Sphere(Point(0, 0, 50), 10), Color::BLACK, transparent(0.5));
    EXPECT_EQ(Color(32.5, 42.5, 52.5), shade(ShadowTracer(s), 0));
  }
  {
    // TC05: an opaque blocker beyond the light (z = 150) does not shadow
    LitScene s = floorScene();
    s.add(blockerAt(150), Color::BLACK, transparent(0));
    EXPECT_EQ(Color(70, 80, 90), shade(ShadowTracer(s), 0));
  }
  {
    // TC06: an opaque blocker below the floor (behind the point) does not shadow
    LitScene s = floorScene();
    s.add(blockerAt(-50), Color::BLACK, transparent(0));
    EXPECT_EQ(Color(70, 80, 90), shade(ShadowTracer(s), 0));
  }
  {
    // TC07: a directional light (coming down -z) is shadowed by a blocker at any height
    LitScene s = floorScene();
    s.lights.clear();
    s.addLight(DirectionalLight(Color(100, 100, 100), Vector(0, 0, -1)));
    s.add(blockerAt(1e6), Color::BLACK, transparent(0));
    EXPECT_EQ(Color(20, 30, 40), shade(ShadowTracer(s), 0));
    EXPECT_EQ(Color(70, 80, 90), shade(ShadowTracer(s), 10));  // beside the blocker: lit
  }
  {
    // TC08: two lights, one blocked: only the other's term is left. Second light at (0,0,-100)
    // is under the floor, on the other side from the viewer: the same-side rule drops it.
    // Third light at (100,0,100) (|n·l| = 1/√2 at the origin) passes beside the blocker.
    LitScene s = floorScene();
    s.add(blockerAt(50), Color::BLACK, transparent(0));
    s.addLight(PointLight(Color(100, 100, 100), Point(0, 0, -100)));
    s.addLight(PointLight(Color(100, 100, 100), Point(100, 0, 100)));
    const Color c = shade(ShadowTracer(s), 0);
    const double side = 100 * 0.5 / std::sqrt(2.0);
    EXPECT_NEAR(20 + side, c.r(), 1e-9);
    EXPECT_NEAR(30 + side, c.g(), 1e-9);
    EXPECT_NEAR(40 + side, c.b(), 1e-9);
  }

  // =============== Boundary Values Tests ==================
  {
    // TC11: the blocker's edge: the shadow ray from (0,0,0) passes exactly over the vertex
    // (0,5,50) of a triangle shifted so that the vertex sits on the z axis: an edge or vertex
    // hit is a miss (the course's rule), so the point is lit
    LitScene s = floorScene();
    s.add(Triangle(Point(-5, -5, 50), Point(5, -5, 50), Point(0, 0, 50)), Color::BLACK,
          transparent(0));
    EXPECT_EQ(Color(70, 80, 90), shade(ShadowTracer(s), 0));
  }
}

TEST(ShadowTracerTests, transmittanceWeightedByK) {
  LitScene s = floorScene();
  s.add(blockerAt(50), Color::BLACK, transparent(0.5));
  const Probe tracer(s);
  const Ray primary(Point(-10, 0, 5), Vector(10, 0, -5));
  const Probe::HitContext h = tracer.makeContext(*s.geometries.closestHit(primary), primary);
  const LightSample light = *illuminate(s.lights[0], h.point);
  RayCounts counts;
  SampleContext ctx(0, 0, 0, 0, counts);
  // ============ Equivalence Partitions Tests ==============
  // TC01: path weight 1: the transmittance itself
  EXPECT_EQ(Double3(0.5), tracer.transmittance(h, 0, light, Double3::ONE, ctx));
  // TC02: path weight 0.001 (a deep secondary ray): 0.5·0.001 is below the cut-off: ZERO
  EXPECT_EQ(Double3::ZERO, tracer.transmittance(h, 0, light, Double3(0.001), ctx));
  // TC03: one channel of the weight keeps the light (course lowerThan: all three below)
  EXPECT_EQ(Double3(0.5), tracer.transmittance(h, 0, light, Double3(0.001, 0.001, 0.01), ctx));

  // =============== Boundary Values Tests ==================
  // TC11: 0.5·0.002 = 0.001 is not below 0.001: kept
  EXPECT_EQ(Double3(0.5), tracer.transmittance(h, 0, light, Double3(0.002), ctx));
  // TC12: each call cast one shadow ray, counted with its queries (the floor and the blocker)
  EXPECT_EQ(4u, counts.shadow);
  EXPECT_EQ(8u, counts.queries.shapeTests);
  EXPECT_EQ(0u, counts.primary + counts.secondary);
}

// The failure mode of the course's fixed DELTA = 0.1 at a small scale: a floor at z = 0 and an
// opaque sheet 0.05 above it, a light above both. The course's shift puts the shadow ray's origin
// above the sheet, so the light leaks under it; the scale-aware offset (ε = 1e-9 here) finds it.
TEST(ShadowTracerTests, courseDeltaLeaksAtSmallScale) {
  LitScene s = floorScene();
  s.add(Triangle(Point(-0.5, -0.5, 0.05), Point(0.5, -0.5, 0.05), Point(0, 0.5, 0.05)),
        Color::BLACK, transparent(0));
  const ShadowTracer course(s, nullptr, RayOffset::course());
  const ShadowTracer scaled(s);
  // The viewing ray must pass under the sheet: from (−1, 0, 0.01) to (0,0,0).
  const Ray primary(Point(-1, 0, 0.01), Vector(1, 0, -0.01));
  EXPECT_EQ(Color(70, 80, 90), course.traceRay(primary));  // light leaks: fully lit
  EXPECT_EQ(Color(20, 30, 40), scaled.traceRay(primary));  // shadowed, as it should be
  EXPECT_EQ(RayOffset::course(), course.rayOffset());
}

/// The colour at (x,0,0) seen as shade() sees it, with the rays it cast counted in counts.
Color shadeCounted(const RayTracer& tracer, double x, RayCounts& counts) {
  const Point p(x, 0, 0);
  const Point eye(x - 10, 0, 5);
  SampleContext ctx(0, 0, 0, 0, counts);
  return tracer.traceRay(Ray(eye, p - eye), ctx);
}

// The tracer aims each shadow ray at a light of the scene's list and says which: an
// acceleration that is also a LightOccluders is asked with that light's index.
TEST(ShadowTracerTests, lightIndexReachesTheOccluders) {
  // The floor scene with a blocker of kT 0.5 over P = (0,0,0); light 1 under the floor (the
  // same-side rule drops it: no shadow ray); light 2 at (100,0,100), behind a sphere of kT
  // (0.3,0.6,0.9) centred on the shadow ray, crossed twice.
  LitScene s = floorScene();
  s.add(blockerAt(50), Color::BLACK, transparent(0.5));
  Material tinted;
  tinted.kT = Double3(0.3, 0.6, 0.9);
  s.add(Sphere(Point(50, 0, 50), 5), Color::BLACK, tinted);
  s.addLight(PointLight(Color(100, 100, 100), Point(0, 0, -100)));
  s.addLight(PointLight(Color(100, 100, 100), Point(100, 0, 100)));
  const test::RecordingOccluders occluders(s.geometries);
  const ShadowTracer tracer(s, &occluders);
  RayCounts counts, plainCounts;
  // ============ Equivalence Partitions Tests ==============
  // TC01: lights 0 and 2 cast a shadow ray each, through crossingsTowards with their index;
  // nothing walks forEachHit
  const Color c = shadeCounted(tracer, 0, counts);
  EXPECT_EQ((std::vector<std::uint32_t>{0, 2}), occluders.lights);
  EXPECT_EQ(0, occluders.forEachHitCalls);
  EXPECT_EQ(2u, counts.shadow);
  // TC02: the same bits as the tracer over the scene's own shapes, and the colour by hand:
  // (20,30,40) + 0.5·50 + kT²·100·0.5/√2 (|n·l| = 1/√2 towards light 2)
  const Color plain = shadeCounted(ShadowTracer(s), 0, plainCounts);
  EXPECT_TRUE(sameBits(plain, c));
  EXPECT_EQ(plainCounts.shadow, counts.shadow);
  const double side = 100 * 0.5 / std::sqrt(2.0);
  EXPECT_NEAR(45 + 0.09 * side, c.r(), 1e-9);
  EXPECT_NEAR(55 + 0.36 * side, c.g(), 1e-9);
  EXPECT_NEAR(65 + 0.81 * side, c.b(), 1e-9);
  // TC03: a shadow query asked directly without a light (NO_LIGHT) walks forEachHit
  const Transmittance t =
      tracer.shadowQuery(Point::ZERO, Vector(0, 0, 1), Vector(0, 0, 1), 100, Double3::ONE, counts);
  EXPECT_EQ(Double3(0.5), t.factor);
  EXPECT_EQ(1, occluders.forEachHitCalls);
  EXPECT_EQ(2u, occluders.lights.size());
}

// A light that gives the point nothing (a spot light facing away: its sample's intensity is
// exactly zero) casts no shadow ray; the pixel is the one without that light, bit for bit.
TEST(ShadowTracerTests, zeroIntensityCastsNoShadowRay) {
  // The floor scene with a blocker of kT 0.5 over P = (0,0,0): (20,30,40) + 0.5·50 = (45,55,65)
  LitScene base = floorScene();
  base.add(blockerAt(50), Color::BLACK, transparent(0.5));
  RayCounts baseCounts;
  const Color without = shadeCounted(ShadowTracer(base), 0, baseCounts);
  ASSERT_EQ(Color(45, 55, 65), without);
  ASSERT_EQ(1u, baseCounts.shadow);
  // base plus one more light: no shadow ray for it, and the colour of base.
  const auto expectNoShadowRay = [&](const LightSource& extra) {
    LitScene s = base;
    s.addLight(extra);
    const Probe probe(s);
    const Ray primary(Point(-10, 0, 5), Vector(10, 0, -5));
    const Probe::HitContext h = probe.makeContext(*s.geometries.closestHit(primary), primary);
    const std::optional<LightSample> sample = illuminate(s.lights[1], h.point);
    ASSERT_TRUE(sample.has_value());
    ASSERT_TRUE(sample->intensity.rgb().isExactlyZero());
    RayCounts counts;
    EXPECT_TRUE(sameBits(without, shadeCounted(ShadowTracer(s), 0, counts)));
    EXPECT_EQ(baseCounts, counts);  // one shadow ray, the same shape tests
    // ... and the tracer's transmittance towards it: ZERO, nothing cast, nothing tested
    RayCounts direct;
    SampleContext ctx(0, 0, 0, 0, direct);
    EXPECT_TRUE(sameBits(Double3::ZERO, probe.transmittance(h, 1, *sample, Double3::ONE, ctx)));
    EXPECT_EQ(RayCounts{}, direct);
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: a bright spot light above P facing up, away from it (it passes the same-side rule)
  expectNoShadowRay(SpotLight(Color(1000, 1000, 1000), Point(0, 0, 100), Vector(0, 0, 1)));
  // TC02: a focused spot (narrowBeam 10) facing away
  expectNoShadowRay(
      SpotLight(Color(1000, 1000, 1000), Point(0, 0, 100), Vector(0.3, 0, 1)).setNarrowBeam(10));
  // TC03: a black point light
  expectNoShadowRay(PointLight(Color(0, 0, 0), Point(0, 0, 100)));
  // TC04: a spot facing P, blue only (0,0,100): a shadow ray is cast, its term passes the
  // blocker: (45,55,65) + (0,0,100·0.5·0.5) = (45,55,90)
  {
    LitScene s = base;
    s.addLight(SpotLight(Color(0, 0, 100), Point(0, 0, 100), Vector(0, 0, -1)));
    RayCounts counts;
    EXPECT_EQ(Color(45, 55, 90), shadeCounted(ShadowTracer(s), 0, counts));
    EXPECT_EQ(2u, counts.shadow);
  }

  // =============== Boundary Values Tests ==================
  // TC11: a spot at a right angle to P (direction·l = 0 exactly: l has no y, the spot faces +y):
  // zero, no shadow ray
  expectNoShadowRay(SpotLight(Color(1000, 1000, 1000), Point(0, 0, 100), Vector(0, 1, 0)));
}

}  // namespace
}  // namespace rt
