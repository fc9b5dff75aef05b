// Tests of the secondary-ray directions and the Fresnel weight: reflection, Snell's law, total
// internal reflection and Schlick's approximation.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "primitives/Vector.h"
#include "reflections/Optics.h"

namespace rt {
namespace {

constexpr double EPS = 1e-12;
const double DEG = std::numbers::pi / 180;

void expectVector(const Vector& expected, const Vector& actual) {
  EXPECT_NEAR(expected.x(), actual.x(), EPS);
  EXPECT_NEAR(expected.y(), actual.y(), EPS);
  EXPECT_NEAR(expected.z(), actual.z(), EPS);
}

/// The unit direction at `angle` (radians) from the normal (0,0,1): going down into the surface
/// (entering) or up out of it (leaving), in the x-z plane.
Vector down(double angle) { return Vector(std::sin(angle), 0, -std::cos(angle)); }
Vector up(double angle) { return Vector(std::sin(angle), 0, std::cos(angle)); }

const Vector N(0, 0, 1);

TEST(OpticsTests, reflect) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: 45 degrees: r = v − 2(v·n)n mirrors the z component
  expectVector(up(45 * DEG), reflect(down(45 * DEG), N));
  // TC02: from the inside of the surface (v·n > 0): the same formula
  expectVector(down(30 * DEG), reflect(up(30 * DEG), N));

  // =============== Boundary Values Tests ==================
  // TC11: normal incidence: straight back
  expectVector(Vector(0, 0, 1), reflect(Vector(0, 0, -1), N));
  // TC12: grazing (v·n = 0): v itself
  expectVector(Vector(1, 0, 0), reflect(Vector(1, 0, 0), N));
}

TEST(OpticsTests, refractSnell) {
  // ============ Equivalence Partitions Tests ==============
  {
    // TC01: entering glass (ior 1.5) at 45 degrees: sinθt = sin45°/1.5 = 0.4714045207910317
    const Refraction r = refract(down(45 * DEG), N, 1.5);
    ASSERT_TRUE(r.direction.has_value());
    EXPECT_TRUE(r.entering);
    const double sinT = std::sin(45 * DEG) / 1.5;
    EXPECT_NEAR(0.4714045207910317, sinT, 1e-15);
    expectVector(Vector(sinT, 0, -std::sqrt(1 - sinT * sinT)), *r.direction);
    // Schlick on the entering side: cosθ = cos45°, R0 = 0.04
    EXPECT_NEAR(0.04 + 0.96 * std::pow(1 - std::cos(45 * DEG), 5), r.reflectance, EPS);
  }
  {
    // TC02: leaving glass at 30 degrees: sinθt = 1.5·sin30° = 0.75, bent away from the normal
    const Refraction r = refract(up(30 * DEG), N, 1.5);
    ASSERT_TRUE(r.direction.has_value());
    EXPECT_FALSE(r.entering);
    expectVector(Vector(0.75, 0, std::sqrt(1 - 0.75 * 0.75)), *r.direction);
    // Schlick uses the cosine on the air side (θt): cosθt = √(1 − 0.5625)
    EXPECT_NEAR(0.04 + 0.96 * std::pow(1 - std::sqrt(1 - 0.5625), 5), r.reflectance, EPS);
  }
  {
    // TC03: total internal reflection: leaving glass at 60 degrees, 1.5·sin60° = 1.299 > 1
    const Refraction r = refract(up(60 * DEG), N, 1.5);
    EXPECT_FALSE(r.direction.has_value());
    EXPECT_FALSE(r.entering);
    EXPECT_EQ(1.0, r.reflectance);
  }
  {
    // TC04: a material less dense than the outside (ior 0.5) entered at 45 degrees:
    // sinθt = sin45°/0.5 = 1.414 > 1: total internal reflection on the way in
    EXPECT_FALSE(refract(down(45 * DEG), N, 0.5).direction.has_value());
  }

  // =============== Boundary Values Tests ==================
  {
    // TC11: normal incidence: straight through, R = R0 = ((1 − 1.5)/(1 + 1.5))² = 0.04
    const Refraction r = refract(Vector(0, 0, -1), N, 1.5);
    expectVector(Vector(0, 0, -1), *r.direction);
    EXPECT_NEAR(0.04, r.reflectance, 1e-15);
  }
  {
    // TC12: just below and just above the critical angle asin(1/1.5) = 41.81 degrees
    const double critical = std::asin(1 / 1.5);
    const Refraction below = refract(up(critical - 1e-6), N, 1.5);
    ASSERT_TRUE(below.direction.has_value());
    EXPECT_GT(below.direction->x(), 0.999);  // nearly grazing the surface
    EXPECT_FALSE(refract(up(critical + 1e-6), N, 1.5).direction.has_value());
  }
  {
    // TC13: ior 1: Snell's direction is v itself (the course's straight-through direction)
    const Refraction r = refract(down(45 * DEG), N, 1.0);
    expectVector(down(45 * DEG), *r.direction);
    expectVector(down(45 * DEG), refractStraight(down(45 * DEG)));
  }
}

TEST(OpticsTests, schlick) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: R0 + (1 − R0)(1 − cosθ)^5 at 60 degrees: 0.04 + 0.96·0.5^5 = 0.07
  EXPECT_NEAR(0.07, schlick(0.5, 1, 1.5), 1e-15);
  // TC02: symmetric in the two indices
  EXPECT_EQ(schlick(0.3, 1, 1.5), schlick(0.3, 1.5, 1));
  // TC03: a ray and its reverse have the same reflectance (θi entering, θt leaving)
  const Refraction in = refract(down(50 * DEG), N, 1.5);
  const Vector back = -*in.direction;  // the transmitted ray reversed, leaving the glass
  EXPECT_NEAR(in.reflectance, refract(back, N, 1.5).reflectance, EPS);

  // =============== Boundary Values Tests ==================
  // TC11: normal incidence: R = R0 = ((1 − n)/(1 + n))²
  EXPECT_NEAR(0.04, schlick(1, 1, 1.5), 1e-15);
  EXPECT_NEAR(std::pow((1 - 2.4) / (1 + 2.4), 2), schlick(1, 1, 2.4), 1e-15);
  // TC12: grazing incidence: R = 1
  EXPECT_EQ(1.0, schlick(0, 1, 1.5));
  // TC13: equal indices at normal incidence: R0 = 0, nothing reflected
  EXPECT_EQ(0.0, schlick(1, 1.5, 1.5));
}

}  // namespace
}  // namespace rt
