// Which part of the build supplies the sampler, the render loop and the accelerator
// (cli/Registry.h's StagePiece): the highest stage that supplies one, whatever the order the parts
// register in. Label cli; in every course cut from stage 4 on: the expectations ask the build
// which stages it has.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "cli/Registry.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {
namespace {

/// True when this build has the stage that adds the tracer.
bool has(std::string_view tracer) { return missingTracerStage(tracer).empty(); }

TEST(RegistryTests, theHighestStageSupplyingAPieceWins) {
  // TC01: a higher stage registered after a lower one wins
  StagePiece<std::string()> piece("makeSampler");
  EXPECT_FALSE(piece);
  EXPECT_EQ("", piece.stage());
  piece.supply("stage04_camera", [] { return std::string("centre"); });
  piece.supply("mini1_glossy", [] { return std::string("jittered"); });
  EXPECT_TRUE(piece);
  EXPECT_EQ("mini1_glossy", piece.stage());
  EXPECT_EQ("jittered", piece());
  // TC02: and registered before it: not the order of registration, the course's
  StagePiece<std::string()> reversed("makeSampler");
  reversed.supply("mini2_bvh", [] { return std::string("tiles"); });
  reversed.supply("stage04_camera", [] { return std::string("rows"); });
  EXPECT_EQ("mini2_bvh", reversed.stage());
  EXPECT_EQ("tiles", reversed());
}

TEST(RegistryTests, refusesTwoSuppliersOfOneStageAndUnknownStages) {
  StagePiece<int()> render("render");
  render.supply("stage04_camera", [] { return 4; });
  // TC01: the same stage twice (two parts of one stage), named
  try {
    render.supply("stage04_camera", [] { return 5; });
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ("the registry's render: supplied twice by stage04_camera", e.what());
  }
  EXPECT_EQ(4, render());  // the first kept
  // TC02: a stage the course does not have, with the course's
  try {
    render.supply("stage08_meshes", [] { return 8; });
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(
        "the registry: 'stage08_meshes' is not a stage of the course (stage01_primitives,"
        "stage02_geometries,stage03_intersections,stage04_camera,stage05_lighting,"
        "stage06_shadows,stage07_reflections,mini1_glossy,mini2_bvh)",
        e.what());
  }
  // TC11: the course's first and last stages are its lowest and highest ranks
  EXPECT_EQ(0, courseStageRank("stage01_primitives"));
  EXPECT_EQ(8, courseStageRank("mini2_bvh"));
}

TEST(RegistryTests, thisBuildsPiecesComeFromItsHighestStages) {
  const CliRegistry& registry = cliRegistry();
  // TC01: the sampler: mini project 1's when the build has it, stage 4's centre ray before
  EXPECT_EQ(has("beams") ? "mini1_glossy" : "stage04_camera", registry.makeSampler.stage());
  // TC02: the render loop and the accelerator: mini project 2's when the build has it (the
  // accelerations are its), stage 4's rows and none before
  const bool mini2 = static_cast<bool>(registry.makeAccelerator);
  EXPECT_EQ(mini2 ? "mini2_bvh" : "stage04_camera", registry.render.stage());
  EXPECT_EQ(mini2 ? "mini2_bvh" : "", registry.makeAccelerator.stage());
}

}  // namespace
}  // namespace rt::cli
