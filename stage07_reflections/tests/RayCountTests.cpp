// Depth limit and cut-off of the Whitted recursion, counted in the hall of mirrors: a primary ray
// perpendicular to two parallel mirrors bounces between them until the level or the path weight
// ends it. The sample context's RayCounts count the rays.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "camera/Camera.h"
#include "primitives/Color.h"
#include "reflections/CourseScenes.h"
#include "reflections/WhittedTracer.h"

namespace rt {
namespace {

/// A ray between the mirrors (z = -150 and z = +150), perpendicular to them, above the floor and
/// away from the spheres: it hits mirror 0, comes back to mirror 1, and so on.
const Ray betweenMirrors(Point(100, 100, 0), Vector(0, 0, -1));

/// The hall of mirrors with both mirrors' kR set to kR.
SceneSetup<LitScene> hall(const Double3& kR) {
  SceneSetup<LitScene> s = course::hallOfMirrors();
  s.scene.appearances[0].material.kR = kR;
  s.scene.appearances[1].material.kR = kR;
  return s;
}

/// The number of secondary rays cast for the one primary ray.
std::uint64_t bounces(const Double3& kR, const WhittedSettings& settings) {
  const SceneSetup<LitScene> s = hall(kR);
  WhittedTracer tracer(s.scene, nullptr, settings);
  RayCounts counts;
  SampleContext ctx(0, 0, 0, 0, counts);
  tracer.traceRay(betweenMirrors, ctx);
  EXPECT_EQ(0u, counts.primary);  // the caller (a pixel sampler) counts the primary ray
  return counts.secondary;
}

TEST(RayCountTests, depthLimit) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: kR 1, the course's maxLevel 10: the primary hit is level 10, the hit at level 1 casts
  // nothing: exactly maxLevel - 1 = 9 secondary rays
  EXPECT_EQ(9u, bounces(Double3(1), {}));
  // TC02: maxLevel 5: 4 rays
  EXPECT_EQ(4u, bounces(Double3(1), {.maxLevel = 5}));
  // TC03: kR 0.5 with maxLevel 10: the weight after 9 bounces is 0.5^9 = 0.00195 >= 0.001, so
  // the depth ends it first: 9
  EXPECT_EQ(9u, bounces(Double3(0.5), {}));

  // =============== Boundary Values Tests ==================
  // TC11: maxLevel 1: no secondary ray at all
  EXPECT_EQ(0u, bounces(Double3(1), {.maxLevel = 1}));
  // TC12: maxLevel 2: exactly one
  EXPECT_EQ(1u, bounces(Double3(1), {.maxLevel = 2}));
}

TEST(RayCountTests, cutOff) {
  // The j-th bounce has weight kR^j and is cast iff kR^j is not lowerThan 0.001, so the count
  // is the largest j with kR^j >= 0.001: floor(log(0.001)/log(kR)) (when maxLevel allows).
  // ============ Equivalence Partitions Tests ==============
  // TC01: kR 0.5, maxLevel 30: log(0.001)/log(0.5) = 9.97: 9 rays (0.5^10 = 0.00098 < 0.001)
  EXPECT_EQ(9, static_cast<int>(std::floor(std::log(0.001) / std::log(0.5))));
  EXPECT_EQ(9u, bounces(Double3(0.5), {.maxLevel = 30}));
  // TC02: kR 0.7, maxLevel 30: log(0.001)/log(0.7) = 19.37: 19 rays
  EXPECT_EQ(19, static_cast<int>(std::floor(std::log(0.001) / std::log(0.7))));
  EXPECT_EQ(19u, bounces(Double3(0.7), {.maxLevel = 30}));
  // TC03: the course's lowerThan needs all three channels below: kR (0.5, 0.9, 0) goes on while
  // green 0.9^j >= 0.001: floor(65.56) = 65 rays (maxLevel 100)
  EXPECT_EQ(65, static_cast<int>(std::floor(std::log(0.001) / std::log(0.9))));
  EXPECT_EQ(65u, bounces(Double3(0.5, 0.9, 0), {.maxLevel = 100}));
  // TC04: no cut-off (minK 0): only the depth: 29 rays for maxLevel 30
  EXPECT_EQ(29u, bounces(Double3(0.5), {.maxLevel = 30, .minK = 0}));

  // =============== Boundary Values Tests ==================
  // TC11: kR 0: the first reflected ray already has weight 0: none
  EXPECT_EQ(0u, bounces(Double3(0), {}));
  // TC12: kR 0.001: the first ray's weight is exactly the cut-off: cast (lowerThan is strict);
  // the second (1e-6) is not
  EXPECT_EQ(1u, bounces(Double3(0.001), {}));
}

TEST(RayCountTests, colourOfTheRegress) {
  // The mirrors emit (5,5,8); the perpendicular ray collects kR^j of that at every bounce j.
  // Ambient WHITE x 0.05 = (12.75,12.75,12.75).
  // ============ Equivalence Partitions Tests ==============
  // TC01: kR 1, 10 levels: 12.75 + 10·(5,5,8)
  {
    const SceneSetup<LitScene> s = hall(Double3(1));
    const Color c = WhittedTracer(s.scene).traceRay(betweenMirrors);
    EXPECT_NEAR(62.75, c.r(), 1e-9);
    EXPECT_NEAR(62.75, c.g(), 1e-9);
    EXPECT_NEAR(92.75, c.b(), 1e-9);
  }
  // TC02: kR 0.5: Σ_{j=0..9} 0.5^j = 2 − 0.5^9 = 1.998046875
  {
    const SceneSetup<LitScene> s = hall(Double3(0.5));
    const Color c = WhittedTracer(s.scene).traceRay(betweenMirrors);
    EXPECT_NEAR(12.75 + 5 * 1.998046875, c.r(), 1e-9);
    EXPECT_NEAR(12.75 + 8 * 1.998046875, c.b(), 1e-9);
  }
}

TEST(RayCountTests, renderCountsEveryRay) {
  // TC01: a 40x30 render of the hall casts 1200 primary rays, and secondary ones
  const SceneSetup<LitScene> s = course::hallOfMirrors();
  CameraSpec spec = s.camera;
  spec.nX = 40;
  spec.nY = 30;
  spec.vpHeight = spec.vpWidth * 30 / 40;
  Camera camera = spec.builder().setRayTracer(std::make_shared<WhittedTracer>(s.scene)).build();
  camera.renderImage();
  const RayCounts& counts = camera.rayCounts();
  EXPECT_EQ(1200u, counts.primary);
  // Most pixels see a mirror (several bounces each), the others the floor or a sphere (none):
  EXPECT_GT(counts.secondary, 600u);
  // TC02: the floor and the spheres are shaded, so shadow rays were cast (the mirrors have no
  // diffuse or specular term: none from them); every camera and secondary ray tested every shape
  // (the linear scan), a shadow ray at most every shape (it stops at an opaque blocker)
  EXPECT_GT(counts.shadow, 0u);
  const std::uint64_t n = s.scene.geometries.size();
  EXPECT_GE(counts.queries.shapeTests, (counts.primary + counts.secondary) * n);
  EXPECT_LT(counts.queries.shapeTests, counts.total() * n);
  // TC11: the course's traceRay(ray) counts nowhere: the render's counts are unchanged
  const RayCounts before = camera.rayCounts();
  (void)WhittedTracer(s.scene).traceRay(betweenMirrors);
  EXPECT_EQ(before, camera.rayCounts());
}

}  // namespace
}  // namespace rt
