// `rt` in every course cut (label cli; built whenever rt is): the program of a repository cut
// after any stage from stage 4 on lists the scenes of the stages present, offers their tracers,
// renders, and refuses a scene-file key or a tracer of a stage the cut does not have, naming it.
// Every test holds in every cut: it asks the build which stages it has (the tracers the scene
// format knows) and expects the answer of that build.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "InProcess.h"
#include "camera/ImageWriter.h"
#include "cli/BuiltinScenes.h"
#include "cli/Commands.h"
#include "cli/Tracers.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {
namespace {

namespace fs = std::filesystem;

using test::hasTracer;
using test::Outcome;
using test::run;
using test::writeText;

/// A fresh directory for one test of this file: cli-test-output/cut-NAME.
std::string freshDirectory(const std::string& name) {
  return test::freshTestDirectory("cut-" + name);
}

TEST(CutTests, theTracersAreThoseOfTheStagesPresent) {
  // TC01: rt's tracers are the scene format's, in the same order, and begin with stage 4's
  // (its debugging views, then the ambient tracer)
  std::vector<std::string_view> ours;
  for (const TracerKind& t : tracerKinds()) ours.push_back(t.name);
  EXPECT_EQ(knownTracers(), ours);
  ASSERT_GE(ours.size(), 4u);
  EXPECT_EQ((std::vector<std::string_view>{"rays", "normals", "hits", "ambient"}),
            std::vector<std::string_view>(ours.begin(), ours.begin() + 4));
  // TC02: the default tracer (an empty name) is the highest stage's
  ASSERT_NE(nullptr, tracerNamed(""));
  EXPECT_EQ(ours.back(), tracerNamed("")->name);
  // TC03: a tracer of a stage the cut lacks is refused naming that stage; one it has is
  // accepted (the whole course has every tracer)
  const Outcome beams = run({"render", "two-color", "--tracer", "beams", "--width", "4", "-o",
                             freshDirectory("beams") + "/x.png", "--silent"});
  if (hasTracer("beams")) {
    EXPECT_EQ(0, beams.code) << beams.err;
  } else {
    EXPECT_EQ(2, beams.code);
    EXPECT_EQ(
        "rt: --tracer: the tracer 'beams' needs mini1_glossy, which this build does not include "
        "(a course cut before it)\n",
        beams.err);
  }
}

TEST(CutTests, listShowsTheScenesOfTheStagesPresent) {
  const Outcome r = run({"list"});
  ASSERT_EQ(0, r.code) << r.err;
  // TC01: stage 4's scene is in every cut, and every scene listed is a built-in scene of a
  // stage whose tracer this build has
  EXPECT_EQ(0u, r.out.rfind("two-color  ", 0));
  std::set<std::string> tracers;
  for (const TracerKind& t : tracerKinds()) tracers.insert(t.name);
  for (const BuiltinScene& s : builtinScenes()) {
    EXPECT_NE(std::string::npos, r.out.find(s.name + "  ")) << s.name;
    EXPECT_EQ(1u, tracers.count(s.tracer)) << s.name << " needs " << s.tracer;
  }
  // TC02: the galaxy only with mini project 1
  EXPECT_EQ(hasTracer("beams"), r.out.find("galaxy  ") != std::string::npos);
}

TEST(CutTests, rendersAndExportsInEveryCut) {
  const std::string dir = freshDirectory("render");
  // TC01: the base render test with the build's default tracer: the sphere's centre is the
  // course's pink (the ambient light; from stage 5 on the shapes are black and matte, so every
  // tracer sees the same), a corner the green background
  const Outcome r = run({"render", "two-color", "--width", "20", "-o", dir + "/a.png", "--silent"});
  ASSERT_EQ(0, r.code) << r.err;
  const Rgb8Image a = readPng(dir + "/a.png");
  EXPECT_EQ(20, a.width);
  EXPECT_EQ(20, a.height);
  EXPECT_EQ((std::array<unsigned char, 3>{255, 191, 191}), a.at(10, 10));
  EXPECT_EQ((std::array<unsigned char, 3>{75, 127, 90}), a.at(19, 0));
  // TC02: its export renders to the same bytes
  const Outcome e = run({"export", "two-color", "-o", dir + "/two-color.json"});
  ASSERT_EQ(0, e.code) << e.err;
  const Outcome b =
      run({"render", dir + "/two-color.json", "--width", "20", "-o", dir + "/b.png", "--silent"});
  ASSERT_EQ(0, b.code) << b.err;
  std::ifstream fa(dir + "/a.png", std::ios::binary), fb(dir + "/b.png", std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(fa), {}),
            std::string(std::istreambuf_iterator<char>(fb), {}));
}

TEST(CutTests, gridLinesArePaintedOnTheRenderedImage) {
  const std::string dir = freshDirectory("gridLines");
  using Rgb = std::array<unsigned char, 3>;
  const Rgb yellow{255, 255, 0}, blue{0, 0, 255}, black{0, 0, 0};
  // TC01: --grid-lines 7: the pixels of every seventh column and row (0, 7, 14) are the course's
  // yellow, every other pixel is the image without lines
  const std::vector<std::string> twoColor{"render", "two-color", "--width", "20", "--silent"};
  std::vector<std::string> plain = twoColor, lined = twoColor;
  plain.insert(plain.end(), {"-o", dir + "/plain.png"});
  lined.insert(lined.end(), {"-o", dir + "/lined.png", "--grid-lines", "7"});
  ASSERT_EQ(0, run(plain).code);
  const Outcome r = run(lined);
  ASSERT_EQ(0, r.code) << r.err;
  const Rgb8Image a = readPng(dir + "/plain.png"), b = readPng(dir + "/lined.png");
  ASSERT_EQ(20, b.width);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x)
      EXPECT_EQ(x % 7 == 0 || y % 7 == 0 ? yellow : a.at(x, y), b.at(x, y)) << x << "," << y;
  // TC02: a scene file's render.gridLines and render.gridColor: blue lines every 5 pixels on
  // the black background of a scene without shapes
  const std::string scene = writeText(dir + "/lines.json", R"({
  "camera": {"location": [0, 0, 10], "target": [0, 0, 0], "vpDistance": 1, "vpSize": [1, 1],
             "resolution": [12, 12]},
  "render": {"gridLines": 5, "gridColor": [0, 0, 255]}
})");
  ASSERT_EQ(0, run({"render", scene, "-o", dir + "/blue.png", "--silent"}).code);
  const Rgb8Image lines = readPng(dir + "/blue.png");
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x)
      EXPECT_EQ(x % 5 == 0 || y % 5 == 0 ? blue : black, lines.at(x, y)) << x << "," << y;
  // TC11: --grid-lines 0 takes the file's lines away: every pixel the background
  ASSERT_EQ(0,
            run({"render", scene, "-o", dir + "/none.png", "--grid-lines", "0", "--silent"}).code);
  const Rgb8Image none = readPng(dir + "/none.png");
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) EXPECT_EQ(black, none.at(x, y)) << x << "," << y;
  // TC12: --grid-lines 1: every pixel is on a line
  ASSERT_EQ(0,
            run({"render", scene, "-o", dir + "/all.png", "--grid-lines", "1", "--silent"}).code);
  const Rgb8Image all = readPng(dir + "/all.png");
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) EXPECT_EQ(blue, all.at(x, y)) << x << "," << y;
  // TC13: a negative interval is refused before any ray, naming the option
  const Outcome bad = run({"render", scene, "-o", dir + "/bad.png", "--grid-lines", "-1"});
  EXPECT_EQ(2, bad.code);
  EXPECT_EQ("rt: --grid-lines: expected an integer from 0 to 32768, got '-1'\n", bad.err);
  EXPECT_FALSE(fs::exists(dir + "/bad.png"));
}

TEST(CutTests, aKeyOfAMissingStageIsRefusedNamingIt) {
  const std::string dir = freshDirectory("keys");
  const std::string camera =
      R"("camera": {"location": [0, 0, 10], "target": [0, 0, 0], "vpDistance": 1,
                 "vpSize": [1, 1], "resolution": [4, 4]})";
  // TC01: lights (stage 5)
  writeText(dir + "/lights.json", "{" + camera + ",\n \"lights\": []}");
  const Outcome lights = run({"render", dir + "/lights.json", "-o", dir + "/l.png", "--silent"});
  if (hasTracer("phong")) {
    EXPECT_EQ(0, lights.code) << lights.err;
  } else {
    EXPECT_EQ(2, lights.code);
    EXPECT_EQ("rt: " + dir + "/lights.json:3:2: lights: the key 'lights' needs stage05_lighting, " +
                  "which this build does not include (a course cut before it)\n",
              lights.err);
  }
  // TC02: render.maxLevel (stage 7)
  writeText(dir + "/level.json", "{" + camera + ",\n \"render\": {\"maxLevel\": 3}}");
  const Outcome level = run({"render", dir + "/level.json", "-o", dir + "/m.png", "--silent"});
  if (hasTracer("whitted")) {
    EXPECT_EQ(0, level.code) << level.err;
  } else {
    EXPECT_EQ(2, level.code);
    EXPECT_NE(std::string::npos,
              level.err.find("render.maxLevel: the key 'maxLevel' needs stage07_reflections"))
        << level.err;
  }
  // TC03: a file without render.tracer renders in every cut, with the build's highest tracer
  writeText(dir + "/plain.json", "{" + camera + "}");
  const Outcome plain = run({"render", dir + "/plain.json", "-o", dir + "/p.png", "--quiet"});
  EXPECT_EQ(0, plain.code) << plain.err;
  ASSERT_NE(nullptr, tracerNamed(""));
  EXPECT_NE(std::string::npos, plain.err.find(", tracer " + tracerNamed("")->name + ","))
      << plain.err;
  // TC04: a mesh geometry (mini 2: its triangles are the accelerations' primitives)
  writeText(dir + "/mesh.json",
            "{" + camera +
                ",\n \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], "
                "[0, 1, 0]], \"triangles\": [[0, 1, 2]]}]}");
  const Outcome mesh = run({"render", dir + "/mesh.json", "-o", dir + "/mesh.png", "--silent"});
  if (cliRegistry().makeAccelerator) {
    EXPECT_EQ(0, mesh.code) << mesh.err;
  } else {
    EXPECT_EQ(2, mesh.code);
    EXPECT_EQ("rt: " + dir + "/mesh.json:3:26: geometries[0].type: the geometry type 'mesh' " +
                  "needs mini2_bvh, which this build does not include (a course cut before it)\n",
              mesh.err);
  }
  // TC11: a key no stage has is an unknown key in every cut
  writeText(dir + "/typo.json", "{" + camera + ",\n \"backgroud\": [0, 0, 0]}");
  const Outcome typo = run({"render", dir + "/typo.json", "-o", dir + "/t.png", "--silent"});
  EXPECT_EQ(2, typo.code);
  EXPECT_NE(std::string::npos, typo.err.find("backgroud: unknown key; did you mean 'background'?"))
      << typo.err;
}

TEST(CutTests, benchIsMiniProject2sCommand) {
  if (cliRegistry().makeAccelerator) {
    // TC01: with mini project 2 (the accelerations it adds), rt has the bench
    const Outcome r = run({"bench", "--help"});
    EXPECT_EQ(0, r.code) << r.err;
    EXPECT_TRUE(r.out.starts_with("Usage: rt bench [SCENE] [OPTIONS]\n")) << r.out;
  } else {
    // TC02: in a cut before it, no such command (with --help, rt's own help would answer)
    const Outcome r = run({"bench"});
    EXPECT_EQ(2, r.code);
    EXPECT_EQ("rt: unknown command 'bench' (see rt --help)\n", r.err);
  }
}

}  // namespace
}  // namespace rt::cli
