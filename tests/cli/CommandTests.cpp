// Tests of `rt` through its library (rt::cli::runRt and the pieces it is made of): the same
// code as the executable, without a process per case.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "InProcess.h"
#include "RtProcess.h"
#include "camera/CourseScenes.h"
#include "cli/BuiltinScenes.h"
#include "cli/CommandLine.h"
#include "cli/Commands.h"
#include "cli/RenderCommand.h"
#include "cli/RenderRequest.h"
#include "cli/Tracers.h"
#include "geometries/Plane.h"
#include "geometries/Sphere.h"
#include "geometries/TriangleMesh.h"
#include "glossy/DemoTable.h"
#include "lighting/CourseScenes.h"
#include "lighting/PhongTracer.h"
#include "reflections/CourseScenes.h"
#include "scenefile/LitDocument.h"
#include "scenefile/MeshDocument.h"
#include "scenefile/ModelFile.h"
#include "scenefile/SceneFile.h"
#include "shadows/CourseScenes.h"

#ifndef RT_SCENES_DIR
#error "RT_SCENES_DIR must name the repository's scenes/ folder"
#endif
#ifndef RT_PROJECT_VERSION
#error "RT_PROJECT_VERSION must be the CMake project's version"
#endif

namespace rt::cli {
namespace {

using test::lines;
using test::Outcome;
using test::run;

// ---------------------------------------------------------------------------------------------
// The built-in scenes

/// The message with which built-in scene `name` refuses --param `param`, or "" when it takes it.
std::string refused(const char* name, const char* param, const char* second = nullptr) {
  std::vector<std::string> params{param};
  if (second != nullptr) params.emplace_back(second);
  try {
    (void)makeBuiltinScene(*findBuiltinScene(name), params);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(BuiltinScenesTests, everyStageTableIsRegisteredOnce) {
  // TC01: the scene count is stage 4's two scenes plus every entry of the stages' tables
  // (and mini project 1's galaxy and demonstration scenes, mini project 2's two teapots)
  const std::size_t expected = 2 + lightingScenes().size() + shadowScenes().size() +
                               reflectionScenes().size() + 1 + demoScenes().size() + 2;
  EXPECT_EQ(builtinScenes().size(), expected);
  // TC02: every table entry is there under its own name, with its stage's tracer
  const auto expectEntries = [](std::span<const CourseScene> table, const char* tracer) {
    for (const CourseScene& entry : table) {
      const BuiltinScene* s = findBuiltinScene(entry.name);
      ASSERT_NE(s, nullptr) << entry.name;
      EXPECT_EQ(s->description, entry.description);
      EXPECT_EQ(s->tracer, tracer) << entry.name;
      const SceneDocument doc = makeBuiltinScene(*s, {});
      EXPECT_EQ(doc.render.tracer, tracer) << entry.name;
      // The course's grid over the picture, where the table gives one (color-render: white,
      // every 100 pixels); the format's default colour, yellow, where it gives none.
      EXPECT_EQ(doc.render.gridLines, entry.gridInterval) << entry.name;
      EXPECT_EQ(doc.render.gridColor, entry.gridInterval > 0 ? entry.gridColor : Color(255, 255, 0))
          << entry.name;
    }
  };
  ASSERT_EQ(lightingScenes()[0].name, std::string_view("color-render"));
  ASSERT_EQ(lightingScenes()[0].gridInterval, 100);  // the one table entry with a grid
  expectEntries(lightingScenes(), "phong");
  expectEntries(shadowScenes(), "shadow");
  expectEntries(reflectionScenes(), "whitted");
  // TC03: stage 4's scenes: the course's is rendered by the ambient tracer, the shapes by the
  // normals
  ASSERT_NE(findBuiltinScene("two-color"), nullptr);
  EXPECT_EQ(makeBuiltinScene(*findBuiltinScene("two-color"), {}).render.tracer, "ambient");
  ASSERT_NE(findBuiltinScene("shapes"), nullptr);
  EXPECT_EQ(findBuiltinScene("shapes")->tracer, "normals");
  EXPECT_EQ(makeBuiltinScene(*findBuiltinScene("shapes"), {}).render.tracer, "normals");
  // TC04: names are unique, non-empty, without spaces; every description is non-empty
  std::set<std::string> names;
  for (const BuiltinScene& s : builtinScenes()) {
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    EXPECT_FALSE(s.name.empty());
    EXPECT_EQ(s.name.find(' '), std::string::npos) << s.name;
    EXPECT_FALSE(s.description.empty()) << s.name;
  }
  // TC11: an unknown name
  EXPECT_EQ(findBuiltinScene("no-such-scene"), nullptr);
}

TEST(BuiltinScenesTests, twoColorDocumentIsTheCourseScene) {
  // TC01: the document carries stage 4's scene and camera unchanged, as a LitScene whose every
  // shape has the default appearance (one shared row)
  const SceneSetup<Scene> course = twoColorScene();
  const SceneDocument doc = makeBuiltinScene(*findBuiltinScene("two-color"), {});
  EXPECT_EQ(litScene(doc).geometries.size(), course.scene.geometries.size());
  EXPECT_EQ(litScene(doc).appearances.size(), 1u);
  EXPECT_EQ(litScene(doc).appearanceIndex, std::vector<std::uint32_t>(4, 0));
  EXPECT_EQ(litScene(doc).background, course.scene.background);
  EXPECT_EQ(litScene(doc).ambientLight.intensity(), course.scene.ambientLight.intensity());
  EXPECT_EQ(doc.camera.nX, course.camera.nX);
  EXPECT_EQ(doc.camera.nY, course.camera.nY);
  EXPECT_TRUE(doc.geometryNames.empty());
  EXPECT_EQ(nullptr, doc.findPart<NamedMaterials>());
}

TEST(BuiltinScenesTests, demoScenesCarryTheirRenderSettingsAndKnobs) {
  const auto doc = [](const char* name, std::vector<std::string> params = {}) {
    return makeBuiltinScene(*findBuiltinScene(name), params);
  };
  // TC01: mini project 1's demonstration scenes are rendered by the beams tracer with the render
  // settings of their table entry
  for (const DemoScene& e : demoScenes()) EXPECT_EQ(doc(e.course.name).render.tracer, "beams");
  EXPECT_EQ(doc("antialiasing").render.samples, 4);
  EXPECT_EQ(doc("depth-of-field").render.lensSamples, 24);
  EXPECT_EQ(doc("depth-of-field").camera.aperture, 0.2);
  EXPECT_TRUE(doc("adaptive").render.adaptive);
  EXPECT_EQ(doc("adaptive").render.adaptiveDepth, 3);
  // TC02: their knobs are their parameters, with the scene's values as defaults
  std::string params;
  for (const SceneParam& p : findBuiltinScene("super-sampling")->params)
    params += p.name + "=" + p.defaultValue + " ";
  EXPECT_EQ(params,
            "glossyGrid=1 frostedGrid=1 shadowSamples=1 samples=1 lensSamples=1 aperture=0 "
            "adaptive=off ");
  // TC03: a parameter changes what it names
  EXPECT_EQ(doc("antialiasing", {"samples=1"}).render.samples, 1);
  EXPECT_FALSE(doc("adaptive", {"adaptive=off"}).render.adaptive);
  EXPECT_EQ(doc("depth-of-field", {"aperture=0.05"}).camera.aperture, 0.05);
  EXPECT_EQ(std::get<PointLight>(litScene(doc("soft-shadows", {"shadowSamples=4"})).lights[0])
                .shadowSamples,
            4);
  // TC11: a value out of range, naming the parameter
  EXPECT_EQ(refused("antialiasing", "samples=0"),
            "--param samples: expected an integer from 1 to 64, got '0'");
  EXPECT_EQ(refused("depth-of-field", "aperture=-1"),
            "--param aperture: expected a number from 0 to 1000, got -1");
  EXPECT_EQ(refused("adaptive", "adaptive=maybe"),
            "--param adaptive: expected on or off, got 'maybe'");
}

TEST(BuiltinScenesTests, teapotsTakeTheirParameters) {
  const auto doc = [](const char* name, std::vector<std::string> params = {}) {
    return makeBuiltinScene(*findBuiltinScene(name), params);
  };
  const auto triangles = [](const SceneDocument& d) {
    return litScene(d).geometries.triangleCount();
  };
  // TC01: the course's TeapotTest: 992 flat triangles, 800 x 800, the Whitted tracer (the
  // course's SimpleRayTracer), no grid lines unless asked for
  const SceneDocument teapot = doc("teapot");
  EXPECT_EQ(findBuiltinScene("teapot")->stage, "mini2_bvh");
  EXPECT_EQ(teapot.render.tracer, "whitted");
  EXPECT_EQ(triangles(teapot), 992u);
  EXPECT_FALSE(litScene(teapot).geometries.meshes()[0].mesh->hasNormals());
  EXPECT_EQ(teapot.camera.nX, 800);
  EXPECT_EQ(teapot.render.gridLines, 0);
  // TC02: its parameters: a finer teapot, smooth, the course's grid lines every 50 pixels
  EXPECT_EQ(triangles(doc("teapot", {"detail=13"})), 10712u);
  EXPECT_TRUE(litScene(doc("teapot", {"smooth=on"})).geometries.meshes()[0].mesh->hasNormals());
  EXPECT_EQ(doc("teapot", {"grid=50"}).render.gridLines, 50);
  // TC03: the later year's: 400 bubbles, 1000 x 1000; fewer, and elsewhere with another seed
  const SceneDocument bubbles = doc("bubbles");
  EXPECT_EQ(litScene(bubbles).geometries.size(), 400u);
  EXPECT_EQ(triangles(bubbles), 992u);
  EXPECT_EQ(bubbles.camera.nX, 1000);
  EXPECT_EQ(litScene(doc("bubbles", {"count=7"})).geometries.size(), 7u);
  EXPECT_NE(std::get<Sphere>(litScene(doc("bubbles", {"seed=2"})).geometries[0]).center(),
            std::get<Sphere>(litScene(bubbles).geometries[0]).center());
  // TC11: values out of range, naming the parameter
  EXPECT_EQ(refused("teapot", "detail=0"),
            "--param detail: expected an integer from 1 to 256, got '0'");
  EXPECT_EQ(refused("teapot", "detail=257"),
            "--param detail: expected an integer from 1 to 256, got '257'");
  EXPECT_EQ(refused("teapot", "smooth=yes"), "--param smooth: expected on or off, got 'yes'");
  EXPECT_EQ(refused("teapot", "grid=-1"),
            "--param grid: expected an integer from 0 to 32768, got '-1'");
  EXPECT_EQ(refused("bubbles", "count=1000001"),
            "--param count: expected an integer from 0 to 1000000, got '1000001'");
  // TC12: the teapot has no bubbles to count
  EXPECT_EQ(refused("teapot", "count=3")
                .rfind("--param: the scene 'teapot' has no parameter "
                       "'count'",
                       0),
            0u);
  // TC13: values each in range that the scene's own checks refuse: the message says which
  // --param values were given (the galaxy's stars are bounded, not only arms and perArm)
  EXPECT_EQ(refused("galaxy", "arms=1000", "perArm=1000000"),
            "--param arms=1000 --param perArm=1000000: galaxy: arms x perArm must be at most "
            "10000000 stars, got 1000 x 1000000 = 1000000000");
  EXPECT_EQ(refused("teapot", "floor=-1"),
            "--param floor=-1: teapotScene: floor must be a non-negative finite number, got -1");
}

TEST(TracersTests, tracerNamesAreTheSceneFormatsOnes) {
  // TC01: --tracer and a scene file's render.tracer accept the same names, in the same order
  std::vector<std::string_view> ours;
  for (const TracerKind& t : tracerKinds()) ours.push_back(t.name);
  const std::vector<std::string_view> format = knownTracers();
  EXPECT_EQ(ours, std::vector<std::string_view>(format.begin(), format.end()));
}

// ---------------------------------------------------------------------------------------------
// rt list, --help, --version, usage errors

TEST(CommandTests, listPrintsOneLinePerSceneNameFirst) {
  const Outcome r = run({"list"});
  // TC01: exit 0, nothing on stderr
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.err, "");
  // TC02: one line per built-in scene, in order: the name, two or more spaces, the description;
  // a scene with parameters has a second line, indented, listing them with their defaults
  const std::vector<std::string> got = lines(r.out);
  std::size_t line = 0;
  for (const BuiltinScene& s : builtinScenes()) {
    ASSERT_LT(line, got.size());
    ASSERT_TRUE(got[line].starts_with(s.name + "  ")) << got[line];
    EXPECT_EQ(got[line].substr(got[line].find_first_not_of(' ', s.name.size())), s.description);
    ++line;
    if (!s.params.empty()) {
      ASSERT_LT(line, got.size());
      std::string expected = "parameters (--param NAME=VALUE):";
      for (const SceneParam& p : s.params) expected += " " + p.name + "=" + p.defaultValue;
      EXPECT_EQ(got[line].substr(got[line].find_first_not_of(' ')), expected);
      ++line;
    }
  }
  EXPECT_EQ(line, got.size());
  // TC03: the galaxy lists its five parameters
  EXPECT_NE(r.out.find("arms=21 perArm=50 stars=0 diffusion=on layout=1"), std::string::npos);
  // TC11: extra arguments are refused
  const Outcome extra = run({"list", "more"});
  EXPECT_EQ(extra.code, 2);
  EXPECT_EQ(extra.err, "rt: unexpected argument 'more' for rt list (see rt list --help)\n");
}

TEST(CommandTests, helpAndVersion) {
  // TC01: --version prints the CMake project's version
  Outcome r = run({"--version"});
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, std::string("rt ") + RT_PROJECT_VERSION + "\n");
  // TC02: rt --help names every command
  r = run({"--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* command : {"list", "render", "probe", "export"})
    EXPECT_NE(r.out.find(std::string("\n  ") + command + " "), std::string::npos) << command;
  // TC03: rt render --help states the default output and every option
  r = run({"render", "--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_TRUE(r.out.starts_with("Usage: rt render SCENE [OPTIONS]\n")) << r.out;
  for (const char* text : {"SCENE.png", "--width W", "--height H", "--tracer T", "--grid-lines N",
                           "--quiet", "--silent", "-o, --output FILE.png", "whitted", "130"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
  // TC04: the other commands' help
  for (const char* command : {"list", "probe", "export"}) {
    r = run({command, "--help"});
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.starts_with(std::string("Usage: rt ") + command)) << r.out;
  }
  // TC11: no command at all
  r = run({});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: missing COMMAND (see rt --help)\n");
}

TEST(CommandTests, badUsageExitsWithTwoAndOneLine) {
  struct Case {
    const char* partition;
    std::vector<std::string> args;
    std::string message;
  };
  // An existing directory, named without an image's or a scene file's ending.
  const std::string directory = test::freshDirectory("outputIsADirectory");
  const std::vector<Case> cases = {
      // TC01: an unknown command, with a suggestion
      {"TC01",
       {"rendr", "two-color"},
       "rt: unknown command 'rendr'; did you mean 'render'? (see rt --help)\n"},
      // TC02: an unknown scene, with a suggestion
      {"TC02",
       {"render", "two-colour"},
       "rt: unknown scene 'two-colour'; did you mean 'two-color'? (rt list shows the built-in "
       "scenes; a scene file ends in .json)\n"},
      // TC03: an unknown scene that resembles nothing
      {"TC03",
       {"render", "nebula"},
       "rt: unknown scene 'nebula' (rt list shows the built-in scenes; a scene file ends in "
       ".json)\n"},
      // TC04: an unknown option
      {"TC04",
       {"render", "two-color", "--fast"},
       "rt: unknown option '--fast' for rt render (see rt render --help)\n"},
      // TC05: a width that is not a number
      {"TC05",
       {"render", "two-color", "--width", "wide"},
       "rt: --width: expected an integer from 1 to 32768, got 'wide'\n"},
      // TC06: an unknown tracer
      {"TC06",
       {"render", "two-color", "--tracer", "phog"},
       "rt: --tracer: unknown tracer 'phog'; did you mean 'phong'? (known: rays normals hits "
       "ambient phong shadow whitted beams)\n"},
      // TC07: an output that is not a PNG
      {"TC07",
       {"render", "two-color", "-o", "x.jpg"},
       "rt: -o: the image is written as PNG, so its name must end in .png; got 'x.jpg'\n"},
      // TC08: probe without a ray
      {"TC08",
       {"probe", "two-color"},
       "rt: missing --ray OX,OY,OZ DX,DY,DZ or --pixel X,Y (see rt probe --help)\n"},
      // TC09: probe with both a ray and a pixel
      {"TC09",
       {"probe", "two-color", "--pixel", "1,1", "--ray", "0,0,0", "0,0,-1"},
       "rt: give only one of --ray OX,OY,OZ DX,DY,DZ or --pixel X,Y (see rt probe --help)\n"},
      // TC10: a zero ray direction
      {"TC10",
       {"probe", "two-color", "--ray", "0,0,0", "0,0,0"},
       "rt: --ray direction: must not be the zero vector, got '0,0,0'\n"},
      // TC11: a ray origin with two numbers
      {"TC11",
       {"probe", "two-color", "--ray", "0,0", "0,0,-1"},
       "rt: --ray origin: expected 3 comma-separated numbers, got '0,0'\n"},
      // TC11b: a ray origin beyond a scene file's coordinates (MAX_COORDINATE), where a sphere's
      // solver overflowed and the probe answered that the ray hits nothing
      {"TC11b",
       {"probe", "two-color", "--ray", "0,0,-1e160", "0,0,1"},
       "rt: --ray origin: expected coordinates from -1e+75 to 1e+75, got '0,0,-1e160'\n"},
      // TC12: export of a name that is not a built-in scene
      {"TC12",
       {"export", "nebula"},
       "rt: unknown scene 'nebula' (rt list shows the built-in scenes; a scene file ends in "
       ".json)\n"},
      // TC13: export to a file that is not .json
      {"TC13",
       {"export", "two-color", "-o", "x.txt"},
       "rt: -o: a scene file's name must end in .json; got 'x.txt'\n"},
      // TC14: a pixel given as two arguments: the X,Y form is explained (once "rt: rt probe:
      // unexpected argument '2'")
      {"TC14",
       {"probe", "two-color", "--pixel", "1", "2"},
       "rt: --pixel takes X,Y (one argument, comma-separated), got '1' and an extra '2' (see rt "
       "probe --help)\n"},
      // TC15: a missing scene
      {"TC15",
       {"render", "--width", "8"},
       "rt: missing SCENE for rt render (see rt render --help)\n"},
      // TC16: a width that is a number but not an integer, in any form
      {"TC16",
       {"render", "two-color", "--width", "6.45e1"},
       "rt: --width: expected an integer from 1 to 32768, got '6.45e1'\n"},
      // TC17: render -o naming an existing directory (once "its name must end in .png")
      {"TC17",
       {"render", "two-color", "-o", directory},
       "rt: -o: cannot write '" + directory + "': it is a directory\n"},
      // TC18: export -o naming an existing directory (once "must end in .json")
      {"TC18",
       {"export", "two-color", "-o", directory},
       "rt: -o: cannot write '" + directory + "': it is a directory\n"},
      // TC21: a width one beyond 2^15 is refused before anything is allocated
      {"TC21",
       {"render", "two-color", "--width", "32769"},
       "rt: --width: expected an integer from 1 to 32768, got '32769'\n"},
      // TC22: a height of zero
      {"TC22",
       {"render", "two-color", "--height", "0"},
       "rt: --height: expected an integer from 1 to 32768, got '0'\n"},
      // TC24: 2^15 + 1 written as a JSON exponent is refused too
      {"TC24",
       {"render", "two-color", "--width", "3.2769e4"},
       "rt: --width: expected an integer from 1 to 32768, got '3.2769e4'\n"},
      // TC23: --pixel one column beyond the (overridden) image
      {"TC23",
       {"probe", "two-color", "--width", "10", "--pixel", "10,0"},
       "rt: --pixel X: expected an integer from 0 to 9, got '10'\n"},
      // TC25: an unknown acceleration, with a suggestion and the known ones
      {"TC25",
       {"render", "two-color", "--accel", "bhv"},
       "rt: --accel: unknown acceleration 'bhv'; did you mean 'bvh'? (known: none cbr bvh bvh4 "
       "grid)\n"},
      // TC26: threads beyond the pool's limit
      {"TC26",
       {"render", "two-color", "--threads", "1025"},
       "rt: --threads: expected an integer from 0 to 1024, got '1025'\n"},
      // TC27: probe takes no thread count, by pixel or by ray (it traces on one thread)
      {"TC27",
       {"probe", "two-color", "--pixel", "0,0", "--threads", "2"},
       "rt: unknown option '--threads' for rt probe (see rt probe --help)\n"},
      {"TC27",
       {"probe", "two-color", "--ray", "0,0,0", "0,0,1", "--threads", "1"},
       "rt: unknown option '--threads' for rt probe (see rt probe --help)\n"},
      // TC28: light buffers neither on nor off
      {"TC28",
       {"render", "two-color", "--light-buffers", "maybe"},
       "rt: --light-buffers: expected on or off, got 'maybe'\n"},
  };
  for (const Case& c : cases) {
    const Outcome r = run(c.args);
    EXPECT_EQ(r.code, 2) << c.partition;
    EXPECT_EQ(r.err, c.message) << c.partition;
    EXPECT_EQ(r.out, "") << c.partition;
  }
}

TEST(CommandTests, probeByRayRefusesTheOptionsThatChooseAPixel) {
  // The galaxy has views, so --view main alone would be accepted.
  const std::vector<std::string> byRay{"probe", "galaxy", "--ray", "0,0,0", "0,0,-1"};
  // TC01: each option a ray given directly leaves without effect (the camera, its image, the
  // pixel's samples): exit 2, the pair named, nothing printed
  const std::vector<std::pair<std::string, std::string>> refused{
      {"--view", "main"}, {"--width", "8"}, {"--height", "8"}, {"--seed", "3"}};
  for (const auto& [option, value] : refused) {
    std::vector<std::string> args = byRay;
    args.insert(args.end(), {option, value});
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 2) << option;
    EXPECT_EQ(r.err, "rt: --ray excludes " + option + " (see rt probe --help)\n") << option;
    EXPECT_EQ(r.out, "") << option;
  }
  // TC02: the same before --ray
  const Outcome before = run({"probe", "galaxy", "--width", "8", "--ray", "0,0,0", "0,0,-1"});
  EXPECT_EQ(before.code, 2);
  EXPECT_EQ(before.err, "rt: --ray excludes --width (see rt probe --help)\n");
  EXPECT_EQ(before.out, "");
  // TC03: the options that change what a ray meets or how it is traced are taken with --ray
  for (const std::vector<std::string>& taken :
       std::vector<std::vector<std::string>>{{"--tracer", "whitted"},
                                             {"--param", "arms=3"},
                                             {"--accel", "none"},
                                             {"--light-buffers", "off"}}) {
    std::vector<std::string> args = byRay;
    args.insert(args.end(), taken.begin(), taken.end());
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 0) << taken[0] << ": " << r.err;
  }
  // TC04: and every refused one with --pixel, which they choose
  std::vector<std::string> byPixel{"probe", "galaxy", "--pixel", "0,0"};
  for (const auto& [option, value] : refused) byPixel.insert(byPixel.end(), {option, value});
  const Outcome pixel = run(byPixel);
  EXPECT_EQ(pixel.code, 0) << pixel.err;
}

TEST(CommandTests, aParamTakesOneValueAndLeavesTheSceneArgumentAlone) {
  // TC01: export: --param before the scene's name is the same as after it
  const Outcome before = run({"export", "--param", "arms=3", "galaxy"});
  EXPECT_EQ(before.code, 0) << before.err;
  EXPECT_EQ(before.out, run({"export", "galaxy", "--param", "arms=3"}).out);
  // TC02: the scene options of render and probe: the same
  const Outcome probe = run({"probe", "--param", "arms=3", "galaxy", "--pixel", "0,0"});
  EXPECT_EQ(probe.code, 0) << probe.err;
  EXPECT_EQ(probe.out, run({"probe", "galaxy", "--param", "arms=3", "--pixel", "0,0"}).out);
}

TEST(CommandTests, defaultOutputPath) {
  // TC01: a built-in scene: NAME.png in the current directory
  EXPECT_EQ(defaultOutputPath("two-color"), "two-color.png");
  // TC02: a scene file: its name, .png for .json, in the current directory
  EXPECT_EQ(defaultOutputPath("some/dir/room.json"), "room.png");
}

TEST(CommandTests, renderStoppedBeforeItsFirstRowWritesNothing) {
  const std::string dir = test::freshDirectory("renderStopped");
  const std::string out = dir + "/out.png";
  { std::ofstream(out) << "the previous image"; }
  // TC01: the stop flag is already raised (Ctrl-C during loading): exit 130, no ray traced,
  // the existing file untouched
  std::ostringstream o, e;
  const std::atomic<bool> stop{true};
  const int code = runRt(std::vector<std::string>{"render", "two-color", "-o", out, "--width", "10",
                                                  "--height", "10", "--quiet"},
                         Io{o, e, false, &stop});
  EXPECT_EQ(code, 130);
  EXPECT_EQ(e.str(), "rt: interrupted after 0 of 100 pixels; nothing written to " + out + "\n");
  EXPECT_EQ(test::readFile(out), "the previous image");
}

// ---------------------------------------------------------------------------------------------
// Light buffers (mini project 2's render setting)

/// The document `rt render ARGS...` renders: its arguments parsed by rt render's own options.
SceneDocument renderedDocument(std::vector<std::string> args) {
  CommandLine line("rt", "rt for the tests", "", "rt 0");
  RenderArgs into;
  addRenderOptions(line.addCommand("render", "render", "", [](const Io&) { return 0; }), into);
  args.insert(args.begin(), "render");
  EXPECT_TRUE(line.parse(args).run);
  return sceneFromArguments(into.scene);
}

TEST(LightBuffersTests, optionSetsTheDocumentsSetting) {
  // TC01: --light-buffers off and on set render.lightBuffers
  EXPECT_FALSE(renderedDocument({"two-color", "--light-buffers", "off"}).render.lightBuffers);
  EXPECT_TRUE(renderedDocument({"two-color", "--light-buffers", "on"}).render.lightBuffers);
  // TC02: without it, the scene's: a built-in scene's default (on), a file's own (off)
  EXPECT_TRUE(renderedDocument({"two-color"}).render.lightBuffers);
  const std::string dir = test::freshDirectory("lightBuffersOption");
  const std::string file = test::writeText(
      dir + "/off.json",
      "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], \"vpDistance\": 10,\n"
      " \"vpSize\": [4, 4], \"resolution\": [4, 4]},\n"
      " \"render\": {\"lightBuffers\": false}}\n");
  EXPECT_FALSE(renderedDocument({file}).render.lightBuffers);
  // TC03: the option overrides the file
  EXPECT_TRUE(renderedDocument({file, "--light-buffers", "on"}).render.lightBuffers);
}

TEST(LightBuffersTests, onAndOffRenderTheSameBytes) {
  // TC01: a small galaxy (three spot lights without a size: each gets a buffer) rendered with
  // and without light buffers: the same PNG, byte for byte
  const std::string dir = test::freshDirectory("lightBuffersImage");
  const auto render = [&](const std::string& setting) {
    const std::string out = dir + "/" + setting + ".png";
    const Outcome r = run({"render", "galaxy", "--width", "32", "--height", "18", "--silent",
                           "--light-buffers", setting, "-o", out});
    EXPECT_EQ(r.code, 0) << r.err;
    return test::readFile(out);
  };
  const std::string on = render("on");
  ASSERT_FALSE(on.empty());
  EXPECT_EQ(render("off"), on);
}

// ---------------------------------------------------------------------------------------------
// probe's JSON

/// probe's JSON for ray, with the tracer's colour for it (what `rt probe --ray` prints).
std::string probeJsonOf(const SceneDocument& doc, const Ray& ray, const RayTracer& tracer) {
  return probeJson(doc, ray, tracer.traceRay(ray));
}

/// A sphere of radius 2 centred on the ray (-1,0.5,-2) + t(0,0,1) at z = 5, and a plane z = 9
/// facing the ray's origin: every value of the answer is exact in binary.
SceneDocument probeScene() {
  SceneDocument doc = litDocument(LitScene{}, CameraSpec{});
  litScene(doc).ambientLight = AmbientLight(Color(100, 100, 100), 0.5);
  litScene(doc).add(Sphere(Point(-1, 0.5, 5), 2), Color(300, 20, 20));
  litScene(doc).add(Plane(Point(0, 0, 9), Vector(0, 0, -1)));
  doc.geometryNames = {{0, "ball \"A\""}};
  return doc;
}

TEST(ProbeTests, probeJsonListsSortedHitsAndTheUnclampedColor) {
  const SceneDocument doc = probeScene();
  const PhongTracer tracer(litScene(doc));
  // TC01: a ray that crosses the sphere through its centre, then the plane: three hits in order
  // of t, outward normals, names (null when none, escaped), and the colour = emission + Ia·kA =
  // (300+50, 20+50, 20+50), not clamped to 255
  EXPECT_EQ(probeJsonOf(doc, Ray(Point(-1, 0.5, -2), Vector(0, 0, 1)), tracer),
            "{\n"
            "  \"ray\": {\"origin\": [-1, 0.5, -2], \"direction\": [0, 0, 1]},\n"
            "  \"hits\": [\n"
            "    {\"t\": 5, \"point\": [-1, 0.5, 3], \"normal\": [0, 0, -1], \"geometry\": 0, "
            "\"name\": \"ball \\\"A\\\"\"},\n"
            "    {\"t\": 9, \"point\": [-1, 0.5, 7], \"normal\": [0, 0, 1], \"geometry\": 0, "
            "\"name\": \"ball \\\"A\\\"\"},\n"
            "    {\"t\": 11, \"point\": [-1, 0.5, 9], \"normal\": [0, 0, -1], \"geometry\": 1, "
            "\"name\": null}\n"
            "  ],\n"
            "  \"color\": [350, 70, 70]\n"
            "}\n");
  // TC02: a ray that misses everything: no hits, the background
  EXPECT_EQ(probeJsonOf(doc, Ray(Point(-1, 0.5, -2), Vector(0, 0, -1)), tracer),
            "{\n"
            "  \"ray\": {\"origin\": [-1, 0.5, -2], \"direction\": [0, 0, -1]},\n"
            "  \"hits\": [],\n"
            "  \"color\": [0, 0, 0]\n"
            "}\n");
  // TC03: a hit too long for one line of 100 columns is written one member per line, as a scene
  // file's long objects are; control characters in a name are escaped
  SceneDocument named = doc;
  named.geometryNames[0] = std::string(60, 'n') + "\t\x01";
  EXPECT_EQ(probeJsonOf(named, Ray(Point(-1, 0.5, -2), Vector(0, 0, 1)), tracer),
            "{\n"
            "  \"ray\": {\"origin\": [-1, 0.5, -2], \"direction\": [0, 0, 1]},\n"
            "  \"hits\": [\n"
            "    {\n"
            "      \"t\": 5,\n"
            "      \"point\": [-1, 0.5, 3],\n"
            "      \"normal\": [0, 0, -1],\n"
            "      \"geometry\": 0,\n"
            "      \"name\": \"" +
                std::string(60, 'n') +
                "\\t\\u0001\"\n"
                "    },\n"
                "    {\n"
                "      \"t\": 9,\n"
                "      \"point\": [-1, 0.5, 7],\n"
                "      \"normal\": [0, 0, 1],\n"
                "      \"geometry\": 0,\n"
                "      \"name\": \"" +
                std::string(60, 'n') +
                "\\t\\u0001\"\n"
                "    },\n"
                "    {\"t\": 11, \"point\": [-1, 0.5, 9], \"normal\": [0, 0, -1], \"geometry\": 1, "
                "\"name\": null}\n"
                "  ],\n"
                "  \"color\": [350, 70, 70]\n"
                "}\n");
  // TC04: numbers in their shortest round-trip form: the direction (1, 1, 0) normalised
  EXPECT_EQ(probeJsonOf(doc, Ray(Point(0, 0, -20), Vector(1, 1, 0)), tracer),
            "{\n"
            "  \"ray\": {\"origin\": [0, 0, -20], \"direction\": [0.7071067811865475, "
            "0.7071067811865475, 0]},\n"
            "  \"hits\": [],\n"
            "  \"color\": [0, 0, 0]\n"
            "}\n");
}

/// probeScene's plane z = 9 (shape 0) with two meshes in front of it and a shape added after
/// them: mesh 0 ("pot", flat), two triangles of the square [-4,4]^2 in z = 3, split along its
/// diagonal; mesh 1 (no name, smooth), one triangle in z = 6 with corners (-3,-1.5), (5,-1.5),
/// (-3,6.5) and normals (0,0,1), (1,0,0), (1,0,0); a sphere far away (shape 1). The primitives:
/// shapes 0 and 1, mesh 0's triangles 2 and 3, mesh 1's triangle 4.
SceneDocument probeMeshScene() {
  SceneDocument doc = litDocument(LitScene{}, CameraSpec{});
  LitScene& scene = litScene(doc);
  scene.ambientLight = AmbientLight(Color(100, 100, 100), 0.5);
  scene.add(Plane(Point(0, 0, 9), Vector(0, 0, -1)));
  scene.addMesh(
      std::make_shared<const TriangleMesh>(
          std::vector<Point>{Point(-4, -4, 3), Point(4, -4, 3), Point(4, 4, 3), Point(-4, 4, 3)},
          std::vector<TriangleMesh::Indices>{{0, 1, 2}, {0, 2, 3}}),
      scene.addAppearance(Color(300, 20, 20)));
  scene.addMesh(std::make_shared<const TriangleMesh>(
                    std::vector<Point>{Point(-3, -1.5, 6), Point(5, -1.5, 6), Point(-3, 6.5, 6)},
                    std::vector<TriangleMesh::Indices>{{0, 1, 2}},
                    std::vector<Double3>{{0, 0, 1}, {1, 0, 0}, {1, 0, 0}}),
                0);
  scene.add(Sphere(Point(100, 100, 100), 1));
  doc.geometryNames = {{0, "back"}};
  doc.part<MeshEntries>().entries.push_back(
      {.firstMesh = 0, .meshCount = 1, .name = "pot", .model = std::nullopt});
  return doc;
}

TEST(ProbeTests, probeJsonNamesMeshTriangles) {
  const SceneDocument doc = probeMeshScene();
  const PhongTracer tracer(litScene(doc));
  // ============ Equivalence Partitions Tests ==============
  // TC01: the ray (-1,0.5,-2) + t(0,0,1) meets mesh 0's triangle 1 (primitive 3) at t = 5, its
  // flat normal (0,0,1), named by its mesh; mesh 1's triangle 0 (primitive 4, no name) at t = 8,
  // where its barycentric coordinates are (0.25, 0.25): the normal 0.5·(0,0,1) + 0.5·(1,0,0),
  // normalised; then the plane, a shape, as before. The colour is mesh 0's look: (300,20,20) +
  // Ia·kA = (350,70,70). A mesh triangle's hit, longer than 100 columns, has a member per line
  EXPECT_EQ(probeJsonOf(doc, Ray(Point(-1, 0.5, -2), Vector(0, 0, 1)), tracer),
            "{\n"
            "  \"ray\": {\"origin\": [-1, 0.5, -2], \"direction\": [0, 0, 1]},\n"
            "  \"hits\": [\n"
            "    {\n"
            "      \"t\": 5,\n"
            "      \"point\": [-1, 0.5, 3],\n"
            "      \"normal\": [0, 0, 1],\n"
            "      \"geometry\": 3,\n"
            "      \"mesh\": 0,\n"
            "      \"triangle\": 1,\n"
            "      \"name\": \"pot\"\n"
            "    },\n"
            "    {\n"
            "      \"t\": 8,\n"
            "      \"point\": [-1, 0.5, 6],\n"
            "      \"normal\": [0.7071067811865475, 0, 0.7071067811865475],\n"
            "      \"geometry\": 4,\n"
            "      \"mesh\": 1,\n"
            "      \"triangle\": 0,\n"
            "      \"name\": null\n"
            "    },\n"
            "    {\"t\": 11, \"point\": [-1, 0.5, 9], \"normal\": [0, 0, -1], \"geometry\": 0, "
            "\"name\": \"back\"}\n"
            "  ],\n"
            "  \"color\": [350, 70, 70]\n"
            "}\n");
  // =============== Boundary Values Tests ==================
  // TC11: mesh 0's triangle 0 (below the diagonal), the first mesh triangle: primitive 2
  EXPECT_EQ(probeJsonOf(doc, Ray(Point(3, -3, 0), Vector(0, 0, 1)), tracer),
            "{\n"
            "  \"ray\": {\"origin\": [3, -3, 0], \"direction\": [0, 0, 1]},\n"
            "  \"hits\": [\n"
            "    {\n"
            "      \"t\": 3,\n"
            "      \"point\": [3, -3, 3],\n"
            "      \"normal\": [0, 0, 1],\n"
            "      \"geometry\": 2,\n"
            "      \"mesh\": 0,\n"
            "      \"triangle\": 0,\n"
            "      \"name\": \"pot\"\n"
            "    },\n"
            "    {\"t\": 9, \"point\": [3, -3, 9], \"normal\": [0, 0, -1], \"geometry\": 0, "
            "\"name\": \"back\"}\n"
            "  ],\n"
            "  \"color\": [350, 70, 70]\n"
            "}\n");
}

TEST(ProbeTests, probeOfTheTeapotNamesItsTriangles) {
  // TC01: rt probe of the teapot's middle pixel (a mesh alone, built in code): the ray enters
  // and leaves the pot's body, through triangles 214 (front) and 177 (back) of mesh 0, numbered
  // as the primitives are (no shapes before them)
  const Outcome r = run({"probe", "teapot", "--pixel", "400,400"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"geometry\": 214,\n      \"mesh\": 0,\n      \"triangle\": 214,"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"geometry\": 177,\n      \"mesh\": 0,\n      \"triangle\": 177,"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("\"mesh\": 1"), std::string::npos) << r.out;
}

// ---------------------------------------------------------------------------------------------
// scenes/ and the output checks

/// The scene files of dir that hand-written.txt lists (written by hand, not exported).
std::set<std::string> handWrittenScenes(const std::filesystem::path& dir) {
  std::set<std::string> names;
  std::ifstream in(dir / "hand-written.txt");
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') names.insert(line);
  return names;
}

TEST(ScenesFolderTests, everyBuiltinSceneIsExportedAndUpToDate) {
  namespace fs = std::filesystem;
  const fs::path dir = RT_SCENES_DIR;
  // TC01: scenes/NAME.json is the current export of every built-in scene
  for (const BuiltinScene& s : builtinScenes()) {
    const fs::path file = dir / (s.name + ".json");
    ASSERT_TRUE(fs::exists(file)) << file
                                  << " is missing; run: cmake --build BUILD --target export-scenes";
    EXPECT_EQ(test::readFile(file.string()), dumpScene(makeBuiltinScene(s, {})))
        << file << " is out of date; run: cmake --build BUILD --target export-scenes";
  }
  // TC02: scenes/ holds no scene file that is not a built-in scene, but those written by hand
  const std::set<std::string> handWritten = handWrittenScenes(dir);
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".json" && !handWritten.count(e.path().filename().string())) {
      EXPECT_NE(findBuiltinScene(e.path().stem().string()), nullptr)
          << e.path() << " is no built-in scene, nor listed in hand-written.txt; export-scenes "
          << "removes it";
    }
  }
}

TEST(ScenesFolderTests, everySceneWrittenByHandLoads) {
  namespace fs = std::filesystem;
  const fs::path dir = RT_SCENES_DIR;
  const std::set<std::string> handWritten = handWrittenScenes(dir);
  // TC01: the list names the shading scene (a model file's mesh, smooth and flat)
  EXPECT_EQ(handWritten.count("model-shading.json"), 1u);
  for (const std::string& name : handWritten) {
    SCOPED_TRACE(name);
    // TC02: every file listed exists, is no built-in scene's export, and loads without warnings
    // (its model files found beside it); without Assimp, a model file is refused saying so
    const fs::path file = dir / name;
    ASSERT_TRUE(fs::exists(file));
    EXPECT_EQ(findBuiltinScene(file.stem().string()), nullptr);
    if (modelFilesSupported()) {
      EXPECT_EQ(loadScene(file.string()).warnings, std::vector<std::string>{});
    } else {
      try {
        (void)loadScene(file.string());
        ADD_FAILURE() << "loaded without Assimp";
      } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("reading model files needs Assimp"), std::string::npos)
            << e.what();
      }
    }
  }
}

TEST(OutputTests, checkOutputWritable) {
  const std::string dir = test::freshDirectory("checkOutputWritable");
  const auto errorOf = [](const std::string& path,
                          const OutputKind& kind = PNG_IMAGE) -> std::string {
    try {
      checkOutputWritable(path, kind);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(no error)";
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: a new file in a writable directory; the check leaves nothing behind
  EXPECT_EQ(errorOf(dir + "/new.png"), "(no error)");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  // TC02: a file in a directory that does not exist
  EXPECT_EQ(errorOf(dir + "/missing/new.png"), "-o: cannot write '" + dir +
                                                   "/missing/new.png': the directory '" + dir +
                                                   "/missing' does not exist");
  // TC03: the path of a directory
  std::filesystem::create_directory(dir + "/sub.png");
  EXPECT_EQ(errorOf(dir + "/sub.png"), "-o: cannot write '" + dir + "/sub.png': it is a directory");
  // TC04: a "directory" that is a file
  { std::ofstream(dir + "/file") << "x"; }
  EXPECT_EQ(errorOf(dir + "/file/new.png"),
            "-o: cannot write '" + dir + "/file/new.png': '" + dir + "/file' is not a directory");
  // TC05: an existing directory whose name lacks the ending: it is a directory that is wrong
  // (once "-o: the image is written as PNG, so its name must end in .png")
  EXPECT_EQ(errorOf(dir), "-o: cannot write '" + dir + "': it is a directory");
  EXPECT_EQ(errorOf(dir, SCENE_FILE), "-o: cannot write '" + dir + "': it is a directory");
  // TC06: a file name without the ending, for an image and for a scene file
  EXPECT_EQ(
      errorOf(dir + "/x.jpg"),
      "-o: the image is written as PNG, so its name must end in .png; got '" + dir + "/x.jpg'");
  EXPECT_EQ(errorOf(dir + "/x.png", SCENE_FILE),
            "-o: a scene file's name must end in .json; got '" + dir + "/x.png'");
  // =============== Boundary Values Tests ==================
  // TC11: a path that ends with a separator and names no existing directory names no file
  EXPECT_EQ(errorOf(dir + "/none/"), "-o: cannot write '" + dir + "/none/': it names no file");
  // TC12: an existing directory written with a final separator is a directory
  EXPECT_EQ(errorOf(dir + "/"), "-o: cannot write '" + dir + "/': it is a directory");
  // TC13: a bare file name is in the current directory (which the tests can write to)
  EXPECT_EQ(errorOf("rt-check-output-test.png"), "(no error)");
  // TC14: the empty path
  EXPECT_EQ(errorOf(""), "-o: cannot write '': it names no file");
}

TEST(OutputTests, sameFile) {
  namespace fs = std::filesystem;
  // Relative, so that "x" and "./x" are names in the current directory.
  const std::string dir = test::freshTestDirectory("sameFile");
  const std::string a = test::writeText(dir + "/a.png", "one image");
  const std::string copy = test::writeText(dir + "/copy.png", "one image");
  fs::create_directory(dir + "/sub");
  // ============ Equivalence Partitions Tests ==============
  // TC01: one existing file under two spellings, and under its absolute path
  EXPECT_TRUE(sameFile(a, "./" + dir + "/sub/../a.png"));
  EXPECT_TRUE(sameFile(fs::absolute(a).string(), a));
  // TC02: a hard link and a symbolic link to it, and the two links to each other
  fs::create_hard_link(a, dir + "/hard.png");
  fs::create_symlink("a.png", dir + "/soft.png");
  EXPECT_TRUE(sameFile(a, dir + "/hard.png"));
  EXPECT_TRUE(sameFile(dir + "/soft.png", a));
  EXPECT_TRUE(sameFile(dir + "/hard.png", dir + "/soft.png"));
  // TC03: two files with the same bytes are two files
  EXPECT_FALSE(sameFile(a, copy));
  // TC04: a file not made yet, named in three ways, and through a link to its folder
  fs::create_directory_symlink(fs::absolute(dir + "/sub"), dir + "/to-sub");
  EXPECT_TRUE(sameFile(dir + "/new.png", "./" + dir + "/new.png"));
  EXPECT_TRUE(sameFile(dir + "/sub/../new.png", dir + "/new.png"));
  EXPECT_TRUE(sameFile(dir + "/to-sub/new.png", dir + "/sub/new.png"));
  // TC05: two new files, and a new file beside an existing one
  EXPECT_FALSE(sameFile(dir + "/new.png", dir + "/other.png"));
  EXPECT_FALSE(sameFile(dir + "/new.png", a));
  EXPECT_FALSE(sameFile(a, dir + "/sub/a.png"));
  // TC06: a symbolic link to a file not made yet is that file, as writing through it makes it
  // (once the names were compared, and a link and its target were two files until the target
  // existed): a chain of links, a relative target from the link's folder, an absolute target
  fs::create_directory(dir + "/links");
  fs::create_symlink("t.md", dir + "/links/t_link.json");
  fs::create_symlink("t_link.json", dir + "/links/chain.csv");
  fs::create_symlink("../new.png", dir + "/links/up.png");
  fs::create_symlink(fs::absolute(dir + "/new.png"), dir + "/links/absolute.png");
  EXPECT_TRUE(sameFile(dir + "/links/t.md", dir + "/links/t_link.json"));
  EXPECT_TRUE(sameFile(dir + "/links/t_link.json", dir + "/links/t.md"));
  EXPECT_TRUE(sameFile(dir + "/links/chain.csv", dir + "/links/t.md"));
  EXPECT_TRUE(sameFile(dir + "/links/chain.csv", dir + "/links/t_link.json"));
  EXPECT_TRUE(sameFile(dir + "/links/up.png", dir + "/new.png"));
  EXPECT_TRUE(sameFile(dir + "/links/absolute.png", "./" + dir + "/new.png"));
  EXPECT_TRUE(sameFile(dir + "/links/up.png", dir + "/links/absolute.png"));
  // TC07: a link to another new file, and a link whose target is relative to its own folder,
  // not to the current directory
  EXPECT_FALSE(sameFile(dir + "/links/t_link.json", dir + "/links/other.md"));
  EXPECT_FALSE(sameFile(dir + "/links/t_link.json", "t.md"));
  EXPECT_FALSE(sameFile(dir + "/links/up.png", dir + "/links/new.png"));
  // =============== Boundary Values Tests ==================
  // TC11: a bare name in the current directory and the same with its path
  EXPECT_TRUE(sameFile("rt-same-file-test.png", fs::absolute("rt-same-file-test.png").string()));
  // TC12: the same name, existing and not
  EXPECT_TRUE(sameFile(a, a));
  EXPECT_TRUE(sameFile(dir + "/new.png", dir + "/new.png"));
  // TC13: a loop of links names no file it reaches, and the answer comes (no endless chase)
  fs::create_symlink("loop2.md", dir + "/links/loop1.md");
  fs::create_symlink("loop1.md", dir + "/links/loop2.md");
  EXPECT_FALSE(sameFile(dir + "/links/loop1.md", dir + "/links/t.md"));
  EXPECT_TRUE(sameFile(dir + "/links/loop1.md", dir + "/links/loop1.md"));
  // The checks made no file
  EXPECT_FALSE(fs::exists(dir + "/new.png"));
  EXPECT_FALSE(fs::exists(dir + "/links/t.md"));
  EXPECT_TRUE(fs::is_empty(dir + "/sub"));
}

TEST(OutputTests, aCommandNeverWritesOverAFileItsSceneReads) {
  namespace fs = std::filesystem;
  const std::string dir = test::freshTestDirectory("outputOverInput");
  const std::string scene =
      test::writeText(dir + "/s.json", test::readFile(RT_SCENES_DIR "/two-color.json"));
  const std::string original = test::readFile(scene);
  fs::create_symlink("s.json", dir + "/to-scene.png");
  fs::create_directory(dir + "/frames");
  fs::create_symlink("../s.json", dir + "/frames/frame-0001.png");
  const auto refusal = [&](const std::string& what, const std::string& output,
                           const std::string& written) {
    return "rt: " + what + ": '" + output + "' is SCENE ('" + scene + "'): " + written +
           " would overwrite the scene file it reads; give another file\n";
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: rt render -o through a link to the scene file (once the PNG replaced the scene)
  Outcome r = run({"render", scene, "--width", "8", "-o", dir + "/to-scene.png", "--silent"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, refusal("-o", dir + "/to-scene.png", "the image"));
  // TC02: rt export of a scene file over itself (once rewritten in place)
  r = run({"export", scene, "-o", scene});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, refusal("-o", scene, "the exported scene"));
  EXPECT_EQ(r.out, "");
  // TC03: rt animate into a folder where a frame's name is a link to the scene file
  r = run({"animate", scene, "--orbit", "30", "--frames", "2", "--width", "8", "-o",
           dir + "/frames", "--silent"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, refusal("-o", dir + "/frames/frame-0001.png", "frame 1"));
  // TC04: a model file, which Assimp recognises by its contents whatever its name: written over
  // by rt render -o and by rt animate --video by its own name (checked before ffmpeg is looked
  // for)
  if (modelFilesSupported()) {
    const std::string obj = "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n";
    test::writeText(dir + "/model.png", obj);
    test::writeText(dir + "/clip.mp4", obj);
    const std::string meshes =
        test::writeText(dir + "/meshes.json",
                        R"({"camera": {"location": [0, 0, 0], "to": [0, 0, -1], "up": [0, 1, 0],
                       "vpDistance": 1, "vpSize": [2, 2], "resolution": [8, 8]},
           "geometries": [{"type": "mesh", "file": "model.png"},
                          {"type": "mesh", "file": "clip.mp4"}]})");
    r = run({"render", meshes, "-o", dir + "/model.png", "--silent"});
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "rt: -o: '" + dir + "/model.png' is a model file of SCENE ('" + dir +
                         "/model.png'): the image would overwrite a file the scene reads; give "
                         "another file\n");
    r = run({"animate", meshes, "--orbit", "30", "--frames", "2", "-o", dir + "/f", "--video",
             dir + "/clip.mp4", "--silent"});
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "rt: --video: '" + dir + "/clip.mp4' is a model file of SCENE ('" + dir +
                         "/clip.mp4'): the video would overwrite a file the scene reads; give "
                         "another file\n");
    EXPECT_EQ(test::readFile(dir + "/model.png"), obj);
    EXPECT_EQ(test::readFile(dir + "/clip.mp4"), obj);
    EXPECT_FALSE(fs::exists(dir + "/f"));
  }
  // TC05: nothing written: the scene as it was, the frames' folder holding its link alone
  EXPECT_EQ(test::readFile(scene), original);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir + "/frames"), fs::directory_iterator()), 1);
  // =============== Boundary Values Tests ==================
  // TC11: a file beside the scene, and the scene exported to another file
  r = run({"render", scene, "--width", "8", "-o", dir + "/s.png", "--silent"});
  EXPECT_EQ(r.code, 0) << r.err;
  r = run({"export", scene, "-o", dir + "/again.json"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(test::readFile(scene), original);
}

}  // namespace
}  // namespace rt::cli
