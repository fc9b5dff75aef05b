// Stage 5: AppearanceInterner, which gives shapes that look the same one row of a LitScene's
// appearance table (what a scene file of a million stars of one material relies on).
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "geometries/Sphere.h"
#include "lighting/AppearanceInterner.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"

namespace rt {
namespace {

Sphere ball() { return Sphere(Point(0, 0, 0), 1); }

Appearance look(double red, double kD) {
  Appearance a;
  a.emission = Color(red, 0, 0);
  a.material.kD = Double3(kD);
  return a;
}

TEST(AppearanceInternerTests, row) {
  // ============ Equivalence Partitions Tests ==============
  LitScene scene;
  AppearanceInterner interner(scene);
  // TC01: the first look gets a new row, row 0
  EXPECT_EQ(interner.row(look(10, 0.5)), 0u);
  // TC02: a different emission gets a row of its own
  EXPECT_EQ(interner.row(look(20, 0.5)), 1u);
  // TC03: a different material gets a row of its own
  EXPECT_EQ(interner.row(look(10, 0.25)), 2u);
  // TC04: a look seen before shares its row, and adds none
  EXPECT_EQ(interner.row(look(20, 0.5)), 1u);
  EXPECT_EQ(interner.row(look(10, 0.5)), 0u);
  ASSERT_EQ(scene.appearances.size(), 3u);
  EXPECT_EQ(scene.appearances[1].emission, Color(20, 0, 0));
  EXPECT_EQ(scene.appearances[2].material.kD, Double3(0.25));
  // TC05: the same look with a label is another row; the same label again shares it
  EXPECT_EQ(interner.row(look(10, 0.5), "glass"), 3u);
  EXPECT_EQ(interner.row(look(10, 0.5), "glass"), 3u);
  // TC06: another label is another row again
  EXPECT_EQ(interner.row(look(10, 0.5), "water"), 4u);
  // TC07: mini 1's beam settings are part of the look
  Appearance glossy = look(10, 0.5);
  glossy.material.reflectedBeam.grid = 5;
  EXPECT_EQ(interner.row(glossy), 5u);
  glossy.material.reflectedBeam.grid = 1;
  glossy.material.refractedBeam.radius = 2;
  EXPECT_EQ(interner.row(glossy), 6u);
  // TC08: shininess and ior are part of the look
  Appearance shiny = look(10, 0.5);
  shiny.material.shininess = 7;
  EXPECT_EQ(interner.row(shiny), 7u);
  shiny.material.shininess = 0;
  shiny.material.ior = 1.5;
  EXPECT_EQ(interner.row(shiny), 8u);
  EXPECT_EQ(scene.appearances.size(), 9u);

  // =============== Boundary Values Tests ==================
  // TC11: -0.0 and 0.0 compare equal but differ in their bits: two rows
  EXPECT_EQ(interner.row(look(0.0, 0.5)), 9u);
  EXPECT_EQ(interner.row(look(-0.0, 0.5)), 10u);
  EXPECT_EQ(scene.appearances.size(), 11u);
}

TEST(AppearanceInternerTests, rowsItDidNotAdd) {
  // TC01: a row already in the table is not handed out, even for the same look
  LitScene scene;
  const std::uint32_t before = scene.addAppearance(Color(10, 0, 0), look(10, 0.5).material);
  AppearanceInterner interner(scene);
  EXPECT_EQ(before, 0u);
  EXPECT_EQ(interner.row(look(10, 0.5)), 1u);
  // TC02: nor is a row added to the scene by other means after the interner was made
  scene.addAppearance(Color(20, 0, 0));
  EXPECT_EQ(interner.row(look(20, 0)), 3u);
}

TEST(AppearanceInternerTests, invalidMaterial) {
  // TC01: an invalid material throws and adds no row; the interner still works afterwards
  LitScene scene;
  AppearanceInterner interner(scene);
  EXPECT_THROW(interner.row(look(10, -1)), std::invalid_argument);
  EXPECT_TRUE(scene.appearances.empty());
  EXPECT_EQ(interner.row(look(10, 0.5)), 0u);
  // TC02: add() with an invalid material adds neither a row nor a shape
  EXPECT_THROW(interner.add(ball(), look(10, -1)), std::invalid_argument);
  EXPECT_EQ(scene.appearances.size(), 1u);
  EXPECT_EQ(scene.geometries.size(), 0u);
}

TEST(AppearanceInternerTests, add) {
  // TC01: shapes that look the same share a row; each shape gets its own index
  LitScene scene;
  AppearanceInterner interner(scene);
  EXPECT_EQ(interner.add(ball(), look(10, 0.5)), 0u);
  EXPECT_EQ(interner.add(ball(), look(20, 0.5)), 1u);
  EXPECT_EQ(interner.add(ball(), look(10, 0.5)), 2u);
  EXPECT_EQ(interner.add(ball(), look(10, 0.5), "glass"), 3u);
  EXPECT_EQ(scene.appearanceIndex, (std::vector<std::uint32_t>{0, 1, 0, 2}));
  EXPECT_EQ(scene.appearances.size(), 3u);
  EXPECT_EQ(&interner.scene(), &scene);
  EXPECT_NO_THROW(scene.validate());
}

}  // namespace
}  // namespace rt
