// Tests of ShadowTracer: a lit point, a fully shadowed one, partial shadows with their exact
// factors, a blocker beyond the light, directional lights, the k-weighted cut-off, and the
// course's fixed offset letting light leak at a small scale.

#include <gtest/gtest.h>

#include <cmath>

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

namespace rt {
namespace {

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

}  // namespace
}  // namespace rt
