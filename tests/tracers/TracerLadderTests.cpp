// Cross-stage: one scene through every tracer of the family. Each stage's tracer must reduce
// to the one below it where the new effect has nothing to act on, and add exactly its effect
// where it does.
#include <gtest/gtest.h>

#include "camera/RayTracer.h"
#include "lighting/LitScene.h"
#include "lighting/PhongTracer.h"
#include "reflections/WhittedTracer.h"
#include "shadows/ShadowTracer.h"

namespace rt {
namespace {

constexpr double EPS = 1e-9;

void expectColor(const Color& actual, const Color& expected) {
  EXPECT_NEAR(actual.r(), expected.r(), EPS) << actual << " vs " << expected;
  EXPECT_NEAR(actual.g(), expected.g(), EPS) << actual << " vs " << expected;
  EXPECT_NEAR(actual.b(), expected.b(), EPS) << actual << " vs " << expected;
}

/// A floor (plane y = 0, facing +y) lit by a point light straight above (0,10,0); optionally a
/// small opaque square blocker at y = 5 between them, and a mirror coefficient on the floor.
LitScene floorScene(bool blocker, double floorKr) {
  LitScene scene;
  scene.background = Color(10, 20, 30);
  scene.ambientLight = AmbientLight(Color(100, 100, 100), 0.1);  // Ia·kA = (10,10,10)
  Material floor;
  floor.kD = Double3(0.5);
  floor.kR = Double3(floorKr);
  scene.add(Plane(Point(0, 0, 0), Vector(0, 1, 0)), Color(1, 2, 3), floor);
  if (blocker) {
    scene.add(Polygon({Point(-1, 5, -1), Point(-1, 5, 1), Point(1, 5, 1), Point(1, 5, -1)}),
              Color::BLACK, Material{});
  }
  scene.addLight(PointLight(Color(200, 200, 200), Point(0, 10, 0)));
  return scene;
}

// The ray straight down onto the floor's origin, from above the blocker.
const Ray DOWN(Point(0, 20, 0), Vector(0, -1, 0));
// A ray from the side onto the floor at (0,0,0), under the blocker's plane.
const Ray SLANTED(Point(0, 1, 3), Vector(0, -1, -3));

// TC01: no blocker, no mirror: Phong, shadow and Whitted give the same colour on the floor;
// the ambient tracer gives the ambient intensity only.
TEST(TracerLadder, TC01_nothingToShadowOrReflect_allAgree) {
  const LitScene scene = floorScene(false, 0);
  // Light at distance 10 straight above: l = (0,-1,0), n·l = -1, kD·|n·l|·I = 0.5·200 = 100.
  // Emission (1,2,3) + ambient (10,10,10) + (100,100,100).
  const Color expected(111, 112, 113);
  expectColor(PhongTracer(scene).traceRay(SLANTED), expected);
  expectColor(ShadowTracer(scene).traceRay(SLANTED), expected);
  expectColor(WhittedTracer(scene).traceRay(SLANTED), expected);
  expectColor(AmbientTracer(scene).traceRay(SLANTED), Color(10, 10, 10));
}

// TC02: an opaque blocker between the light and the floor: Phong ignores it, the shadow and
// Whitted tracers drop exactly the light's term.
TEST(TracerLadder, TC02_opaqueBlocker_shadowTracersDropTheLightTerm) {
  const LitScene scene = floorScene(true, 0);
  expectColor(PhongTracer(scene).traceRay(SLANTED), Color(111, 112, 113));
  expectColor(ShadowTracer(scene).traceRay(SLANTED), Color(11, 12, 13));
  expectColor(WhittedTracer(scene).traceRay(SLANTED), Color(11, 12, 13));
}

// TC03: a half-mirror floor with nothing above it but the background: only Whitted adds the
// reflected ray, which misses and brings background × kR.
TEST(TracerLadder, TC03_mirrorFloor_onlyWhittedAddsTheReflection) {
  const LitScene scene = floorScene(false, 0.5);
  expectColor(ShadowTracer(scene).traceRay(SLANTED), Color(111, 112, 113));
  // + background (10,20,30) × 0.5.
  expectColor(WhittedTracer(scene).traceRay(SLANTED), Color(116, 122, 128));
}

// TC11: a ray that misses everything: every tracer returns the background.
TEST(TracerLadder, TC11_miss_everyTracerReturnsTheBackground) {
  const LitScene scene = floorScene(true, 0.5);
  const Ray up(Point(0, 1, 0), Vector(0, 1, 1));
  for (const Color& c : {AmbientTracer(scene).traceRay(up), PhongTracer(scene).traceRay(up),
                         ShadowTracer(scene).traceRay(up), WhittedTracer(scene).traceRay(up)})
    expectColor(c, Color(10, 20, 30));
}

// TC12: the blocker seen from above: it is hit first (emission black, no material), so every
// lit tracer shows ambient only.
TEST(TracerLadder, TC12_blockerSeenFirst_ambientOnly) {
  const LitScene scene = floorScene(true, 0.5);
  expectColor(PhongTracer(scene).traceRay(DOWN), Color(10, 10, 10));
  expectColor(WhittedTracer(scene).traceRay(DOWN), Color(10, 10, 10));
}

}  // namespace
}  // namespace rt
