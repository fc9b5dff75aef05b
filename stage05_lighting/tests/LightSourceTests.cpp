// Stage 5: the light sources — intensity, direction l and distance at given points, and their
// validation. Every expected value is worked out by hand in the comment beside it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "TestSupport.h"
#include "lighting/LightSource.h"
#include "lighting/LitScene.h"

namespace rt {
namespace {

using test::colorNear;
using test::EPS;
using test::invalidArgumentMessage;
using test::tripleNear;
using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr double INF = std::numeric_limits<double>::infinity();

TEST(DirectionalLightTests, illuminate) {
  const LightSource light = DirectionalLight(Color(100, 200, 300), Vector(0, 0, -2));
  // ============ Equivalence Partitions Tests ==============
  // TC01: at an ordinary point: I0 unchanged, l = the normalised direction, distance +inf
  auto s = illuminate(light, Point(1, 2, 3));
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100, 200, 300));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(0, 0, -1)));
  EXPECT_EQ(s->distance, INF);
  // TC02: at a far away point: the same (no attenuation, no direction change)
  s = illuminate(light, Point(-1e6, 5e5, 3e6));
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100, 200, 300));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(0, 0, -1)));
  EXPECT_EQ(s->distance, INF);

  // =============== Boundary Values Tests ==================
  // TC11: at the origin (no position to coincide with): still I0
  s = illuminate(light, Point::ZERO);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100, 200, 300));
  // TC12: the constructor normalises a non-unit direction: (1,1,-0.5) has length 1.5
  const DirectionalLight d(Color::WHITE, Vector(1, 1, -0.5));
  EXPECT_TRUE(tripleNear(d.direction.xyz(), Double3(2.0 / 3, 2.0 / 3, -1.0 / 3)));
}

TEST(PointLightTests, illuminate) {
  // Position (1,2,3); the test point (4,6,3) is at offset (3,4,0): d = 5, l = (0.6,0.8,0).
  const Point pos(1, 2, 3);
  const Point p(4, 6, 3);
  // ============ Equivalence Partitions Tests ==============
  // TC01: all three factors: kC + kL·d + kQ·d² = 1 + 0.1·5 + 0.02·25 = 2 -> I0 / 2
  LightSource light = PointLight(Color(100, 200, 300), pos).setKc(1).setKl(0.1).setKq(0.02);
  auto s = illuminate(light, p);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 50, 100, 150));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(0.6, 0.8, 0)));
  EXPECT_NEAR(s->distance, 5, EPS);
  // TC02: the course's defaults (kC 1, kL 0, kQ 0): no attenuation at any distance
  light = PointLight(Color(100, 200, 300), pos);
  s = illuminate(light, Point(1, 2, -997));  // d = 1000
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100, 200, 300));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(0, 0, -1)));
  EXPECT_NEAR(s->distance, 1000, EPS);
  // TC03: linear only: 1 + 0.2·5 = 2
  light = PointLight(Color(100, 200, 300), pos).setKl(0.2);
  s = illuminate(light, p);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 50, 100, 150));
  // TC04: quadratic only: 1 + 0.12·25 = 4
  light = PointLight(Color(100, 200, 300), pos).setKq(0.12);
  s = illuminate(light, p);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 25, 50, 75));
  // TC05: constant only: kC = 4 -> I0 / 4 at any distance
  light = PointLight(Color(100, 200, 300), pos).setKc(4);
  s = illuminate(light, p);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 25, 50, 75));
  // TC06: the LightsTests sphere light (kL 0.001, kQ 0.0002) at the sphere's front point
  // (0,0,0), 75 away from (-50,-50,25): 1 + 0.075 + 1.125 = 2.2; l = (50,50,-25)/75
  light = PointLight(Color(800, 500, 0), Point(-50, -50, 25)).setKl(0.001).setKq(0.0002);
  s = illuminate(light, Point::ZERO);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 800 / 2.2, 500 / 2.2, 0));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(2.0 / 3, 2.0 / 3, -1.0 / 3)));
  EXPECT_NEAR(s->distance, 75, EPS);

  // =============== Boundary Values Tests ==================
  // TC11: at the light's own position l is undefined: no sample (never a throw)
  light = PointLight(Color(100, 200, 300), pos).setKl(0.1).setKq(0.02);
  EXPECT_FALSE(illuminate(light, pos).has_value());
  // TC12: a hair away from the light (d = 1e-9): intensity tends to I0 / kC
  s = illuminate(light, Point(1, 2, 3 + 1e-9));
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100, 200, 300, 1e-6));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(0, 0, 1)));
  EXPECT_NEAR(s->distance, 1e-9, 1e-15);  // 3 + 1e-9 is rounded to 4.4e-16
}

TEST(SpotLightTests, illuminate) {
  // A spot at the origin aimed along -Z, I0 = (100,200,300), no attenuation unless stated.
  // Test points at distance 2: on the axis (0,0,-2); at 60° from it (sqrt(3),0,-1), where
  // direction·l = cos 60° = 0.5; at 90° (2,0,0); and behind the light (0,0,2).
  const Color i0(100, 200, 300);
  const Point axis(0, 0, -2), at60(std::sqrt(3.0), 0, -1), at90(2, 0, 0), behind(0, 0, 2);
  // ============ Equivalence Partitions Tests ==============
  // TC01: along the axis: factor max(0,1)^1 = 1 -> I0
  LightSource light = SpotLight(i0, Point::ZERO, Vector(0, 0, -1));
  auto s = illuminate(light, axis);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100, 200, 300));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(0, 0, -1)));
  EXPECT_NEAR(s->distance, 2, EPS);
  // TC02: at 60°, default narrowBeam 1: factor 0.5
  s = illuminate(light, at60);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 50, 100, 150));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(std::sqrt(3.0) / 2, 0, -0.5)));
  EXPECT_NEAR(s->distance, 2, EPS);
  // TC03: at 60° with narrowBeam 3: factor 0.5^3 = 0.125
  light = SpotLight(i0, Point::ZERO, Vector(0, 0, -1)).setNarrowBeam(3);
  s = illuminate(light, at60);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 12.5, 25, 37.5));
  // TC04: at 60° with narrowBeam 10 (the course's sharp spot): 0.5^10 = 1/1024
  light = SpotLight(i0, Point::ZERO, Vector(0, 0, -1)).setNarrowBeam(10);
  s = illuminate(light, at60);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100.0 / 1024, 200.0 / 1024, 300.0 / 1024));
  // TC05: attenuation and the spot factor multiply: kL 0.1 at d = 2 -> 1.2; at 60° -> 0.5/1.2
  light = SpotLight(i0, Point::ZERO, Vector(0, 0, -1)).setKl(0.1);
  s = illuminate(light, at60);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100 * 0.5 / 1.2, 200 * 0.5 / 1.2, 300 * 0.5 / 1.2));
  // TC06: a non-unit direction is normalised: (0,0,-7) behaves as (0,0,-1)
  light = SpotLight(i0, Point::ZERO, Vector(0, 0, -7));
  s = illuminate(light, at60);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 50, 100, 150));

  // =============== Boundary Values Tests ==================
  // TC11: at 90° (direction·l = 0): factor 0 -> black
  light = SpotLight(i0, Point::ZERO, Vector(0, 0, -1));
  s = illuminate(light, at90);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 0, 0, 0));
  EXPECT_TRUE(tripleNear(s->l.xyz(), Double3(1, 0, 0)));
  // TC12: behind the light (direction·l = -1), narrowBeam 1: max(0,-1) = 0 -> black
  s = illuminate(light, behind);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 0, 0, 0));
  EXPECT_NEAR(s->distance, 2, EPS);
  // TC13: behind the light with an even narrowBeam 2: still black. Without the max(0,·) before
  // the power, (-1)^2 = 1 would light the back of the spot at full strength.
  light = SpotLight(i0, Point::ZERO, Vector(0, 0, -1)).setNarrowBeam(2);
  s = illuminate(light, behind);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 0, 0, 0));
  // TC14: at the spot's own position: no sample
  EXPECT_FALSE(illuminate(light, Point::ZERO).has_value());
  // TC15: narrowBeam 0: factor x^0 = 1, like a point light (also at 90°, where 0^0 = 1)
  light = SpotLight(i0, Point::ZERO, Vector(0, 0, -1)).setNarrowBeam(0);
  s = illuminate(light, at60);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100, 200, 300));
  s = illuminate(light, at90);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(colorNear(s->intensity, 100, 200, 300));
}

TEST(SpotLightTests, settersKeepTheSpotLight) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: every setter of a spot light returns the spot light itself (a SpotLight&, so a chain
  // can end with setNarrowBeam), and sets its field
  SpotLight spot(Color::WHITE, Point::ZERO, Vector(0, 0, -2));
  static_assert(std::is_same_v<SpotLight&, decltype(spot.setKc(2))>);
  static_assert(std::is_same_v<SpotLight&, decltype(spot.setKl(0.5))>);
  static_assert(std::is_same_v<SpotLight&, decltype(spot.setKq(0.25))>);
  static_assert(std::is_same_v<SpotLight&, decltype(spot.setRadius(3))>);
  static_assert(std::is_same_v<SpotLight&, decltype(spot.setShadowSamples(9))>);
  SpotLight& chained =
      spot.setKc(2).setKl(0.5).setKq(0.25).setRadius(3).setShadowSamples(9).setNarrowBeam(4);
  EXPECT_EQ(&spot, &chained);
  EXPECT_EQ(2.0, spot.kC);
  EXPECT_EQ(0.5, spot.kL);
  EXPECT_EQ(0.25, spot.kQ);
  EXPECT_EQ(3.0, spot.radius);
  EXPECT_EQ(9, spot.shadowSamples);
  EXPECT_EQ(4.0, spot.narrowBeam);
  EXPECT_EQ(-1.0, spot.direction.z());
  // TC02: a point light's setters return the point light, and a spot light is a point light
  PointLight point(Color::WHITE, Point::ZERO);
  static_assert(std::is_same_v<PointLight&, decltype(point.setKc(2))>);
  EXPECT_EQ(&point, &point.setKl(0.5).setKq(0.25));
  EXPECT_EQ(0.5, point.kL);
  const PointLight& asPoint = spot;
  EXPECT_EQ(0.25, asPoint.kQ);
}

TEST(LightSourceTests, sizeForSoftShadows) {
  // The radius and shadowSamples of point and spot lights are data for mini project 1's soft
  // shadows; validate checks them with the light.
  // ============ Equivalence Partitions Tests ==============
  // TC01: the defaults are the course's point light: radius 0, one sample
  const PointLight point(Color::WHITE, Point::ZERO);
  EXPECT_EQ(0.0, point.radius);
  EXPECT_EQ(1, point.shadowSamples);
  // TC02: a spot light of radius 2 with 64 samples is accepted, and illuminates as before
  const SpotLight sized = SpotLight(Color(100, 100, 100), Point::ZERO, Vector(0, 0, -1))
                              .setRadius(2)
                              .setShadowSamples(64);
  EXPECT_NO_THROW(validate(sized));
  EXPECT_NEAR(100, illuminate(sized, Point(0, 0, -1))->intensity.r(), 1e-12);
  // =============== Boundary Values Tests ==================
  // TC11: a negative radius, naming the light, the field and the value
  EXPECT_STREQ("PointLight: radius must be a non-negative finite number, got -1",
               invalidArgumentMessage([] {
                 validate(PointLight(Color::WHITE, Point::ZERO).setRadius(-1));
               }).c_str());
  // TC12: 0 samples and one more than the largest
  EXPECT_STREQ(
      "SpotLight: shadowSamples must be between 1 and 4096, got 0",
      invalidArgumentMessage([] {
        validate(SpotLight(Color::WHITE, Point::ZERO, Vector(0, 0, -1)).setShadowSamples(0));
      }).c_str());
  EXPECT_THROW(validate(PointLight(Color::WHITE, Point::ZERO).setShadowSamples(4097)),
               std::invalid_argument);
  EXPECT_NO_THROW(validate(PointLight(Color::WHITE, Point::ZERO).setShadowSamples(4096)));
}

TEST(LightSourceTests, validate) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the course's lights as used in LightsTests are accepted
  EXPECT_NO_THROW(validate(DirectionalLight(Color(800, 500, 0), Vector(1, 1, -0.5))));
  EXPECT_NO_THROW(
      validate(PointLight(Color(800, 500, 0), Point(-50, -50, 25)).setKl(0.001).setKq(0.0002)));
  EXPECT_NO_THROW(validate(SpotLight(Color(800, 500, 0), Point(-50, -50, 25), Vector(1, 1, -0.5))
                               .setKl(0.001)
                               .setKq(0.00004)
                               .setNarrowBeam(10)));
  // TC02: a negative kL is rejected, naming the light, the field and the value
  EXPECT_THAT(
      invalidArgumentMessage([] { validate(PointLight(Color::WHITE, Point::ZERO).setKl(-1)); }),
      AllOf(HasSubstr("PointLight"), HasSubstr("kL"), HasSubstr("-1")));
  // TC03: a negative kQ on a spot light names the spot light
  EXPECT_THAT(invalidArgumentMessage([] {
                validate(SpotLight(Color::WHITE, Point::ZERO, Vector(0, 0, -1)).setKq(-0.5));
              }),
              AllOf(HasSubstr("SpotLight"), HasSubstr("kQ"), HasSubstr("-0.5")));
  // TC04: a negative narrowBeam is rejected
  EXPECT_THAT(invalidArgumentMessage([] {
                validate(SpotLight(Color::WHITE, Point::ZERO, Vector(0, 0, -1)).setNarrowBeam(-2));
              }),
              AllOf(HasSubstr("narrowBeam"), HasSubstr("-2")));
  // TC05: a negative kC is rejected
  EXPECT_THAT(
      invalidArgumentMessage([] { validate(PointLight(Color::WHITE, Point::ZERO).setKc(-1)); }),
      AllOf(HasSubstr("kC"), HasSubstr("-1")));

  // =============== Boundary Values Tests ==================
  // TC11: kC = 0 makes the attenuation zero at distance 0 (infinite intensity): rejected
  EXPECT_THAT(
      invalidArgumentMessage([] { validate(PointLight(Color::WHITE, Point::ZERO).setKc(0)); }),
      AllOf(HasSubstr("kC"), HasSubstr("0")));
  // TC12: kL = kQ = 0 and narrowBeam = 0 are accepted
  EXPECT_NO_THROW(validate(
      SpotLight(Color::WHITE, Point::ZERO, Vector(0, 0, -1)).setKl(0).setKq(0).setNarrowBeam(0)));
  // TC13: non-finite factors are rejected
  EXPECT_THAT(
      invalidArgumentMessage([] {
        validate(
            PointLight(Color::WHITE, Point::ZERO).setKq(std::numeric_limits<double>::infinity()));
      }),
      AllOf(HasSubstr("kQ"), HasSubstr("inf")));
  EXPECT_THAT(
      invalidArgumentMessage([] {
        validate(
            SpotLight(Color::WHITE, Point::ZERO, Vector(0, 0, -1)).setNarrowBeam(std::nan("")));
      }),
      HasSubstr("narrowBeam"));
  // TC14: a non-finite position is rejected
  EXPECT_THAT(
      invalidArgumentMessage([] {
        validate(PointLight(Color::WHITE, Point(std::numeric_limits<double>::infinity(), 0, 0)));
      }),
      HasSubstr("position"));
  // TC15: LitScene::addLight validates: a bad light is not added
  LitScene scene;
  EXPECT_THROW(scene.addLight(PointLight(Color::WHITE, Point::ZERO).setKc(0)),
               std::invalid_argument);
  EXPECT_TRUE(scene.lights.empty());
}

}  // namespace
}  // namespace rt
