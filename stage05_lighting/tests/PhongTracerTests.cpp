// Stage 5: the Phong tracer on tiny scenes whose pixel colour is worked out by hand.
//
// Most tests look at the plane z = -10 (normal +Z) from the origin along -Z, so the ray hits
// P = (0,0,-10) with v = (0,0,-1), n = (0,0,1), n·v = -1. A light at (0,3,-6) is then 5 away
// with l = (P - L)/5 = (0,-0.6,-0.8), n·l = -0.8, r = l - 2(l·n)n = (0,-0.6,0.8), -v·r = 0.8.
// With I0 = (100,200,300) and kC 1, kL 0.1, kQ 0.02 the attenuation is 1 + 0.5 + 0.5 = 2, so
// I_L(P) = (50,100,150). The material's kD is (0.5,0.25,1).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "TestSupport.h"
#include "geometries/Plane.h"
#include "geometries/Sphere.h"
#include "intersections/Geometries.h"
#include "lighting/LightSource.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"
#include "lighting/PhongTracer.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::colorNear;
using test::EPS;
using test::invalidArgumentMessage;
using test::sameBits;
using test::thrownMessage;
using test::tripleNear;
using ::testing::AllOf;
using ::testing::HasSubstr;

/// The tracer with its protected steps opened up for the tests.
class ExposedPhong : public PhongTracer {
 public:
  using PhongTracer::HitContext;
  using PhongTracer::localEffects;
  using PhongTracer::makeContext;
  using PhongTracer::PhongTracer;
  using PhongTracer::transmittance;
};

/// A tracer whose lights reach the surface through a fixed per-channel transmittance, the way
/// stage 6 plugs in its shadow rays; it records what it was asked.
class FixedTransmittanceTracer : public ExposedPhong {
 public:
  FixedTransmittanceTracer(const LitScene& scene, const Double3& t) : ExposedPhong(scene), t_(t) {}
  Double3 transmittance(const HitContext&, std::uint32_t light, const LightSample& sample,
                        const Double3&, SampleContext&) const override {
    ++calls;
    lastLight = light;
    lastDistance = sample.distance;
    return t_;
  }
  mutable int calls = 0;
  mutable std::uint32_t lastLight = 99;
  mutable double lastDistance = 0;

 private:
  Double3 t_;
};

const Double3 KD(0.5, 0.25, 1);
const Ray EYE_RAY(Point::ZERO, Vector(0, 0, -1));

Material diffuse() {
  Material m;
  m.kD = KD;
  return m;
}

/// The plane z = -10 facing the origin, with the given look.
LitScene planeScene(const Material& m, const Color& emission = Color::BLACK) {
  LitScene scene;
  scene.add(Plane(Point(0, 0, -10), Vector(0, 0, 1)), emission, m);
  return scene;
}

PointLight frontLight() {
  return PointLight(Color(100, 200, 300), Point(0, 3, -6)).setKl(0.1).setKq(0.02);
}

/// One pixel looking along -Z from the origin: its ray is EYE_RAY.
CameraSpec onePixelCamera() {
  return CameraSpec::squareView(Point::ZERO, Vector(0, 0, -1), 1, 1, 1);
}

TEST(PhongTracerTests, diffuse) {
  LitScene scene = planeScene(diffuse());
  scene.addLight(frontLight());
  const PhongTracer tracer(scene);
  // ============ Equivalence Partitions Tests ==============
  // TC01: diffuse only: I_L·kD·|n·l| = (50,100,150)·(0.5,0.25,1)·0.8 = (20,20,120)
  EXPECT_TRUE(colorNear(tracer.traceRay(EYE_RAY), 20, 20, 120));
  // TC02: the same value in the rendered image (through the stage-4 camera)
  const Camera camera = test::renderPhong(scene, onePixelCamera());
  EXPECT_TRUE(colorNear(camera.image().pixel(0, 0), 20, 20, 120));
  // TC03: a directional light along l = (0,-0.6,-0.8) with I0 = (50,100,150): the same colour
  LitScene directional = planeScene(diffuse());
  directional.addLight(DirectionalLight(Color(50, 100, 150), Vector(0, -3, -4)));
  EXPECT_TRUE(colorNear(PhongTracer(directional).traceRay(EYE_RAY), 20, 20, 120));

  // =============== Boundary Values Tests ==================
  // TC11: light straight above the hit point (l = -n, |n·l| = 1): I_L·kD;
  // d = 4: 1 + 0.4 + 0.32 = 1.72
  LitScene above = planeScene(diffuse());
  above.addLight(PointLight(Color(100, 200, 300), Point(0, 0, -6)).setKl(0.1).setKq(0.02));
  EXPECT_TRUE(colorNear(PhongTracer(above).traceRay(EYE_RAY), 50 / 1.72, 50 / 1.72, 300 / 1.72));
}

TEST(PhongTracerTests, specular) {
  // kS 0.5, nSh 2: kS·max(0,-v·r)^2 = 0.5·0.64 = 0.32
  Material m = diffuse();
  m.kS = Double3(0.5);
  m.shininess = 2;
  // ============ Equivalence Partitions Tests ==============
  // TC01: diffuse + specular: (50,100,150)·((0.4,0.2,0.8) + 0.32) = (36,52,168)
  LitScene scene = planeScene(m);
  scene.addLight(frontLight());
  EXPECT_TRUE(colorNear(PhongTracer(scene).traceRay(EYE_RAY), 36, 52, 168));
  // TC02: specular only (kD 0): (50,100,150)·0.32 = (16,32,48)
  Material shiny;
  shiny.kS = Double3(0.5);
  shiny.shininess = 2;
  LitScene shinyScene = planeScene(shiny);
  shinyScene.addLight(frontLight());
  EXPECT_TRUE(colorNear(PhongTracer(shinyScene).traceRay(EYE_RAY), 16, 32, 48));
  // TC03: a per-channel kS (0.25,0.5,1) and nSh 3: 0.8^3 = 0.512 ->
  // (50·0.25, 100·0.5, 150·1)·0.512 = (6.4, 25.6, 76.8)
  shiny.kS = Double3(0.25, 0.5, 1);
  shiny.shininess = 3;
  LitScene perChannel = planeScene(shiny);
  perChannel.addLight(frontLight());
  EXPECT_TRUE(colorNear(PhongTracer(perChannel).traceRay(EYE_RAY), 6.4, 25.6, 76.8));

  // =============== Boundary Values Tests ==================
  // TC11: the highlight turned away from the viewer: -v·r < 0 gives no specular, even with an
  // even exponent. Ray from (-10,0,0) along (1,0,-1) hits (0,0,-10) with v = (1,0,-1)/sqrt(2);
  // light at (-4,0,-7), 5 away, l = (0.8,0,-0.6), r = (0.8,0,0.6), -v·r = -0.2/sqrt(2) < 0.
  // Diffuse only: (100,200,300)·(0.5,0.25,1)·0.6 = (30,30,180)
  LitScene away = planeScene(m);
  away.addLight(PointLight(Color(100, 200, 300), Point(-4, 0, -7)));
  const Ray oblique(Point(-10, 0, 0), Vector(1, 0, -1));
  EXPECT_TRUE(colorNear(PhongTracer(away).traceRay(oblique), 30, 30, 180));
  // TC12: the course's SHININESS 301 at -v·r = 0.8: kS·0.8^301 (about 3e-30), essentially 0
  shiny.kS = Double3(0.5);
  shiny.shininess = 301;
  LitScene sharp = planeScene(shiny);
  sharp.addLight(frontLight());
  const double spec = 0.5 * std::pow(0.8, 301);
  EXPECT_TRUE(
      colorNear(PhongTracer(sharp).traceRay(EYE_RAY), 50 * spec, 100 * spec, 150 * spec, 1e-25));
  // TC13: nSh 0 where -v·r > 0: 0.8^0 = 1 -> kS·I_L = (25,50,75)
  shiny.shininess = 0;
  LitScene flat = planeScene(shiny);
  flat.addLight(frontLight());
  EXPECT_TRUE(colorNear(PhongTracer(flat).traceRay(EYE_RAY), 25, 50, 75));
}

TEST(PhongTracerTests, spotLight) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a spot at (0,3,-6) aimed along -Z with narrowBeam 2: direction·l = 0.8, factor 0.64,
  // I_L = (50,100,150)·0.64 = (32,64,96); diffuse (0.4,0.2,0.8) -> (12.8,12.8,76.8)
  LitScene scene = planeScene(diffuse());
  scene.addLight(SpotLight(Color(100, 200, 300), Point(0, 3, -6), Vector(0, 0, -1))
                     .setKl(0.1)
                     .setKq(0.02)
                     .setNarrowBeam(2));
  EXPECT_TRUE(colorNear(PhongTracer(scene).traceRay(EYE_RAY), 12.8, 12.8, 76.8));
  // TC02: the same in the rendered image
  const Camera camera = test::renderPhong(scene, onePixelCamera());
  EXPECT_TRUE(colorNear(camera.image().pixel(0, 0), 12.8, 12.8, 76.8));

  // =============== Boundary Values Tests ==================
  // TC11: the point outside the cone (the spot aimed along +Y, direction·l = -0.6): the light
  // gives nothing; emission (1,2,3) + ambient (100,100,100)·0.1 = (11,12,13) exactly
  LitScene outside = planeScene(diffuse(), Color(1, 2, 3));
  outside.ambientLight = AmbientLight(Color(100, 100, 100), 0.1);
  outside.addLight(SpotLight(Color(100, 200, 300), Point(0, 3, -6), Vector(0, 1, 0))
                       .setKl(0.1)
                       .setKq(0.02)
                       .setNarrowBeam(2));
  EXPECT_TRUE(colorNear(PhongTracer(outside).traceRay(EYE_RAY), 11, 12, 13));
}

TEST(PhongTracerTests, sameSideRule) {
  const Color emission(10, 20, 30);
  const AmbientLight ambient(Color(100, 100, 100), 0.05);  // (5,5,5)
  // ============ Equivalence Partitions Tests ==============
  // TC01: light behind the surface, viewer in front: (n·l)(n·v) = (0.8)(-1) < 0 -> emission +
  // ambient only = (15,25,35). Light at (0,3,-14): l = (0,-0.6,0.8), n·l = 0.8.
  LitScene behind = planeScene(diffuse(), emission);
  behind.ambientLight = ambient;
  behind.addLight(PointLight(Color(100, 200, 300), Point(0, 3, -14)).setKl(0.1).setKq(0.02));
  EXPECT_TRUE(colorNear(PhongTracer(behind).traceRay(EYE_RAY), 15, 25, 35));
  // TC02: the control: the mirrored light in front adds its diffuse (20,20,120) -> (35,45,155)
  LitScene front = planeScene(diffuse(), emission);
  front.ambientLight = ambient;
  front.addLight(frontLight());
  EXPECT_TRUE(colorNear(PhongTracer(front).traceRay(EYE_RAY), 35, 45, 155));
  // TC03: viewer behind the plane (ray from (0,0,-20) along +Z, n·v = 1), light in front
  // (n·l = -0.8): opposite sides -> (15,25,35)
  const Ray fromBehind(Point(0, 0, -20), Vector(0, 0, 1));
  EXPECT_TRUE(colorNear(PhongTracer(front).traceRay(fromBehind), 15, 25, 35));
  // TC04: viewer and light both behind (n·v = 1, n·l = 0.8): the same side counts, with |n·l|
  EXPECT_TRUE(colorNear(PhongTracer(behind).traceRay(fromBehind), 35, 45, 155));

  // =============== Boundary Values Tests ==================
  // TC11: light in the plane of the surface (at (0,5,-10): l = (0,-1,0), n·l = 0): no light
  LitScene grazingLight = planeScene(diffuse(), emission);
  grazingLight.ambientLight = ambient;
  grazingLight.addLight(PointLight(Color(100, 200, 300), Point(0, 5, -10)));
  EXPECT_TRUE(colorNear(PhongTracer(grazingLight).traceRay(EYE_RAY), 15, 25, 35));
  // TC12: n·v = 0 (a view along the surface): only the emission, whatever the lights
  const ExposedPhong tracer(front);
  const ExposedPhong::HitContext grazingView{
      0, Point(0, 0, -10), Vector(0, 0, 1), Vector(0, 1, 0), 0.0, 0, &front.appearances[0]};
  test::TestSample sample;
  EXPECT_TRUE(colorNear(tracer.localEffects(grazingView, Double3::ONE, sample.ctx), 10, 20, 30));
}

TEST(PhongTracerTests, ambientAndEmission) {
  // A sphere of radius 1 at (0,0,-5): the eye ray hits (0,0,-4) with n = (0,0,1).
  LitScene scene;
  scene.background = Color(7, 8, 9);
  scene.ambientLight = AmbientLight(Color(100, 50, 20), Double3(0.5, 0.2, 1));  // (50,10,20)
  scene.add(Sphere(Point(0, 0, -5), 1), Color(1, 2, 3));
  // ============ Equivalence Partitions Tests ==============
  // TC01: no material, no light: Ia·kA + emission = (51,12,23)
  EXPECT_TRUE(colorNear(PhongTracer(scene).traceRay(EYE_RAY), 51, 12, 23));
  // TC02: a light changes nothing on a surface with kD = kS = 0
  scene.addLight(PointLight(Color(1000, 1000, 1000), Point(0, 0, 0)));
  EXPECT_TRUE(colorNear(PhongTracer(scene).traceRay(EYE_RAY), 51, 12, 23));
  // TC03: a miss sees the background, without the ambient light
  EXPECT_TRUE(colorNear(PhongTracer(scene).traceRay(Ray(Point::ZERO, Vector(0, 1, 0))), 7, 8, 9));
  // TC04: two lights add up, and ambient and emission are added once, not per light:
  // plane, emission (1,2,3), ambient (5,5,5), frontLight (20,20,120) + a directional light
  // (40,40,40) straight down -Z (|n·l| = 1): (1,2,3) + (5,5,5) + (20,20,120) + (20,10,40)
  LitScene two = planeScene(diffuse(), Color(1, 2, 3));
  two.ambientLight = AmbientLight(Color(100, 100, 100), 0.05);
  two.addLight(frontLight());
  two.addLight(DirectionalLight(Color(40, 40, 40), Vector(0, 0, -1)));
  EXPECT_TRUE(colorNear(PhongTracer(two).traceRay(EYE_RAY), 46, 37, 168));

  // =============== Boundary Values Tests ==================
  // TC11: no ambient light (the default): emission alone
  LitScene dark;
  dark.add(Sphere(Point(0, 0, -5), 1), Color(1, 2, 3));
  EXPECT_TRUE(colorNear(PhongTracer(dark).traceRay(EYE_RAY), 1, 2, 3));
  // TC12: an empty scene: the background everywhere
  LitScene empty;
  empty.background = Color(7, 8, 9);
  EXPECT_TRUE(colorNear(PhongTracer(empty).traceRay(EYE_RAY), 7, 8, 9));
}

TEST(PhongTracerTests, transmittanceSeam) {
  LitScene scene = planeScene(diffuse());
  scene.addLight(frontLight());
  test::TestSample ts;
  // ============ Equivalence Partitions Tests ==============
  // TC01: this stage's transmittance is (1,1,1)
  const ExposedPhong plain(scene);
  const auto h = plain.makeContext(Hit{10, 0}, EYE_RAY);
  const LightSample sample = *illuminate(scene.lights[0], h.point);
  EXPECT_EQ(plain.transmittance(h, 0, sample, Double3::ONE, ts.ctx), Double3::ONE);
  // TC02: a derived tracer's transmittance scales each light per channel:
  // (20,20,120)·(0.5,0.25,1) = (10,5,120); it is asked once, for light 0 at distance 5
  const FixedTransmittanceTracer half(scene, Double3(0.5, 0.25, 1));
  EXPECT_TRUE(colorNear(half.traceRay(EYE_RAY), 10, 5, 120));
  EXPECT_EQ(half.calls, 1);
  EXPECT_EQ(half.lastLight, 0u);
  EXPECT_NEAR(half.lastDistance, 5, EPS);
  // TC03: the path weight k only decides whether a light is worth it; it does not scale the
  // local colour (the recursive caller does): k = (0.5,0.5,0.5) still gives (20,20,120)
  EXPECT_TRUE(colorNear(plain.localEffects(h, Double3(0.5), ts.ctx), 20, 20, 120));

  // =============== Boundary Values Tests ==================
  // TC11: transmittance·k below MIN_CALC_COLOR_K = 0.001 in every channel: the light is skipped
  // (black), where scaling would have given (0.018,0.018,0.108)
  const FixedTransmittanceTracer opaque(scene, Double3(0.0009));
  EXPECT_TRUE(colorNear(opaque.traceRay(EYE_RAY), 0, 0, 0));
  // TC12: one channel at 0.002 keeps the light (the course's lowerThan needs all three below):
  // (20,20,120)·(0.0009,0.0009,0.002) = (0.018,0.018,0.24)
  const FixedTransmittanceTracer tinted(scene, Double3(0.0009, 0.0009, 0.002));
  EXPECT_TRUE(colorNear(tinted.traceRay(EYE_RAY), 0.018, 0.018, 0.24));
  // TC13: the same transmittance 0.5 with a path weight k = 0.001: 0.0005 < 0.001, skipped
  const FixedTransmittanceTracer halfAgain(scene, Double3(0.5));
  EXPECT_TRUE(colorNear(halfAgain.localEffects(h, Double3(0.001), ts.ctx), 0, 0, 0));
}

/// A tracer that records every light it is asked the transmittance of, with the sample it was
/// handed (the transmittance is (1,1,1)).
class RecordingTracer : public ExposedPhong {
 public:
  using ExposedPhong::ExposedPhong;
  Double3 transmittance(const HitContext&, std::uint32_t light, const LightSample& sample,
                        const Double3&, SampleContext&) const override {
    lights.push_back(light);
    samples.push_back(sample);
    return Double3::ONE;
  }
  mutable std::vector<std::uint32_t> lights;
  mutable std::vector<LightSample> samples;
};

// localEffects works each light's sample out one light ahead (while the light before it is
// shaded): each light must still be shaded with its own sample, the lights whose sample does not
// exist (P is the light's position) skipped without shifting the others.
TEST(PhongTracerTests, eachLightItsOwnSample) {
  // The plane z = -10 seen at P = (0,0,-10); lights 0 and 3 sit at P (no sample), the others
  // are of three kinds, all on the viewer's side.
  LitScene scene = planeScene(diffuse(), Color(1, 2, 3));
  scene.addLight(PointLight(Color(500, 500, 500), Point(0, 0, -10)));
  scene.addLight(DirectionalLight(Color(50, 100, 150), Vector(0, -3, -4)));
  scene.addLight(SpotLight(Color(100, 200, 300), Point(0, 3, -6), Vector(0, 0.1, -1))
                     .setKl(0.1)
                     .setNarrowBeam(3));
  scene.addLight(PointLight(Color(500, 500, 500), Point(0, 0, -10)));
  scene.addLight(PointLight(Color(70, 80, 90), Point(2, -1, -3)).setKq(0.01));
  const RecordingTracer tracer(scene);
  const auto h = tracer.makeContext(Hit{10, 0}, EYE_RAY);
  ASSERT_EQ(h.point, Point(0, 0, -10));
  ASSERT_FALSE(illuminate(scene.lights[0], h.point).has_value());
  test::TestSample ts;
  const Color c = tracer.localEffects(h, Double3::ONE, ts.ctx);
  // ============ Equivalence Partitions Tests ==============
  // TC01: lights 1, 2 and 4 are asked for, in order, each with its own sample, bit for bit
  EXPECT_EQ((std::vector<std::uint32_t>{1, 2, 4}), tracer.lights);
  ASSERT_EQ(tracer.lights.size(), tracer.samples.size());
  for (std::size_t i = 0; i < tracer.lights.size(); ++i) {
    const LightSample own = *illuminate(scene.lights[tracer.lights[i]], h.point);
    const LightSample& got = tracer.samples[i];
    EXPECT_TRUE(sameBits(own.intensity.rgb(), got.intensity.rgb())) << tracer.lights[i];
    EXPECT_TRUE(sameBits(own.l.xyz(), got.l.xyz())) << tracer.lights[i];
    EXPECT_EQ(own.distance, got.distance) << tracer.lights[i];
  }
  // TC02: the colour, bit for bit, is the emission plus the lights' diffuse terms added one by
  // one in the list's order, I_L·kD·|n·l| from each light's own sample (n = (0,0,1))
  Double3 expected = Color(1, 2, 3).rgb();
  for (const std::uint32_t light : {1u, 2u, 4u}) {
    const LightSample own = *illuminate(scene.lights[light], h.point);
    expected = expected + own.intensity.rgb() * Double3::ONE * (KD * std::abs(own.l.xyz().z));
  }
  EXPECT_TRUE(sameBits(expected, c.rgb())) << c.rgb().str() << " vs " << expected.str();

  // =============== Boundary Values Tests ==================
  // TC11: the last light without a sample, and a single light: nothing shifts
  LitScene lastAtP = planeScene(diffuse());
  lastAtP.addLight(DirectionalLight(Color(50, 100, 150), Vector(0, -3, -4)));
  lastAtP.addLight(PointLight(Color(500, 500, 500), Point(0, 0, -10)));
  const RecordingTracer last(lastAtP);
  (void)last.localEffects(last.makeContext(Hit{10, 0}, EYE_RAY), Double3::ONE, ts.ctx);
  EXPECT_EQ(std::vector<std::uint32_t>{0}, last.lights);
  LitScene single = planeScene(diffuse());
  single.addLight(frontLight());
  const RecordingTracer one(single);
  (void)one.localEffects(one.makeContext(Hit{10, 0}, EYE_RAY), Double3::ONE, ts.ctx);
  ASSERT_EQ(std::vector<std::uint32_t>{0}, one.lights);
  EXPECT_EQ(5.0, one.samples[0].distance);
}

TEST(PhongTracerTests, makeContext) {
  LitScene scene;
  scene.add(Sphere(Point(0, 0, -50), 1));
  scene.add(Sphere(Point(0, 0, -5), 1), Color(1, 2, 3));
  const ExposedPhong tracer(scene);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the nearer sphere (index 1) wins at t = 4: point (0,0,-4), normal (0,0,1),
  // v = (0,0,-1), n·v = -1, and its own appearance
  const auto hit = scene.geometries.closestHit(EYE_RAY);
  ASSERT_TRUE(hit.has_value());
  const auto h = tracer.makeContext(*hit, EYE_RAY);
  EXPECT_EQ(h.geometry, 1u);
  EXPECT_TRUE(tripleNear(h.point.xyz(), Double3(0, 0, -4)));
  EXPECT_TRUE(tripleNear(h.normal.xyz(), Double3(0, 0, 1)));
  EXPECT_TRUE(tripleNear(h.v.xyz(), Double3(0, 0, -1)));
  EXPECT_NEAR(h.nv, -1, EPS);
  EXPECT_EQ(h.appearance, &scene.appearanceOf(1));
  EXPECT_EQ(h.appearanceRow, 1u);

  // =============== Boundary Values Tests ==================
  // TC11: a ray from inside the sphere sees its inside: the outward normal, n·v = +1
  const Ray inside(Point(0, 0, -5), Vector(0, 0, 1));
  const auto out = scene.geometries.closestHit(inside);
  ASSERT_TRUE(out.has_value());
  const auto hi = tracer.makeContext(*out, inside);
  EXPECT_TRUE(tripleNear(hi.point.xyz(), Double3(0, 0, -4)));
  EXPECT_NEAR(hi.nv, 1, EPS);
}

TEST(PhongTracerTests, constructorChecks) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a scene built with add() is accepted
  LitScene ok = planeScene(diffuse());
  ok.addLight(frontLight());
  EXPECT_NO_THROW(PhongTracer{ok});
  // TC02: shapes added behind LitScene's back: logic_error naming both sizes
  LitScene mismatched;
  mismatched.add(Sphere(Point(0, 0, -5), 1));
  mismatched.geometries.add(Sphere(Point(0, 0, -9), 1));
  EXPECT_THAT(thrownMessage<std::logic_error>([&] { PhongTracer tracer(mismatched); }),
              HasSubstr("2 geometries but 1 appearance indices"));
  // TC03: an invalid light pushed straight into the list is caught here, naming its index
  LitScene badLight = planeScene(diffuse());
  badLight.lights.push_back(PointLight(Color::WHITE, Point::ZERO).setKc(0));
  EXPECT_THAT(invalidArgumentMessage([&] { PhongTracer tracer(badLight); }),
              AllOf(HasSubstr("lights[0]"), HasSubstr("kC")));
  // TC04: an invalid material pushed straight into the table, naming its row and field
  LitScene badMaterial = planeScene(diffuse());
  badMaterial.appearances.push_back({});
  badMaterial.appearances.back().material.kS = Double3(-1);
  badMaterial.geometries.add(Sphere(Point(0, 0, -5), 1));
  badMaterial.appearanceIndex.push_back(1);
  EXPECT_THAT(invalidArgumentMessage([&] { PhongTracer tracer(badMaterial); }),
              AllOf(HasSubstr("appearances[1]"), HasSubstr("kS")));
  // TC05: a shape whose row does not exist: the shape, its row and the table's size
  LitScene badRow = planeScene(diffuse());
  badRow.appearanceIndex[0] = 3;
  EXPECT_THAT(thrownMessage<std::logic_error>([&] { PhongTracer tracer(badRow); }),
              HasSubstr("geometry 0 uses appearance 3 but the table has 1 rows"));

  // =============== Boundary Values Tests ==================
  // TC11: an empty scene is accepted (0 == 0)
  EXPECT_NO_THROW(PhongTracer{LitScene{}});
  // TC12: rows without shapes are fine (a table may hold looks no shape uses yet)
  LitScene extra;
  extra.appearances.push_back({});
  EXPECT_NO_THROW(PhongTracer{extra});
  // TC13: the last row is a valid index, one past it is not
  LitScene edge = planeScene(diffuse());
  edge.appearances.push_back({});
  edge.appearanceIndex[0] = 1;
  EXPECT_NO_THROW(PhongTracer{edge});
  edge.appearanceIndex[0] = 2;
  EXPECT_THROW(PhongTracer{edge}, std::logic_error);
}

TEST(PhongTracerTests, accelerator) {
  LitScene scene = planeScene(diffuse());
  scene.addLight(frontLight());
  // ============ Equivalence Partitions Tests ==============
  // TC01: an accelerator over the same shapes gives the same colour
  Geometries same;
  same.add(Plane(Point(0, 0, -10), Vector(0, 0, 1)));
  EXPECT_TRUE(colorNear(PhongTracer(scene, &same).traceRay(EYE_RAY), 20, 20, 120));

  // =============== Boundary Values Tests ==================
  // TC11: the tracer really asks the accelerator: an empty one sees only the background
  const Geometries none;
  EXPECT_TRUE(colorNear(PhongTracer(scene, &none).traceRay(EYE_RAY), 0, 0, 0));
}

}  // namespace
}  // namespace rt
