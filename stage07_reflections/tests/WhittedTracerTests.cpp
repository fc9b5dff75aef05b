// Tests of WhittedTracer with hand-computed colours: a mirror, transparent sheets, the missed
// secondary ray, the depth limit, the index of refraction (Fresnel at normal incidence, total
// internal reflection), the secondary-ray hook, the secondary rays' order, and the settings'
// validation.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "lighting/LightSource.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"
#include "primitives/Color.h"
#include "reflections/WhittedTracer.h"
#include "shadows/RayOffset.h"
#include "shadows/ShadowTracer.h"

namespace rt {
namespace {

constexpr double EPS = 1e-9;

void expectColor(const Color& expected, const Color& actual) {
  EXPECT_NEAR(expected.r(), actual.r(), EPS);
  EXPECT_NEAR(expected.g(), actual.g(), EPS);
  EXPECT_NEAR(expected.b(), actual.b(), EPS);
}

/// The square |x|, |y| <= 10 in the plane z, normal +z (counter-clockwise seen from +z).
Polygon square(double z) {
  return Polygon{Point(-10, -10, z), Point(10, -10, z), Point(10, 10, z), Point(-10, 10, z)};
}

Material withKr(const Double3& kR) {
  Material m;
  m.kR = kR;
  return m;
}
Material withKt(const Double3& kT) {
  Material m;
  m.kT = kT;
  return m;
}

/// Every test looks straight down -z from (0,0,10) at the origin.
const Ray down(Point(0, 0, 10), Vector(0, 0, -1));

/// Ambient (20,20,20) x 0.5 = (10,10,10), background (1,2,3).
LitScene baseScene() {
  LitScene s;
  s.ambientLight = AmbientLight(Color(20, 20, 20), 0.5);
  s.background = Color(1, 2, 3);
  return s;
}

/*
 * The mirror: a square mirror at z = 0 (emission (10,20,30), kR 0.5), a diffuse wall z = 20
 * facing it (emission (100,50,0), kD 0.5), a directional light (100,100,100) along (1,0,1).
 *
 *        wall z = 20  ===========o=========   (0,0,20): lit by the light at |n·l| = 1/√2
 *                                |  ^
 *                         eye (0,0,10)
 *                                v  |
 *        mirror z = 0      ------o------      (0,0,0): r = v − 2(v·n)n = (0,0,1)
 *
 * The wall's shadow ray leaves along (−1,0,−1)/√2 and meets z = 0 at x = −20, beside the mirror.
 *   wall   = (100,50,0) + 100·0.5·(1/√2)            = (100 + 25√2, 50 + 25√2, 25√2)
 *   colour = ambient + mirror emission + 0.5·wall    = (10,10,10) + (10,20,30) + 0.5·wall
 *          = (70 + 12.5√2, 55 + 12.5√2, 40 + 12.5√2)
 */
LitScene mirrorScene() {
  LitScene s = baseScene();
  s.add(square(0), Color(10, 20, 30), withKr(Double3(0.5)));
  Material wall;
  wall.kD = Double3(0.5);
  s.add(Plane(Point(0, 0, 20), Vector(0, 0, -1)), Color(100, 50, 0), wall);
  s.addLight(DirectionalLight(Color(100, 100, 100), Vector(1, 0, 1)));
  return s;
}

TEST(WhittedTracerTests, mirror) {
  const LitScene s = mirrorScene();
  const double h = 12.5 * std::sqrt(2.0);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the reflected wall, weighted by kR
  expectColor(Color(70 + h, 55 + h, 40 + h), WhittedTracer(s).traceRay(down));
  // TC02: the course's fixed offset gives the same colour here
  expectColor(Color(70 + h, 55 + h, 40 + h),
              WhittedTracer(s, nullptr, {}, RayOffset::course()).traceRay(down));
  // TC03: the tracers below see no reflection: ambient + emission
  EXPECT_EQ(Color(20, 30, 40), ShadowTracer(s).traceRay(down));

  // =============== Boundary Values Tests ==================
  // TC11: maxLevel 1: the primary hit casts no secondary ray
  EXPECT_EQ(Color(20, 30, 40), WhittedTracer(s, nullptr, {.maxLevel = 1}).traceRay(down));
  // TC12: maxLevel 2: one bounce, the full colour
  expectColor(Color(70 + h, 55 + h, 40 + h),
              WhittedTracer(s, nullptr, {.maxLevel = 2}).traceRay(down));
}

TEST(WhittedTracerTests, transparentSheet) {
  // ============ Equivalence Partitions Tests ==============
  {
    // TC01: a sheet (emission (5,5,5), kT (0.5,0.25,0.1)) in front of a wall z = -10 of
    // emission (0,100,200): (10,10,10) + (5,5,5) + (0·0.5, 100·0.25, 200·0.1) = (15,40,35)
    LitScene s = baseScene();
    s.add(square(0), Color(5, 5, 5), withKt(Double3(0.5, 0.25, 0.1)));
    s.add(Plane(Point(0, 0, -10), Vector(0, 0, 1)), Color(0, 100, 200));
    expectColor(Color(15, 40, 35), WhittedTracer(s).traceRay(down));
  }
  {
    // TC02: transparent and reflective: kT 0.4 onto a wall z = -10 of (100,0,0), kR 0.3 back up
    // to a wall z = 20 of (0,0,100), refraction first:
    // (10,10,10) + (5,5,5) + 0.4·(100,0,0) + 0.3·(0,0,100) = (55,15,45)
    LitScene s = baseScene();
    Material m;
    m.kT = Double3(0.4);
    m.kR = Double3(0.3);
    s.add(square(0), Color(5, 5, 5), m);
    s.add(Plane(Point(0, 0, -10), Vector(0, 0, 1)), Color(100, 0, 0));
    s.add(Plane(Point(0, 0, 20), Vector(0, 0, -1)), Color(0, 0, 100));
    expectColor(Color(55, 15, 45), WhittedTracer(s).traceRay(down));
  }
  {
    // TC03: two sheets of kT 0.5 (emissions (10,10,10), (20,20,20)) before a wall of (100,...):
    // the weights multiply: 10 + 10 + 0.5·(20 + 0.5·100) = 55 per channel
    LitScene s = baseScene();
    s.add(square(0), Color(10, 10, 10), withKt(Double3(0.5)));
    s.add(square(-5), Color(20, 20, 20), withKt(Double3(0.5)));
    s.add(Plane(Point(0, 0, -10), Vector(0, 0, 1)), Color(100, 100, 100));
    expectColor(Color(55, 55, 55), WhittedTracer(s).traceRay(down));
    // TC04: maxLevel 2 stops at the second sheet (level 1): 10 + 10 + 0.5·20 = 30
    expectColor(Color(30, 30, 30), WhittedTracer(s, nullptr, {.maxLevel = 2}).traceRay(down));
  }
  {
    // TC05: a missed secondary ray sees the background weighted by kx (5785's fix):
    // (10,10,10) + (5,5,5) + (1,2,3)·(0.5,0.5,0.3) = (15.5,16,15.9)
    LitScene s = baseScene();
    s.add(square(0), Color(5, 5, 5), withKt(Double3(0.5, 0.5, 0.3)));
    expectColor(Color(15.5, 16, 15.9), WhittedTracer(s).traceRay(down));
  }

  // =============== Boundary Values Tests ==================
  {
    // TC11: the primary ray misses everything: the background, without ambient
    LitScene s = baseScene();
    s.add(square(0), Color(5, 5, 5), withKt(Double3(0.5)));
    EXPECT_EQ(Color(1, 2, 3), WhittedTracer(s).traceRay(Ray(Point(50, 0, 10), Vector(0, 0, -1))));
  }
  {
    // TC12: a weight exactly at the cut-off is kept (lowerThan is strict): kT 0.001 on a wall of
    // 1000: 15 + 1 = 16; with minK 0.0011 the ray is not cast: 15
    LitScene s = baseScene();
    s.add(square(0), Color(5, 5, 5), withKt(Double3(0.001)));
    s.add(Plane(Point(0, 0, -10), Vector(0, 0, 1)), Color(1000, 1000, 1000));
    expectColor(Color(16, 16, 16), WhittedTracer(s).traceRay(down));
    expectColor(Color(15, 15, 15), WhittedTracer(s, nullptr, {.minK = 0.0011}).traceRay(down));
  }
}

TEST(WhittedTracerTests, indexOfRefraction) {
  // ============ Equivalence Partitions Tests ==============
  {
    // TC01: normal incidence on glass (kT 1, ior 1.5): R = R0 = 0.04, so 0.96 goes through to
    // the wall z = -10 of (100,100,100) and 0.04 is reflected to the wall z = 20 of (0,0,50):
    // (10,10,10) + 0.96·(100,100,100) + 0.04·(0,0,50) = (106,106,108)
    LitScene s = baseScene();
    Material glass;
    glass.kT = Double3(1);
    glass.ior = 1.5;
    s.add(square(0), Color::BLACK, glass);
    s.add(Plane(Point(0, 0, -10), Vector(0, 0, 1)), Color(100, 100, 100));
    s.add(Plane(Point(0, 0, 20), Vector(0, 0, -1)), Color(0, 0, 50));
    expectColor(Color(106, 106, 108), WhittedTracer(s).traceRay(down));
  }
  {
    // TC02: total internal reflection. The sheet's glass is below it (normal +z); a ray from
    // inside meets it at 60 degrees: 1.5·sin60° > 1, so all of kT (0.8) goes to the mirror
    // direction, down to the wall z = -5 of (0,100,0): (10,10,10) + 0.8·(0,100,0) = (10,90,10).
    // With ior 1 (the course) the ray goes straight up to the wall z = 5 of (100,0,0):
    // (10,10,10) + 0.8·(100,0,0) = (90,10,10).
    LitScene s = baseScene();
    Material glass;
    glass.kT = Double3(0.8);
    glass.ior = 1.5;
    const std::uint32_t sheet = s.add(square(0), Color::BLACK, glass);
    s.add(Plane(Point(0, 0, -5), Vector(0, 0, 1)), Color(0, 100, 0));
    s.add(Plane(Point(0, 0, 5), Vector(0, 0, -1)), Color(100, 0, 0));
    const double a = 60 * std::acos(-1.0) / 180;
    const Ray inside(Point(-2 * std::sin(a), 0, -2 * std::cos(a)),
                     Vector(std::sin(a), 0, std::cos(a)));
    expectColor(Color(10, 90, 10), WhittedTracer(s).traceRay(inside));
    s.appearances[sheet].material.ior = 1;
    expectColor(Color(90, 10, 10), WhittedTracer(s).traceRay(inside));
  }
}

/// A tracer whose reflected rays all see (1000,0,0) and refracted rays (0,0,1000): the hook mini
/// project 1 overrides. It counts the calls of each kind and records their order.
class ConstantSecondary : public WhittedTracer {
 public:
  using WhittedTracer::WhittedTracer;
  mutable int reflected = 0, refracted = 0;
  mutable std::vector<SecondaryKind> order;

 protected:
  Color secondaryColor(const HitContext&, const Ray&, SecondaryKind kind, int, const Double3&,
                       SampleContext&) const override {
    order.push_back(kind);
    if (kind == SecondaryKind::Reflected) {
      ++reflected;
      return Color(1000, 0, 0);
    }
    ++refracted;
    return Color(0, 0, 1000);
  }
};

TEST(WhittedTracerTests, secondaryColorHook) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the override replaces what a secondary ray sees, and the tracer still weights it by
  // kx: (10,10,10) + (5,5,5) + 0.5·(0,0,1000) = (15,15,515), one refracted call (kR is 0)
  LitScene s = baseScene();
  s.add(square(0), Color(5, 5, 5), withKt(Double3(0.5)));
  const ConstantSecondary tracer(s);
  expectColor(Color(15, 15, 515), tracer.traceRay(down));
  EXPECT_EQ(1, tracer.refracted);
  EXPECT_EQ(0, tracer.reflected);
  // TC02: a mirror (kR 0.25, kT 0): one reflected call, (15,15,15) + 0.25·(1000,0,0)
  LitScene m = baseScene();
  Material mirror;
  mirror.kR = Double3(0.25);
  m.add(square(0), Color(5, 5, 5), mirror);
  const ConstantSecondary mirrorTracer(m);
  expectColor(Color(265, 15, 15), mirrorTracer.traceRay(down));
  EXPECT_EQ(1, mirrorTracer.reflected);
  EXPECT_EQ(0, mirrorTracer.refracted);
}

TEST(WhittedTracerTests, refractedRayCastBeforeReflected) {
  // The order matters once secondary rays draw random numbers (mini project 1's beams): each
  // takes the next ones from the sample's stream, so it must not depend on the compiler.
  constexpr SecondaryKind T = SecondaryKind::Refracted, R = SecondaryKind::Reflected;
  LitScene s = baseScene();
  Material m;
  m.kT = Double3(0.4);
  m.kR = Double3(0.3);
  const std::uint32_t sheet = s.add(square(0), Color(5, 5, 5), m);
  // ============ Equivalence Partitions Tests ==============
  {
    // TC01: ior 1 (the course's straight-through refraction): refracted, then reflected
    const ConstantSecondary tracer(s);
    tracer.traceRay(down);
    EXPECT_EQ((std::vector<SecondaryKind>{T, R}), tracer.order);
  }
  {
    // TC02: ior 1.5 (Snell and Fresnel): the same order
    s.appearances[sheet].material.ior = 1.5;
    const ConstantSecondary tracer(s);
    tracer.traceRay(down);
    EXPECT_EQ((std::vector<SecondaryKind>{T, R}), tracer.order);
  }
}

TEST(WhittedTracerTests, settingsValidation) {
  LitScene s = baseScene();
  // ============ Equivalence Partitions Tests ==============
  // TC01: the course's defaults
  EXPECT_EQ(10, WhittedTracer(s).settings().maxLevel);
  EXPECT_EQ(0.001, WhittedTracer(s).settings().minK);
  // TC02: a negative or non-finite minK
  try {
    WhittedTracer bad(s, nullptr, {.minK = -1});
    FAIL() << "minK -1 must throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ("WhittedSettings: minK must be a non-negative finite number, got -1", e.what());
  }
  EXPECT_THROW(WhittedTracer(s, nullptr, {.minK = std::numeric_limits<double>::quiet_NaN()}),
               std::invalid_argument);

  // =============== Boundary Values Tests ==================
  // TC11: maxLevel 0 is refused, 1 is the smallest accepted
  try {
    WhittedTracer bad(s, nullptr, {.maxLevel = 0});
    FAIL() << "maxLevel 0 must throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ("WhittedSettings: maxLevel must be between 1 and 1000, got 0", e.what());
  }
  EXPECT_NO_THROW(WhittedTracer(s, nullptr, {.maxLevel = 1}));
  // TC12: the upper limit (one stack frame per level): 1000 accepted, 1001 refused
  EXPECT_NO_THROW(WhittedTracer(s, nullptr, {.maxLevel = 1000}));
  EXPECT_THROW(WhittedTracer(s, nullptr, {.maxLevel = 1001}), std::invalid_argument);
  // TC13: minK 0 (no cut-off) is accepted
  EXPECT_NO_THROW(WhittedTracer(s, nullptr, {.minK = 0}));
}

}  // namespace
}  // namespace rt
