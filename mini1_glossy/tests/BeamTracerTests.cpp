// Mini project 1: the beams tracer. Without blur it is the Whitted tracer, bit for bit; a glossy
// mirror's beam converges to the analytic fraction of an emitter it sees; the depth setting
// decides where beams are cast; diffused glass blurs what is behind it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "camera/Camera.h"
#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "glossy/BeamTracer.h"
#include "reflections/CourseScenes.h"
#include "support/AllocationCounter.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;

/// Renders s through its camera at n x n pixels with tracer and the centre sampler.
Image render(const SceneSetup<LitScene>& s, const RayTracer& tracer, int n, RayCounts* counts) {
  CameraSpec spec = s.camera;
  spec.nX = spec.nY = n;
  const Camera camera = spec.builder().build();
  Image image(n, n);
  const RayCounts c = renderBlock({camera, tracer, CenterSampler(5)}, {0, 0, n, n}, image);
  if (counts) *counts = c;
  return image;
}

TEST(BeamTracerTests, withoutBlurItIsTheWhittedTracer) {
  // TC01: every stage-7 scene, no material blurs and no light has a size: the same bits as
  // the Whitted tracer, pixel by pixel, and the same ray counts
  for (const CourseScene& entry : reflectionScenes()) {
    const SceneSetup<LitScene> s = entry.make();
    RayCounts a, b;
    const Image whitted = render(s, WhittedTracer(s.scene), 40, &a);
    const Image beams = render(s, BeamTracer(s.scene), 40, &b);
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x)
        ASSERT_TRUE(sameBits(whitted.pixel(x, y), beams.pixel(x, y))) << entry.name;
    EXPECT_EQ(a, b) << entry.name;
  }
}

/*
 * A glossy mirror seen from straight above: the floor z = 0 (kR 1, nothing else) and, at height
 * H = 10, an emitting square covering x > c·H/d of the sky, emission (0, 0, 1000). A ray straight
 * down hits the mirror at the origin; its reflection goes straight up, and the beam's target
 * circle (radius r at distance d) maps onto the emitter's plane by the central projection from the
 * origin (scale H/d). So the beam sees the emitter through the part of its circle with x > c: the
 * circular segment of area r²·acos(c/r) − c·√(r² − c²), a fraction f of πr². The beam's colour is
 * the mirror's kR (1) times 1000·f in blue.
 */
TEST(BeamTracerTests, glossyBeamConvergesToTheAnalyticFraction) {
  const double r = 1, d = 10, c = 0.3, H = 10;
  LitScene s;
  Material mirror;
  mirror.kR = Double3(1);
  mirror.reflectedBeam = {d, r, 32};
  const std::uint32_t glossy = s.addAppearance(Color::BLACK, mirror);
  s.add(Plane(Point(0, 0, 0), Vector(0, 0, 1)), glossy);
  const double x0 = c * H / d;
  s.add(
      Polygon{Point(x0, -1000, H), Point(1000, -1000, H), Point(1000, 1000, H), Point(x0, 1000, H)},
      Color(0, 0, 1000));
  const BeamTracer tracer(s, nullptr, {.maxLevel = 2, .minK = 0});
  const double fraction =
      (r * r * std::acos(c / r) - c * std::sqrt(r * r - c * c)) / (std::numbers::pi * r * r);
  // TC01: the mean over 64 pixels' samples (different random numbers) is 1000·f within 0.5%.
  // Why that tolerance: the 32 x 32 grid keeps 812 cells; only the ~N = 32 cells the segment's
  // chord crosses are random (each sees the emitter or not), so one beam's fraction has a
  // standard deviation of at most √(32·¼)/812 ≈ 0.35%, and 64 beams bring it to 0.044%. What is
  // left is the grid's own approximation of the circle by whole cells: its union differs from the
  // disk along the rim, ~0.2% of the area for N = 32. 0.5% covers both with a wide margin.
  const Ray down(Point(0, 0, 5), Vector(0, 0, -1));
  double sum = 0, sumSquares = 0;
  for (std::uint32_t px = 0; px < 64; ++px) {
    RayCounts counts;
    SampleContext ctx(static_cast<int>(px), 0, 0, 11, counts);
    const double blue = tracer.traceRay(down, ctx).b();
    sum += blue;
    sumSquares += blue * blue;
    EXPECT_EQ(static_cast<std::uint64_t>(beamCellCount(32)), counts.secondary);
  }
  const double mean = sum / 64, variance = sumSquares / 64 - mean * mean;
  EXPECT_NEAR(1000 * fraction, mean, 0.005 * 1000 * fraction);
  // TC02: and each beam's own estimate spreads as stratified sampling predicts: a standard
  // deviation well under 1% of the value (a beam of 812 independent rays would give ~1.7%)
  EXPECT_LT(std::sqrt(variance), 0.01 * 1000 * fraction);
  EXPECT_GT(variance, 0);  // the samples are jittered: beams differ
}

/// Two parallel glossy mirrors facing each other (z = 0 facing up, z = 10 facing down), a ray
/// between them perpendicular to both; maxLevel 3, no cut-off.
LitScene mirrors() {
  LitScene s;
  Material m;
  m.kR = Double3(1);
  m.reflectedBeam = {5, 0.1, 10};
  const std::uint32_t glossy = s.addAppearance(Color(1, 1, 1), m);
  s.add(Plane(Point(0, 0, 0), Vector(0, 0, 1)), glossy);
  s.add(Plane(Point(0, 0, 10), Vector(0, 0, -1)), glossy);
  return s;
}

TEST(BeamTracerTests, beamDepth) {
  const LitScene s = mirrors();
  const Ray down(Point(0, 0, 5), Vector(0, 0, -1));
  const auto secondary = [&](BeamDepth depth) {
    const BeamTracer tracer(s, nullptr, {.maxLevel = 3, .minK = 0}, {depth});
    RayCounts counts;
    SampleContext ctx(0, 0, 0, 0, counts);
    tracer.traceRay(down, ctx);
    return counts.secondary;
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: first bounce only (the default): the primary hit (level 3) casts a beam of 80 rays;
  // each of their hits (level 2) casts one ray; hits at level 1 cast none: 80 + 80
  EXPECT_EQ(160u, secondary(BeamDepth::FirstBounce));
  // TC02: every bounce: the level-2 hits cast beams too: 80 + 80·80
  EXPECT_EQ(6480u, secondary(BeamDepth::EveryBounce));
  // =============== Boundary Values Tests ==================
  // TC11: the default setting is the first bounce
  EXPECT_EQ(BeamDepth::FirstBounce, BeamTracer(s).beamSettings().beamDepth);
}

TEST(BeamTracerTests, diffusedGlassBlursWhatIsBehindIt) {
  // A pane of glass (kT 1) at z = 5 in front of a half-lit wall at z = 0: x < 0 emits 200, x > 0
  // nothing. Looking straight down at x = 0 through the pane:
  Material glass;
  glass.kT = Double3(1);
  const auto pane = [&](const BeamSettings& refracted) {
    LitScene g;
    Material m = glass;
    m.refractedBeam = refracted;
    const std::uint32_t row = g.addAppearance(Color::BLACK, m);
    g.add(Polygon{Point(-50, -50, 5), Point(50, -50, 5), Point(50, 50, 5), Point(-50, 50, 5)}, row);
    g.add(Polygon{Point(-50, -50, 0), Point(0, -50, 0), Point(0, 50, 0), Point(-50, 50, 0)},
          Color(200, 200, 200));
    return g;
  };
  const LitScene clear = pane({}), frosted = pane({5, 1, 16});
  // ============ Equivalence Partitions Tests ==============
  // TC01: clear glass at x = -0.5 and x = +0.5: the sharp wall, 200 and 0
  const BeamTracer sharp(clear);
  EXPECT_NEAR(200, sharp.traceRay(Ray(Point(-0.5, 0, 10), Vector(0, 0, -1))).r(), 1e-9);
  EXPECT_NEAR(0, sharp.traceRay(Ray(Point(0.5, 0, 10), Vector(0, 0, -1))).r(), 1e-9);
  // TC02: frosted glass (a refracted beam of radius 1 at distance 5: it spreads over ±1 on the
  // wall): both points see part of each side, the dark one some light, the lit one some dark
  const BeamTracer blurred(frosted);
  const double left = blurred.traceRay(Ray(Point(-0.5, 0, 10), Vector(0, 0, -1))).r();
  const double right = blurred.traceRay(Ray(Point(0.5, 0, 10), Vector(0, 0, -1))).r();
  EXPECT_GT(left, 100);
  EXPECT_LT(left, 195);
  EXPECT_GT(right, 5);
  EXPECT_LT(right, 100);
  // =============== Boundary Values Tests ==================
  // TC11: far from the edge (x = -5, beyond the spread) the frosted pane shows the wall as is
  EXPECT_NEAR(200, blurred.traceRay(Ray(Point(-5, 0, 10), Vector(0, 0, -1))).r(), 1e-9);
}

TEST(BeamTracerTests, allocatesNothing) {
  // TC01: the galaxy's materials on the all-features scene: every shape's material blurs both
  // rays and the lights have sizes; a rendered block allocates nothing
  const SceneSetup<LitScene> base = course::allFeaturesAbove();
  LitScene s = base.scene;
  for (Appearance& a : s.appearances)
    a.material.reflectedBeam = a.material.refractedBeam = {12, 0.2, 4};
  for (LightSource& light : s.lights)
    if (PointLight* p = std::get_if<PointLight>(&light))
      p->setRadius(3).setShadowSamples(4);
    else if (SpotLight* q = std::get_if<SpotLight>(&light))
      q->setRadius(3).setShadowSamples(4);
  const BeamTracer tracer(s);
  CameraSpec spec = base.camera;
  spec.nX = spec.nY = 24;
  const Camera camera = spec.builder().build();
  Image image(24, 24);
  RayCounts counts;
  EXPECT_EQ(0, testing::allocationsDuring([&] {
              counts = renderBlock({camera, tracer, CenterSampler()}, {0, 0, 24, 24}, image);
            }));
  EXPECT_GT(counts.secondary, 24u * 24u);
  EXPECT_GT(counts.shadow, 24u * 24u);
}

}  // namespace
}  // namespace rt
