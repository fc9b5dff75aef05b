// What rt says about a scene that renders, but not as its author expects (label cli; in every
// course cut from stage 4 on): the scene file's warnings (stage 7: glass faces wound both ways),
// the ambient tracer on a scene without ambient light, and -o naming a directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "InProcess.h"
#include "cli/Commands.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {
namespace {

namespace fs = std::filesystem;

using test::hasTracer;
using test::Outcome;
using test::run;
using test::writeText;

/// A sphere seen by a 4 x 4 camera, with the ambient light and render object given.
std::string sphereScene(const std::string& ambient, const std::string& render = "{}") {
  return "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], \"vpDistance\": 10,\n"
         "            \"vpSize\": [4, 4], \"resolution\": [4, 4]},\n"
         " \"ambient\": " +
         ambient +
         ",\n"
         " \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}],\n"
         " \"render\": " +
         render + "}\n";
}

/// The warning about a zero ambient light, with where the tracer was chosen: in the whole
/// course, and in a cut after stage 4 (no other tracer to offer).
std::string ambientWarning(const std::string& chosenBy) {
  const std::string head = "rt: warning: the ambient tracer (" + chosenBy +
                           ") shows the ambient light wherever a ray hits a shape, and this "
                           "scene's ambient light is zero (ambient.color x ambient.kA): every "
                           "shape will be black; give the scene an ambient light";
  if (hasTracer("beams"))
    return head +
           ", or render with a tracer that shows its lights (phong, shadow, whitted, "
           "beams)\n";
  if (!hasTracer("phong")) return head + "\n";
  return head;  // a cut between: the tracers it has follow
}

/// A render that went through without a warning: exit code 0, no "rt: warning", the final
/// line naming the image, and the image written.
void expectRenderedWithoutWarning(const Outcome& r, const std::string& image) {
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("rt: warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rt: wrote " + image + ":"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_regular_file(image)) << image;
}

TEST(SceneWarningTests, ambientTracerWithoutAmbientLight) {
  const std::string dir = test::freshTestDirectory("warnings-ambient");
  const std::string dark = writeText(dir + "/dark.json", sphereScene("{}"));
  // TC01: --tracer ambient on a scene without ambient light: the warning first, then the render
  Outcome r = run({"render", dark, "--tracer", "ambient", "-o", dir + "/a.png"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.rfind(ambientWarning("--tracer ambient"), 0), 0u) << r.err;
  EXPECT_NE(r.err.find("\nrt: wrote " + dir + "/a.png"), std::string::npos) << r.err;
  // TC02: the ambient tracer chosen by the file
  const std::string byFile =
      writeText(dir + "/by-file.json", sphereScene("{}", R"({"tracer": "ambient"})"));
  r = run({"render", byFile, "-o", dir + "/b.png"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.rfind(ambientWarning("the scene's render.tracer"), 0), 0u) << r.err;
  // TC03: a zero kA is a zero ambient light too
  const std::string zeroKa =
      writeText(dir + "/zero-ka.json", sphereScene(R"({"color": [255, 255, 255], "kA": 0})"));
  r = run({"render", zeroKa, "--tracer", "ambient", "-o", dir + "/c.png"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.rfind(ambientWarning("--tracer ambient"), 0), 0u) << r.err;
  // TC04: an ambient light: no warning
  const std::string lit =
      writeText(dir + "/lit.json", sphereScene(R"({"color": [255, 255, 255], "kA": 0.1})"));
  r = run({"render", lit, "--tracer", "ambient", "-o", dir + "/d.png"});
  expectRenderedWithoutWarning(r, dir + "/d.png");
  // TC05: --quiet keeps the warning (and the final line); --silent: nothing but errors
  r = run({"render", dark, "--tracer", "ambient", "-o", dir + "/e.png", "--quiet"});
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.err.rfind(ambientWarning("--tracer ambient"), 0), 0u) << r.err;
  r = run({"render", dark, "--tracer", "ambient", "-o", dir + "/e.png", "--silent"});
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.err, "");
  // TC06: probe shows the colour itself and does not warn
  r = run({"probe", dark, "--tracer", "ambient", "--pixel", "2,2"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  // TC07: another tracer (from stage 5 on) shows the lights: no warning
  if (hasTracer("phong")) {
    r = run({"render", dark, "--tracer", "phong", "-o", dir + "/f.png"});
    expectRenderedWithoutWarning(r, dir + "/f.png");
  }
  // TC11: a scene without shapes shows only its background: no warning
  const std::string empty =
      writeText(dir + "/empty.json",
                R"({"camera": {"location": [0, 0, 10], "target": [0, 0, 0], "vpDistance": 10,
          "vpSize": [4, 4], "resolution": [4, 4]}})");
  r = run({"render", empty, "--tracer", "ambient", "-o", dir + "/g.png"});
  expectRenderedWithoutWarning(r, dir + "/g.png");
}

TEST(SceneWarningTests, glassFacesWoundBothWays) {
  if (!hasTracer("phong")) GTEST_SKIP() << "a cut before stage05_lighting has no materials";
  const std::string dir = test::freshTestDirectory("warnings-winding");
  // Two glass triangles sharing the edge (1,0,0)-(0,1,0) in the same direction.
  const std::string scene = writeText(
      dir + "/sheet.json",
      "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], \"vpDistance\": 10,\n"
      "            \"vpSize\": [4, 4], \"resolution\": [4, 4]},\n"
      " \"ambient\": {\"color\": [255, 255, 255], \"kA\": 0.1},\n"
      " \"materials\": {\"glass\": {\"kT\": 0.9, \"ior\": 1.5}},\n"
      " \"geometries\": [\n"
      "  {\"type\": \"triangle\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
      "\"material\": \"glass\", \"name\": \"lower\"},\n"
      "  {\"type\": \"triangle\", \"vertices\": [[0, 1, 0], [1, 1, 0], [1, 0, 0]], "
      "\"material\": \"glass\", \"name\": \"upper\"}]}\n");
  const std::string warning =
      "rt: warning: " + scene +
      ":7:3: geometries[1]: mixed winding in a glass surface of 2 faces (material 'glass', ior "
      "1.5): geometries[1] ('upper') is wound against geometries[0] ('lower') (an edge shared by "
      "two faces runs the same way in both); refraction needs outward normals: reverse the order "
      "of the vertices of one side\n";
  // TC01: render prints it first (from stage 7 on: the check is refraction's)
  Outcome r = run({"render", scene, "-o", dir + "/s.png"});
  EXPECT_EQ(r.code, 0) << r.err;
  if (hasTracer("whitted"))
    EXPECT_EQ(r.err.rfind(warning, 0), 0u) << r.err;
  else
    EXPECT_EQ(r.err.find("rt: warning"), std::string::npos) << r.err;
  // TC02: so does probe, on stderr; its JSON alone is on stdout
  r = run({"probe", scene, "--pixel", "2,2"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, hasTracer("whitted") ? warning : "");
  EXPECT_EQ(r.out.rfind("{", 0), 0u) << r.out;
}

TEST(SceneWarningTests, outputNamingADirectory) {
  const std::string dir = test::freshTestDirectory("warnings-directory");
  fs::create_directories(dir + "/images");
  fs::create_directories(dir + "/shot.png");
  // TC01: -o naming an existing directory says so (not that its name lacks .png), renders
  // nothing and writes nothing into it
  Outcome r = run({"render", "two-color", "-o", dir + "/images"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: -o: cannot write '" + dir + "/images': it is a directory\n");
  // TC02: ... also when the directory's name ends in .png
  r = run({"render", "two-color", "-o", dir + "/shot.png"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: -o: cannot write '" + dir + "/shot.png': it is a directory\n");
  EXPECT_TRUE(fs::is_empty(dir + "/images"));
  EXPECT_TRUE(fs::is_empty(dir + "/shot.png"));
}

}  // namespace
}  // namespace rt::cli
