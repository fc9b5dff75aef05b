// The render request resolved in one step (cli/RenderRequest.h): the scene argument and the
// options turned into the document, the tracer, the output and the warnings, every check done,
// nothing printed. Label cli; in every course cut from stage 4 on.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "InProcess.h"
#include "cli/BuiltinScenes.h"
#include "cli/CommandLine.h"
#include "cli/Registry.h"
#include "cli/RenderRequest.h"

namespace rt::cli {
namespace {

/// The message of the UsageError that f throws ("" when it throws none).
template <typename F>
std::string usageErrorOf(F f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

SceneArguments twoColor(std::optional<int> width = 40) {
  SceneArguments a;
  a.argument = "two-color";
  a.width = width;
  return a;
}

TEST(RenderRequestTests, resolvesTheSceneTheOptionsAndTheOutput) {
  // TC01: a render of a built-in scene without -o: the scene with the options applied, its
  // stage's tracer, the default output, no warnings
  const RenderRequest r = resolveRenderRequest(twoColor(), {.writesImage = true});
  EXPECT_EQ(40, r.doc.camera.nX);
  EXPECT_EQ(40, r.doc.camera.nY);  // the scene's aspect ratio (square) kept
  ASSERT_NE(nullptr, r.tracer);
  EXPECT_EQ("ambient", r.tracer->name);
  EXPECT_EQ("two-color.png", r.output);
  EXPECT_EQ(std::vector<std::string>{}, r.warnings);
  // TC02: -o given: the output is its path
  const std::string dir = test::freshTestDirectory("request-output");
  const RenderRequest given =
      resolveRenderRequest(twoColor(), {.writesImage = true, .output = dir + "/x.png"});
  EXPECT_EQ(dir + "/x.png", given.output);
  // TC03: a command that writes no image (probe, bench) has no output
  EXPECT_EQ("", resolveRenderRequest(twoColor(), {}).output);
  // TC04: --tracer and --seed are applied to the document's render settings
  SceneArguments hits = twoColor();
  hits.tracer = "hits";
  hits.seed = 7;
  const RenderRequest h = resolveRenderRequest(hits, {});
  EXPECT_EQ("hits", h.tracer->name);
  EXPECT_EQ("hits", h.doc.render.tracer);
  EXPECT_EQ(7u, h.doc.render.seed);
  // TC05: --light-buffers (mini project 2's option, a setting in every cut) is applied to the
  // document: off and on as given, and without it the scene's render.lightBuffers (on)
  SceneArguments off = twoColor();
  off.settings.lightBuffers = false;
  EXPECT_FALSE(resolveRenderRequest(off, {}).doc.render.lightBuffers);
  SceneArguments on = twoColor();
  on.settings.lightBuffers = true;
  EXPECT_TRUE(resolveRenderRequest(on, {}).doc.render.lightBuffers);
  EXPECT_TRUE(r.doc.render.lightBuffers);
}

TEST(RenderRequestTests, refusesBadInputBeforeTheFirstRay) {
  const std::string dir = test::freshTestDirectory("request-refused");
  // TC01: an unknown scene, named
  SceneArguments unknown;
  unknown.argument = "nebula";
  EXPECT_EQ(
      "unknown scene 'nebula' (rt list shows the built-in scenes; a scene file ends in .json)",
      usageErrorOf([&] { resolveRenderRequest(unknown, {}); }));
  // TC02: -o naming a directory, with its origin
  EXPECT_EQ("-o: cannot write '" + dir + "': it is a directory", usageErrorOf([&] {
              resolveRenderRequest(twoColor(), {.writesImage = true, .output = dir});
            }));
  // TC03: -o without .png
  EXPECT_EQ(
      "-o: the image is written as PNG, so its name must end in .png; got '" + dir + "/x.jpg'",
      usageErrorOf([&] {
        resolveRenderRequest(twoColor(), {.writesImage = true, .output = dir + "/x.jpg"});
      }));
  // TC04: an unknown view, with the scene's (none)
  SceneArguments view = twoColor();
  view.view = "above";
  EXPECT_EQ("--view: the scene has no view 'above' (it has none)",
            usageErrorOf([&] { resolveRenderRequest(view, {}); }));
  // TC05: (not refused) a scene file's default output is its name with .png, in the current
  // directory
  const std::string file = dir + "/room.json";
  std::ofstream(file) << "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0],\n"
                         " \"vpDistance\": 10, \"vpSize\": [4, 4], \"resolution\": [4, 4]}}\n";
  SceneArguments room;
  room.argument = file;
  EXPECT_EQ("room.png", resolveRenderRequest(room, {.writesImage = true}).output);
  // TC06: a resolution out of range, with where it came from: --width on a scene 1 pixel wide
  // and 32768 high makes the height 32768·32768
  const std::string tall = dir + "/tall.json";
  std::ofstream(tall) << "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0],\n"
                         " \"vpDistance\": 10, \"vpSize\": [4, 4], \"resolution\": [1, 32768]}}\n";
  SceneArguments wide;
  wide.argument = tall;
  wide.width = 32768;
  EXPECT_EQ(
      "the image's resolution 32768x1073741824 (from --width, the height keeping the scene's "
      "aspect ratio) is outside 1..32768 per side",
      usageErrorOf([&] { resolveRenderRequest(wide, {}); }));
  // TC07: the four origins a size is said to come from
  EXPECT_EQ("from --width and --height", resolutionOrigin(1, 2));
  EXPECT_EQ("from --width, the height keeping the scene's aspect ratio",
            resolutionOrigin(1, std::nullopt));
  EXPECT_EQ("from --height, the width keeping the scene's aspect ratio",
            resolutionOrigin(std::nullopt, 2));
  EXPECT_EQ("the scene's resolution", resolutionOrigin(std::nullopt, std::nullopt));
}

TEST(RenderRequestTests, collectsTheWarningsWithoutPrinting) {
  // A sphere without ambient light, by the ambient tracer: every shape black.
  const std::string dir = test::freshTestDirectory("request-warnings");
  const std::string file = dir + "/dark.json";
  std::ofstream(file)
      << "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], \"vpDistance\": 10,\n"
         "            \"vpSize\": [4, 4], \"resolution\": [4, 4]},\n"
         " \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}]}\n";
  SceneArguments dark;
  dark.argument = file;
  dark.tracer = "ambient";
  // TC01: rendering: one warning, without "rt: " (the caller prints it)
  const RenderRequest r = resolveRenderRequest(dark, {});
  ASSERT_EQ(1u, r.warnings.size());
  EXPECT_TRUE(r.warnings[0].starts_with(
      "warning: the ambient tracer (--tracer ambient) shows the ambient light wherever a ray "
      "hits a shape, and this scene's ambient light is zero"))
      << r.warnings[0];
  // TC02: not rendering (probe): no warning about the render
  EXPECT_EQ(std::vector<std::string>{},
            resolveRenderRequest(dark, {.makesImage = false, .renders = false}).warnings);
}

TEST(RenderRequestTests, warnsOfABlackMeshToo) {
  // TC01: the teapot (a mesh and no shape) has no ambient light: by the ambient tracer, the
  // same warning as for shapes
  if (findBuiltinScene("teapot") == nullptr) GTEST_SKIP() << "the teapot is mini2_bvh's";
  SceneArguments pot;
  pot.argument = "teapot";
  pot.tracer = "ambient";
  const RenderRequest r = resolveRenderRequest(pot, {});
  ASSERT_EQ(1u, r.warnings.size());
  EXPECT_TRUE(r.warnings[0].starts_with("warning: the ambient tracer (--tracer ambient)"))
      << r.warnings[0];
}

TEST(RenderRequestTests, buildsTheRenderContext) {
  const RenderRequest r = resolveRenderRequest(twoColor(), {});
  const RenderSetup setup = r.build();
  // TC01: the camera of the document's size, its own image, the tracer and the sampler
  EXPECT_EQ(40, setup.camera.nX());
  EXPECT_EQ(40, setup.camera.nY());
  ASSERT_NE(nullptr, setup.tracer);
  ASSERT_NE(nullptr, setup.sampler);
  EXPECT_EQ(1, setup.sampler->samplesPerPixel());  // two-color asks for one sample
  // TC02: the context is the three
  const RenderContext context = setup.context();
  EXPECT_EQ(&setup.camera, &context.camera);
  EXPECT_EQ(setup.tracer.get(), &context.tracer);
  EXPECT_EQ(setup.sampler.get(), &context.sampler);
  // TC03: an accelerator exactly when the build has one (mini project 2: bvh by default)
  EXPECT_EQ(static_cast<bool>(cliRegistry().makeAccelerator), setup.accelerator != nullptr);
}

}  // namespace
}  // namespace rt::cli
