// Mini project 1: soft shadows. A light with a radius is a disk facing the shaded point; its
// transmittance is the mean over its shadow rays, so a point in the penumbra sees the fraction of
// the disk that is not blocked.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "glossy/BeamTracer.h"

namespace rt {
namespace {

/// The tracer's transmittance hook, opened for the tests.
class Probe : public BeamTracer {
 public:
  using BeamTracer::BeamTracer;
  using BeamTracer::HitContext;
  using BeamTracer::makeContext;
  using BeamTracer::transmittance;
};

/*
 * A floor z = 0 (diffuse), a point light of radius R at (0, 0, 20), and an opaque half-plane
 * occluder at z = 10 covering x < 0. Seen from a floor point (x, 0, 0) the occluder's edge passes
 * in front of the disk; below the edge (x = 0) it hides exactly half of it (by symmetry).
 */
LitScene penumbraScene(double radius, int samples) {
  LitScene s;
  Material floor;
  floor.kD = Double3(1);
  s.add(Plane(Point(0, 0, 0), Vector(0, 0, 1)), Color::BLACK, floor);
  s.add(Polygon{Point(-100, -100, 10), Point(0, -100, 10), Point(0, 100, 10), Point(-100, 100, 10)},
        Color::BLACK);
  s.addLight(PointLight(Color(100, 100, 100), Point(0, 0, 20))
                 .setRadius(radius)
                 .setShadowSamples(samples));
  return s;
}

/// The transmittance towards the light at floor point (x, 0, 0), for the sample (px, 0, 0).
double transmittanceAt(const Probe& tracer, const LitScene& s, double x, int px,
                       RayCounts& counts) {
  const Ray down(Point(x, 0, 5), Vector(0, 0, -1));
  const auto h = tracer.makeContext(Hit{5, 0}, down);
  const LightSample sample = *illuminate(s.lights[0], h.point);
  SampleContext ctx(px, 0, 0, 3, counts);
  return tracer.transmittance(h, 0, sample, Double3::ONE, ctx).x;
}

TEST(SoftShadowTests, penumbraSeesTheVisibleFractionOfTheDisk) {
  const LitScene s = penumbraScene(4, 64);
  const Probe tracer(s);
  RayCounts counts;
  // ============ Equivalence Partitions Tests ==============
  // TC01: below the occluder's edge, half the disk is hidden: the mean over 256 shading samples
  // is 0.5 within 0.01. Each estimate uses 64 points of a shifted Fibonacci lattice on the disk;
  // only the points near the edge's chord are uncertain (~√64 = 8 of them), so one estimate is
  // within a few 1/64 of 0.5 and the mean of 256 within a fraction of a percent.
  double sum = 0;
  for (int px = 0; px < 256; ++px) {
    const double t = transmittanceAt(tracer, s, 0, px, counts);
    EXPECT_NEAR(0.5, t, 4.0 / 64) << px;
    sum += t;
  }
  EXPECT_NEAR(0.5, sum / 256, 0.01);
  // TC02: every estimate cast 64 shadow rays (and nothing else)
  EXPECT_EQ(256u * 64u, counts.shadow);
  EXPECT_EQ(0u, counts.primary + counts.secondary);
  // TC03: well inside the umbra (x = -10) and well outside (x = 10): 0 and 1 exactly
  EXPECT_EQ(0.0, transmittanceAt(tracer, s, -10, 0, counts));
  EXPECT_EQ(1.0, transmittanceAt(tracer, s, 10, 0, counts));
  // TC04: across the penumbra the light grows steadily: x = -1 darker than 0, darker than +1
  const double a = transmittanceAt(tracer, s, -1, 7, counts),
               b = transmittanceAt(tracer, s, 0, 7, counts),
               c = transmittanceAt(tracer, s, 1, 7, counts);
  EXPECT_LT(a, b);
  EXPECT_LT(b, c);
  EXPECT_GT(a, 0);
  EXPECT_LT(c, 1);
}

TEST(SoftShadowTests, aPointLightStaysSharp) {
  // =============== Boundary Values Tests ==================
  // TC11: radius 0, or a single sample: the shadow tracer's one shadow ray towards the light's
  // centre: a hard edge, lit (1) just right of it at x = 0.01, dark (0) just left at x = -0.01,
  // with one shadow ray each
  for (const auto& [radius, samples] : {std::pair{0.0, 64}, std::pair{4.0, 1}}) {
    const LitScene s = penumbraScene(radius, samples);
    const Probe tracer(s);
    RayCounts counts;
    EXPECT_EQ(1.0, transmittanceAt(tracer, s, 0.01, 0, counts));
    EXPECT_EQ(0.0, transmittanceAt(tracer, s, -0.01, 0, counts));
    EXPECT_EQ(2u, counts.shadow);
  }
}

}  // namespace
}  // namespace rt
