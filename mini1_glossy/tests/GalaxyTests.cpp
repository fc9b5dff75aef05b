// Mini project 1: the reference report's galaxy in a glass box, generated from its parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <variant>

#include "camera/Camera.h"
#include "glossy/Galaxy.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;

int countSpheres(const LitScene& s) {
  int n = 0;
  for (const Geometry& g : s.geometries.shapes()) n += std::holds_alternative<Sphere>(g) ? 1 : 0;
  return n;
}

TEST(GalaxyTests, theSeedsLayout) {
  const GalaxySetup g = galaxy();
  const LitScene& s = g.scene;
  // ============ Equivalence Partitions Tests ==============
  // TC01: 1 floor + 12 pedestal faces + 6 glass faces + 8 bars x 6 faces = 67 other shapes;
  // 18 arms x 50 stars = 900, the core and its halo, and 138 suns: the positions of the 3 sun
  // arms (150) whose first draw after the star's three is below 0.9. The draws come from
  // RandomStream (SplitMix64, specified to the bit), so the count is the same everywhere.
  const int spheres = countSpheres(s);
  EXPECT_EQ(67, static_cast<int>(s.geometries.size()) - spheres);
  EXPECT_EQ(902 + 138, spheres);
  // TC02: three spot lights, no ambient light, black background
  EXPECT_EQ(3u, s.lights.size());
  for (const LightSource& l : s.lights) EXPECT_TRUE(std::holds_alternative<SpotLight>(l));
  EXPECT_EQ(Color::BLACK, s.ambientLight.intensity());
  EXPECT_NO_THROW(s.validate());
  // TC03: the reference report's camera, and the views (main is the reference report's)
  EXPECT_EQ(Point(100, 27, 22), g.camera.location);
  EXPECT_EQ(1280, g.camera.nX);
  EXPECT_EQ(720, g.camera.nY);
  EXPECT_EQ(384, g.camera.vpWidth);
  EXPECT_EQ(216, g.camera.vpHeight);
  EXPECT_EQ(750, g.camera.vpDistance);
  std::set<std::string> names;
  for (const NamedView& v : g.views) {
    names.insert(v.name);
    EXPECT_NO_THROW((void)v.camera.builder().build()) << v.name;
  }
  EXPECT_EQ((std::set<std::string>{"main", "above", "inside", "side"}), names);
  // TC04: the glass blurs both secondary rays with the reference report's beam (N 10, distance 12,
  // radius 0.2): exactly one row of the table has beams
  int blurred = 0;
  for (const Appearance& a : s.appearances)
    if (a.material.reflectedBeam.isBeam() || a.material.refractedBeam.isBeam()) {
      ++blurred;
      EXPECT_EQ((BeamSettings{12, 0.2, 10}), a.material.reflectedBeam);
      EXPECT_EQ((BeamSettings{12, 0.2, 10}), a.material.refractedBeam);
      EXPECT_EQ(Double3(0.85), a.material.kT);
    }
  EXPECT_EQ(1, blurred);
}

TEST(GalaxyTests, everyStarIsWithinTheSpiralsReach) {
  // TC01: every sphere is within the outermost arm's radius of the galaxy's centre (4,8,4):
  // 1.7·e^(0.25·0.15·49) plus the largest jitter in the disc (0.2·⌊49/8⌋/2 = 0.6 in x and in z)
  // and off it (0.1), plus its own radius; and above the pedestal (y > 4). (As in the Java course
  // project, the outermost stars of the arms pointing to −x reach a little past the glass wall at x
  // = −6.5: the box is not centred on the galaxy in x.)
  const LitScene s = galaxy().scene;
  const double reach = 1.7 * std::exp(0.25 * 0.15 * 49) + std::sqrt(2 * 0.6 * 0.6) + 0.1;
  int count = 0;
  for (const Geometry& g : s.geometries.shapes()) {
    const Sphere* sphere = std::get_if<Sphere>(&g);
    if (!sphere) continue;
    ++count;
    const Point& c = sphere->center();
    EXPECT_LE(std::sqrt(c.distanceSquared(Point(4, 8, 4))), reach + sphere->radius());
    EXPECT_GT(c.y() - sphere->radius(), 4);
  }
  EXPECT_GT(count, 1000);
}

TEST(GalaxyTests, boxesFaceOutwards) {
  // TC01: every polygon's normal points away from the centre of the box it belongs to: checked
  // through the box of the glass (faces 13..18): their normals point away from (6, 9.5, 4)
  const LitScene s = galaxy().scene;
  for (std::uint32_t i = 13; i < 19; ++i) {
    const Polygon& face = std::get<Polygon>(s.geometries[i]);
    const Double3 toFace = face.vertices()[0].xyz() - Double3(6, 9.5, 4);
    EXPECT_GT(face.plane().normal().xyz().dot(toFace), 0) << i;
  }
}

TEST(GalaxyTests, parameters) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the same parameters give the same scene, sphere for sphere; another seed moves them
  const LitScene a = galaxy().scene, b = galaxy().scene;
  GalaxyParams other;
  other.seed = 2;
  const LitScene c = galaxy(other).scene;
  ASSERT_EQ(a.geometries.size(), b.geometries.size());
  for (std::uint32_t k = 0; k < a.geometries.size(); ++k) {
    const auto* sa = std::get_if<Sphere>(&a.geometries[k]);
    const auto* sb = std::get_if<Sphere>(&b.geometries[k]);
    ASSERT_EQ(sa == nullptr, sb == nullptr) << k;
    if (sa == nullptr) continue;
    EXPECT_TRUE(sameBits(sa->center(), sb->center())) << k;
    EXPECT_TRUE(sameBits(sa->radius(), sb->radius())) << k;
  }
  EXPECT_NE(std::get<Sphere>(a.geometries[80]).center().x(),
            std::get<Sphere>(c.geometries[80]).center().x());
  // TC02: arms and positions: 7 arms of 10 (arm 4 holds suns): 6 x 10 stars, the core and its
  // halo, and 9 suns on arm 4's 10 positions
  GalaxyParams small;
  small.arms = 7;
  small.perArm = 10;
  EXPECT_EQ(60 + 2 + 9, countSpheres(galaxy(small).scene));
  // TC03: stars scales the galaxy: 10^4 stars on 21 arms: 476 positions per arm
  GalaxyParams many;
  many.stars = 10000;
  EXPECT_EQ(476, many.positionsPerArm());
  // 18 arms of stars, the core and its halo, and 1263 suns on the 3 sun arms' 1428 positions
  EXPECT_EQ(18 * 476 + 2 + 1263, countSpheres(galaxy(many).scene));
  // TC04: no diffusion: no blur anywhere
  GalaxyParams clear;
  clear.diffusion = false;
  for (const Appearance& look : galaxy(clear).scene.appearances) {
    EXPECT_FALSE(look.material.reflectedBeam.isBeam());
    EXPECT_FALSE(look.material.refractedBeam.isBeam());
  }
  // =============== Boundary Values Tests ==================
  // TC11: one arm of one position: one sphere, the core and the halo
  GalaxyParams one;
  one.arms = 1;
  one.perArm = 1;
  EXPECT_EQ(3, countSpheres(galaxy(one).scene));
  // TC12: out of range, naming the parameter
  GalaxyParams bad;
  bad.arms = 0;
  try {
    (void)galaxy(bad);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ("galaxy: arms must be between 1 and 1000, got 0", e.what());
  }
  bad = {};
  bad.stars = GalaxyParams::MAX_STARS + 1;
  EXPECT_THROW((void)galaxy(bad), std::invalid_argument);
  // TC13: arms x perArm beyond MAX_STARS (each within its own range), refused before anything
  // is made; stars, when given, sets perArm instead
  bad = {};
  bad.arms = 1000;
  bad.perArm = 1'000'000;
  try {
    (void)galaxy(bad);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(
        "galaxy: arms x perArm must be at most 10000000 stars, got 1000 x 1000000 = 1000000000",
        e.what());
  }
  GalaxyParams atMost;
  atMost.arms = 1000;
  atMost.perArm = 10'000;
  EXPECT_NO_THROW(atMost.validate());
  atMost.perArm = 10'001;
  EXPECT_THROW(atMost.validate(), std::invalid_argument);
  atMost.stars = 5000;
  EXPECT_NO_THROW(atMost.validate());
}

}  // namespace
}  // namespace rt
