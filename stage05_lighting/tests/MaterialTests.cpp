// Stage 5: Material's validation and LitScene's bookkeeping of appearances.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "TestSupport.h"
#include "geometries/Geometry.h"
#include "geometries/Sphere.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"

namespace rt {
namespace {

using test::invalidArgumentMessage;
using ::testing::AllOf;
using ::testing::HasSubstr;

TEST(MaterialTests, defaults) {
  // TC01: a default material is all zero, shininess 0 and ior 1 (the course's defaults)
  const Material m;
  EXPECT_EQ(m.kD, Double3::ZERO);
  EXPECT_EQ(m.kS, Double3::ZERO);
  EXPECT_EQ(m.kT, Double3::ZERO);
  EXPECT_EQ(m.kR, Double3::ZERO);
  EXPECT_EQ(m.shininess, 0);
  EXPECT_EQ(m.ior, 1.0);
  EXPECT_NO_THROW(m.validate());
}

TEST(MaterialTests, validate) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: ordinary coefficients (the LightsTests triangle material) are accepted
  Material ok;
  ok.kD = Double3(0.2, 0.6, 0.4);
  ok.kS = Double3(0.2, 0.4, 0.3);
  ok.kT = Double3(0.3);
  ok.kR = Double3(0.5, 0, 0.4);
  ok.shininess = 301;
  ok.ior = 1.5;
  EXPECT_NO_THROW(ok.validate());

  // TC02: a negative kD component is rejected, naming the field and its value
  Material m;
  m.kD = Double3(-0.5, 0, 0);
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }),
              AllOf(HasSubstr("kD"), HasSubstr("(-0.5,0,0)")));
  // TC03: a negative kS, kT or kR component is rejected, each naming its own field
  m = Material{};
  m.kS = Double3(0, -1, 0);
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }),
              AllOf(HasSubstr("kS"), HasSubstr("(0,-1,0)")));
  m = Material{};
  m.kT = Double3(0, 0, -0.25);
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }),
              AllOf(HasSubstr("kT"), HasSubstr("-0.25")));
  m = Material{};
  m.kR = Double3(-2);
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }), HasSubstr("kR"));
  // TC04: a negative shininess is rejected with its value
  m = Material{};
  m.shininess = -3;
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }),
              AllOf(HasSubstr("shininess"), HasSubstr("-3")));
  // TC05: a negative ior is rejected with its value
  m = Material{};
  m.ior = -1.5;
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }),
              AllOf(HasSubstr("ior"), HasSubstr("-1.5")));

  // =============== Boundary Values Tests ==================
  // TC11: zero coefficients and shininess 0 are accepted (they are the defaults)
  EXPECT_NO_THROW(Material{}.validate());
  // TC12: ior exactly 0 is rejected
  m = Material{};
  m.ior = 0;
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }), HasSubstr("ior"));
  // TC13: a non-finite coefficient (infinity, NaN) is rejected
  m = Material{};
  m.kT = Double3(std::numeric_limits<double>::infinity(), 0, 0);
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }),
              AllOf(HasSubstr("kT"), HasSubstr("inf")));
  m = Material{};
  m.kD = Double3(0, std::nan(""), 0);
  EXPECT_THAT(invalidArgumentMessage([&] { m.validate(); }), HasSubstr("kD"));
  // TC14: coefficients above 1 are accepted (the course does not bound them; energy is the
  // scene author's business)
  m = Material{};
  m.kS = Double3(2);
  EXPECT_NO_THROW(m.validate());
}

TEST(MaterialTests, beams) {
  // The beams are data for mini project 1's glossy surfaces and diffused glass; validate checks
  // them with the material.
  Material m;
  // ============ Equivalence Partitions Tests ==============
  // TC01: no beam by default; the galaxy's glass (distance 12, radius 0.2, grid 10) is valid
  EXPECT_FALSE(m.reflectedBeam.isBeam());
  EXPECT_FALSE(m.refractedBeam.isBeam());
  m.refractedBeam = {12, 0.2, 10};
  EXPECT_TRUE(m.refractedBeam.isBeam());
  EXPECT_NO_THROW(m.validate());
  // =============== Boundary Values Tests ==================
  // TC11: a grid of 1 or a radius of 0 is no beam (the course's single ray), and is valid
  EXPECT_FALSE((BeamSettings{12, 0.2, 1}.isBeam()));
  EXPECT_FALSE((BeamSettings{12, 0, 10}.isBeam()));
  // TC12: distance 0, a negative radius, grid 0 and MAX_GRID + 1: refused, naming the beam and
  // the field
  m.refractedBeam = {0, 0.2, 10};
  EXPECT_STREQ("Material: refractedBeam: distance must be a positive finite number, got 0",
               invalidArgumentMessage([&] { m.validate(); }).c_str());
  m.refractedBeam = {1, 0.2, 10};
  m.reflectedBeam = {1, -0.5, 10};
  EXPECT_STREQ("Material: reflectedBeam: radius must be a non-negative finite number, got -0.5",
               invalidArgumentMessage([&] { m.validate(); }).c_str());
  m.reflectedBeam = {1, 0.2, 0};
  EXPECT_THROW(m.validate(), std::invalid_argument);
  m.reflectedBeam = {1, 0.2, BeamSettings::MAX_GRID + 1};
  EXPECT_THROW(m.validate(), std::invalid_argument);
  m.reflectedBeam = {1, 0.2, BeamSettings::MAX_GRID};
  EXPECT_NO_THROW(m.validate());
}

TEST(LitSceneTests, addKeepsAppearancesAligned) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: add() appends the shape and its appearance at the same index
  LitScene scene;
  Material m;
  m.kD = Double3(0.5);
  EXPECT_EQ(scene.add(Sphere(Point(0, 0, -5), 1)), 0u);
  EXPECT_EQ(scene.add(Sphere(Point(0, 0, -9), 1), Color(1, 2, 3), m), 1u);
  ASSERT_EQ(scene.appearances.size(), 2u);
  ASSERT_EQ(scene.geometries.size(), 2u);
  EXPECT_EQ(scene.appearances[0].emission, Color::BLACK);
  EXPECT_EQ(scene.appearances[0].material.kD, Double3::ZERO);
  EXPECT_EQ(scene.appearances[1].emission, Color(1, 2, 3));
  EXPECT_EQ(scene.appearances[1].material.kD, Double3(0.5));
  // TC02: an invalid material is rejected before anything is added
  Material bad;
  bad.kS = Double3(-1);
  EXPECT_THROW(scene.add(Sphere(Point(0, 0, -5), 1), Color::BLACK, bad), std::invalid_argument);
  EXPECT_EQ(scene.appearances.size(), 2u);
  EXPECT_EQ(scene.geometries.size(), 2u);

  // =============== Boundary Values Tests ==================
  // TC11: a stage-4 scene becomes a lit one whose shapes share one default appearance
  Scene plain;
  plain.geometries.add(Sphere(Point(0, 0, -5), 1));
  plain.geometries.add(Sphere(Point(0, 0, -9), 2));
  const LitScene lit(plain);
  EXPECT_EQ(lit.appearances.size(), 1u);
  EXPECT_EQ(lit.appearanceIndex, (std::vector<std::uint32_t>{0, 0}));
  EXPECT_EQ(lit.geometries.size(), 2u);
  EXPECT_TRUE(lit.lights.empty());
  EXPECT_NO_THROW(lit.validate());
}

TEST(LitSceneTests, sharedAppearances) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: many shapes of one look share one row: 1000 spheres, 2 rows
  LitScene scene;
  Material m;
  m.kD = Double3(0.2);
  const std::uint32_t blue = scene.addAppearance(Color(80, 255, 230), m);
  const std::uint32_t white = scene.addAppearance(Color(200, 250, 255), m);
  for (int i = 0; i < 1000; ++i)
    EXPECT_EQ(static_cast<std::uint32_t>(i),
              scene.add(Sphere(Point(i, 0, -5), 0.05), i % 2 ? white : blue));
  EXPECT_EQ(2u, scene.appearances.size());
  EXPECT_EQ(1000u, scene.appearanceIndex.size());
  EXPECT_EQ(Color(200, 250, 255), scene.appearanceOf(999).emission);
  EXPECT_EQ(Color(80, 255, 230), scene.appearanceOf(998).emission);
  EXPECT_EQ(&scene.appearanceOf(0), &scene.appearanceOf(2));
  // TC02: a change to a shared row changes every shape that uses it
  scene.appearances[blue].material.kS = Double3(0.33);
  EXPECT_EQ(Double3(0.33), scene.appearanceOf(500).material.kS);
  EXPECT_EQ(Double3::ZERO, scene.appearanceOf(501).material.kS);
  // =============== Boundary Values Tests ==================
  // TC11: the last row is a valid row; one past it is refused, naming the row and the table,
  // and nothing is added
  EXPECT_EQ(1000u, scene.add(Sphere(Point(0, 1, -5), 1), white));
  try {
    scene.add(Sphere(Point(0, 2, -5), 1), 2);
    ADD_FAILURE() << "no exception";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ("LitScene::add: appearance 2 does not exist (the table has 2 rows)", e.what());
  }
  EXPECT_EQ(1001u, scene.geometries.size());
  EXPECT_EQ(1001u, scene.appearanceIndex.size());
  // TC12: an invalid material is refused by addAppearance, and no row is added
  Material bad;
  bad.kT = Double3(-0.1);
  EXPECT_THROW(scene.addAppearance(Color::BLACK, bad), std::invalid_argument);
  EXPECT_EQ(2u, scene.appearances.size());
}

TEST(LitSceneTests, aSphereCostsAtMost150Bytes) {
  // The budget that lets the BVH mini project's 10^6-star galaxy fit in 300 MB with its
  // hierarchy: a shape (the variant, as large as its largest alternative) plus its row index.
  // The measured figure (heap included) is printed by stage05_scene_memory; see the README.
  // TC01: 104 + 4 bytes (the Triangle, three points and a normal, sets the variant's size)
  EXPECT_EQ(104u, sizeof(Geometry));
  EXPECT_LE(sizeof(Geometry) + sizeof(std::uint32_t), 150u);
}

}  // namespace
}  // namespace rt
