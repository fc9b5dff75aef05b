// Tests that run the built `rt` executable as a user would: exit codes, files written (or not),
// Ctrl-C, and the byte-for-byte equality of a built-in scene and its export.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "RtProcess.h"
#include "TestFiles.h"
#include "camera/Image.h"
#include "camera/ImageWriter.h"
#include "cli/BuiltinScenes.h"
#include "lighting/CourseScenes.h"
#include "reflections/CourseScenes.h"
#include "scenefile/ModelFile.h"
#include "shadows/CourseScenes.h"

namespace rt::cli {
namespace {

using test::freshDirectory;
using test::readFile;
using test::runRt;
using test::writeText;

// ---------------------------------------------------------------------------------------------
// standard output

TEST(OutputProcessTests, aFullStandardOutputFailsTheCommand) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  // TC01: rt export's scene, rt list and rt probe printed into a full device: exit 1, said so
  for (const std::vector<std::string>& command : {std::vector<std::string>{"export", "two-color"},
                                                  {"list"},
                                                  {"probe", "two-color", "--pixel", "1,1"}}) {
    std::vector<std::string> argv{"/bin/sh", "-c", "exec \"$0\" \"$@\" >/dev/full", RT_EXE};
    argv.insert(argv.end(), command.begin(), command.end());
    const test::RtResult r = test::runProgram(argv);
    EXPECT_EQ(r.exitCode, 1) << command.front() << ": " << r.err;
    EXPECT_EQ(r.err, "rt: cannot write standard output: what was printed is incomplete\n")
        << command.front();
  }
  // TC02: a usage error keeps its own exit code, 2
  const test::RtResult bad =
      test::runProgram({"/bin/sh", "-c", "exec \"$0\" export no-such-scene >/dev/full", RT_EXE});
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
}

TEST(OutputProcessTests, compareThatCannotPrintItsAnswerSaysNeitherSameNorDifferent) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  const std::string dir = freshDirectory("compareFullOutput");
  Image image(4, 4);
  PngImageWriter().write(image, dir + "/a.png");
  image.setPixel(1, 2, Color(9, 0, 0));
  PngImageWriter().write(image, dir + "/b.png");
  const auto compare = [&](const std::string& a, const std::string& b, bool full) {
    return test::runProgram({"/bin/sh", "-c",
                             full ? "exec \"$0\" \"$@\" >/dev/full" : "exec \"$0\" \"$@\"", RT_EXE,
                             "compare", a, b});
  };
  const std::string lost = "rt: cannot write standard output: what was printed is incomplete\n";
  // TC01: the same images and different ones, printed into a full device: exit 2, rt compare's
  // code for an answer it could not give (once 1, which says that the images differ)
  for (const std::string& b : {dir + "/a.png", dir + "/b.png"}) {
    const test::RtResult r = compare(dir + "/a.png", b, true);
    EXPECT_EQ(r.exitCode, 2) << b;
    EXPECT_EQ(r.err, lost) << b;
  }
  // TC02: an image it cannot read, which prints nothing: its message and its code, 2
  const test::RtResult missing = compare(dir + "/a.png", dir + "/none.png", true);
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_EQ(missing.err, "rt: B: cannot read '" + dir + "/none.png': no such file\n");
  // TC03: printed where it can be, the answers stay 0 and 1
  EXPECT_EQ(compare(dir + "/a.png", dir + "/a.png", false).exitCode, 0);
  EXPECT_EQ(compare(dir + "/a.png", dir + "/b.png", false).exitCode, 1);
}

// ---------------------------------------------------------------------------------------------
// render

TEST(RenderProcessTests, widthAndHeightOverrideTheScenesResolution) {
  const std::string dir = freshDirectory("renderOverride");
  // TC01: both overridden: the PNG has that size, and the course's two-colour picture: the
  // sphere (pink) in the middle, the empty up-right quadrant (green background) in the corner
  test::RtResult r = runRt(
      {"render", "two-color", "-o", dir + "/a.png", "--width", "40", "--height", "30", "--silent"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  const Rgb8Image a = readPng(dir + "/a.png");
  EXPECT_EQ(a.width, 40);
  EXPECT_EQ(a.height, 30);
  EXPECT_EQ(a.at(20, 15), (std::array<unsigned char, 3>{255, 191, 191}));
  EXPECT_EQ(a.at(39, 0), (std::array<unsigned char, 3>{75, 127, 90}));
  // TC02: only the width: the height keeps the scene's aspect ratio (1000 x 1000: square), so
  // nothing is squashed (once it stayed 1000, giving an 8 x 1000 image)
  r = runRt({"render", "two-color", "-o", dir + "/b.png", "--width", "8", "--silent"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Rgb8Image b = readPng(dir + "/b.png");
  EXPECT_EQ(b.width, 8);
  EXPECT_EQ(b.height, 8);
  // TC03: integers in any JSON number form, as in a scene file (once "--width 4e1" was refused)
  r = runRt({"render", "two-color", "-o", dir + "/e.png", "--width", "4e1", "--height", "30.0",
             "--silent"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Rgb8Image e = readPng(dir + "/e.png");
  EXPECT_EQ(e.width, 40);
  EXPECT_EQ(e.height, 30);
  // TC11: the smallest image, 1x1
  r = runRt(
      {"render", "two-color", "-o", dir + "/c.png", "--width", "1", "--height", "1", "--silent"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readPng(dir + "/c.png").width, 1);
}

TEST(RenderProcessTests, defaultOutputIsSceneDotPngInTheCurrentDirectory) {
  const std::string dir = freshDirectory("renderDefaultOutput");
  // TC01: without -o, NAME.png appears in the working directory
  const test::RtResult r =
      runRt({"render", "two-color", "--width", "4", "--height", "3", "--silent"},
            {.cwd = dir, .asUnprivileged = false, .path = {}});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readPng(dir + "/two-color.png").width, 4);
}

TEST(RenderProcessTests, progressAndTimingGoToStderr) {
  const std::string dir = freshDirectory("renderProgress");
  const std::string out = dir + "/p.png";
  // TC01: stderr is not a terminal: a header, one line per 10% in order (with the rays per second
  // and the time left once there are any), then the wall time, the threads when more than one,
  // and the rate of primary rays; stdout stays empty
  const test::RtResult r =
      runRt({"render", "two-color", "-o", out, "--width", "20", "--height", "10"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const std::string header = "rt: rendering two-color (20x10, tracer ambient) to " + out + "\n";
  ASSERT_TRUE(r.err.starts_with(header)) << r.err;
  std::string steps;
  for (int p = 10; p <= 100; p += 10)
    steps += "rt: rendering " + std::to_string(p) + "%( \\([0-9]+ rays/s(, [0-9.]+ s left)?\\))?\n";
  EXPECT_TRUE(std::regex_match(
      r.err.substr(header.size()),
      std::regex(steps + "rt: wrote " + out +
                 ": 20x10, tracer ambient, 200 primary rays in [0-9.]+ s( on [2-9] threads)? "
                 "\\([0-9]+ primary rays/s\\)\n")))
      << r.err;
  // TC03: --quiet: no header and no progress, only the final line; --silent: nothing
  const test::RtResult quiet =
      runRt({"render", "two-color", "-o", out, "--width", "20", "--height", "10", "--quiet"});
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_TRUE(std::regex_match(quiet.err, std::regex("rt: wrote " + out + ": 20x10, [^\n]+\n")))
      << quiet.err;
  const test::RtResult silent =
      runRt({"render", "two-color", "-o", out, "--width", "20", "--height", "10", "--silent"});
  ASSERT_EQ(silent.exitCode, 0) << silent.err;
  EXPECT_EQ(silent.err, "");
  // TC02: --tracer names the tracer in the report
  const test::RtResult phong = runRt(
      {"render", "two-color", "-o", out, "--width", "2", "--height", "2", "--tracer", "phong"});
  ASSERT_EQ(phong.exitCode, 0) << phong.err;
  EXPECT_NE(phong.err.find("(2x2, tracer phong)"), std::string::npos) << phong.err;
}

TEST(RenderProcessTests, threadsAndAccelerationChangeNothingInTheImage) {
  const std::string dir = freshDirectory("renderThreadsAccel");
  // The galaxy (every kind of shape, beams, soft shadows), small: the reference is one thread
  // over the scene's own list, the course's renderer.
  const std::vector<std::string> scene{"render",   "galaxy", "--width", "48",
                                       "--height", "27",     "--silent"};
  const auto renderWith = [&](const std::string& name, std::vector<std::string> options) {
    std::vector<std::string> args = scene;
    args.insert(args.end(), {"-o", dir + "/" + name + ".png"});
    args.insert(args.end(), options.begin(), options.end());
    const test::RtResult r = runRt(args);
    EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
    return readFile(dir + "/" + name + ".png");
  };
  const std::string reference = renderWith("reference", {"--threads", "1", "--accel", "none"});
  ASSERT_FALSE(reference.empty());
  // TC01: two and seven threads (more threads than cores), the same bytes
  EXPECT_EQ(renderWith("t2", {"--threads", "2", "--accel", "none"}), reference);
  EXPECT_EQ(renderWith("t7", {"--threads", "7", "--accel", "none"}), reference);
  // TC02: each acceleration structure, and every core (0), the same bytes
  EXPECT_EQ(renderWith("cbr", {"--accel", "cbr", "--threads", "1"}), reference);
  EXPECT_EQ(renderWith("bvh", {"--accel", "bvh", "--threads", "0"}), reference);
  EXPECT_EQ(renderWith("grid", {"--accel", "grid", "--threads", "0"}), reference);
}

TEST(RenderProcessTests, badSceneFileExitsWithTwo) {
  const std::string dir = freshDirectory("renderBadFile");
  // TC01: a scene file that does not exist: the loader's message, exit 2, nothing written
  test::RtResult r = runRt({"render", dir + "/missing.json", "-o", dir + "/x.png"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(r.err.starts_with("rt: ")) << r.err;
  EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
  // TC02: malformed JSON: the message names the file, line and column
  writeText(dir + "/bad.json", "{\n  \"background\": [1, 2,\n}\n");
  r = runRt({"render", dir + "/bad.json", "-o", dir + "/x.png"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(r.err.starts_with("rt: " + dir + "/bad.json:3:")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
}

TEST(RenderProcessTests, unwritableOutputFailsBeforeRendering) {
  const std::string dir = freshDirectory("renderUnwritable");
  // TC01: a missing directory: exit 2, the one-line reason, and no render started (no progress)
  const std::string missing = dir + "/missing/out.png";
  const test::RtResult r = runRt({"render", "two-color", "-o", missing});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "rt: -o: cannot write '" + missing + "': the directory '" + dir +
                       "/missing' does not exist\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/missing"));
}

TEST(RenderProcessTests, readOnlyDirectoryKeepsTheExistingFile) {
  namespace fs = std::filesystem;
  // A directory that its owner can read but not write; when the tests run as root (who may
  // write anywhere) rt runs as the unprivileged user nobody, for whom the mode holds. The
  // directory lives in /tmp, which every user can reach.
  char pattern[] = "/tmp/rt-cli-readonly-XXXXXX";
  ASSERT_NE(::mkdtemp(pattern), nullptr);
  const std::string dir = pattern;
  const std::string out = dir + "/out.png";
  writeText(out, "the previous image");
  ::chmod(out.c_str(), 0644);
  ::chmod(dir.c_str(), 0555);
  // TC01: exit 2 before rendering (no progress line), the reason named, the file untouched
  const test::RtResult r =
      runRt({"render", "two-color", "-o", out}, {.cwd = "", .asUnprivileged = true, .path = {}});
  ::chmod(dir.c_str(), 0755);
  const std::string kept = readFile(out);
  const auto entries = std::distance(fs::directory_iterator(dir), fs::directory_iterator());
  fs::remove_all(dir);
  if (r.exitCode == 125 || r.exitCode == 127)
    GTEST_SKIP() << "cannot run " << RT_EXE << " as the user nobody (exit " << r.exitCode << ")";
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "rt: -o: cannot write '" + out + "': Permission denied\n");
  EXPECT_EQ(kept, "the previous image");
  EXPECT_EQ(entries, 1);  // no temporary file left behind
}

TEST(RenderProcessTests, ctrlCStopsTheRenderAndWritesNothing) {
  const std::string dir = freshDirectory("renderInterrupt");
  const std::string out = dir + "/out.png";
  writeText(out, "the previous image");
  // The scene with the most shapes, with the slowest tracer, large: it takes seconds, and the
  // signal is sent as soon as the first 10% are reported.
  const BuiltinScene* slowest = &builtinScenes().front();
  for (const BuiltinScene& s : builtinScenes())
    if (makeBuiltinScene(s, {}).scene->geometries.size() >
        makeBuiltinScene(*slowest, {}).scene->geometries.size())
      slowest = &s;
  test::RtChild child({"render", slowest->name, "-o", out, "--tracer", "whitted", "--width", "1200",
                       "--height", "1200"});
  ASSERT_TRUE(child.waitForLine("rt: rendering 10%")) << child.err();
  child.signal(SIGINT);
  // TC01: exit code 130, a message, the existing file untouched, no temporary file left
  EXPECT_EQ(child.wait(), 130) << child.err();
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      child.err(), m,
      std::regex("rt: interrupted after ([0-9]+) of 1440000 pixels; nothing written to " + out +
                 "\n$")))
      << child.err();
  // the render stopped part way: at least the reported 10%, not all of it
  EXPECT_GE(std::stoll(m[1]), 144000);
  EXPECT_LT(std::stoll(m[1]), 1440000);
  EXPECT_EQ(readFile(out), "the previous image");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);
}

// ---------------------------------------------------------------------------------------------
// probe

TEST(ProbeProcessTests, negativeCoordinatesAndTheFirstHit) {
  const std::string dir = freshDirectory("probe");
  // A sphere of radius 2 at (0,0,2) and a named wall z = 5; ambient (100,100,100) x 0.5.
  writeText(dir + "/simple.json", R"({
  "camera": {"location": [0, 0, -10], "target": [0, 0, 0], "vpDistance": 10,
             "vpSize": [4, 4], "resolution": [5, 5]},
  "background": [1, 2, 3],
  "ambient": {"color": [100, 100, 100], "kA": 0.5},
  "geometries": [
    {"type": "sphere", "center": [0, 0, 2], "radius": 2, "emission": [300, 20, 20],
     "name": "ball"},
    {"type": "plane", "point": [0, 0, 5], "normal": [0, 0, 1], "name": "wall"}
  ],
  "render": {"tracer": "phong"}
}
)");
  // TC01: --ray with negative coordinates parses; the first hit is where the line x = -1,
  // y = 0.5 enters the sphere: z = 2 - sqrt(4 - 1.25), t = 4 - sqrt(2.75); its outward normal
  // is (p - c) / 2 = (-0.5, 0.25, -sqrt(2.75)/2)
  const test::RtResult r = runRt({"probe", dir + "/simple.json", "--ray", "-1,0.5,-2", "0,0,1"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["ray"]["origin"], nlohmann::json::parse("[-1, 0.5, -2]"));
  EXPECT_EQ(j["ray"]["direction"], nlohmann::json::parse("[0, 0, 1]"));
  ASSERT_EQ(j["hits"].size(), 3u);
  const double s = std::sqrt(2.75);
  const nlohmann::json& first = j["hits"][0];
  EXPECT_NEAR(first["t"].get<double>(), 4 - s, 1e-12);
  EXPECT_NEAR(first["point"][0].get<double>(), -1, 1e-12);
  EXPECT_NEAR(first["point"][1].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(first["point"][2].get<double>(), 2 - s, 1e-12);
  EXPECT_NEAR(first["normal"][0].get<double>(), -0.5, 1e-12);
  EXPECT_NEAR(first["normal"][1].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(first["normal"][2].get<double>(), -s / 2, 1e-12);
  EXPECT_EQ(first["geometry"], 0);
  EXPECT_EQ(first["name"], "ball");
  // the sphere's far side, then the wall, sorted by t
  EXPECT_NEAR(j["hits"][1]["t"].get<double>(), 4 + s, 1e-12);
  EXPECT_EQ(j["hits"][2]["t"], 7);
  EXPECT_EQ(j["hits"][2]["geometry"], 1);
  EXPECT_EQ(j["hits"][2]["name"], "wall");
  EXPECT_EQ(j["hits"][2]["normal"], nlohmann::json::parse("[0, 0, 1]"));
  // the Phong tracer's colour: emission + Ia·kA, unclamped
  EXPECT_EQ(j["color"], nlohmann::json::parse("[350, 70, 70]"));

  // TC02: --tracer ambient changes the colour to the ambient light alone
  const test::RtResult ambient =
      runRt({"probe", dir + "/simple.json", "--ray", "-1,0.5,-2", "0,0,1", "--tracer", "ambient"});
  ASSERT_EQ(ambient.exitCode, 0) << ambient.err;
  EXPECT_EQ(nlohmann::json::parse(ambient.out)["color"], nlohmann::json::parse("[50, 50, 50]"));

  // TC03: --pixel: the camera's ray through the centre pixel of the 5x5 image goes from the
  // camera's location straight at the target
  const test::RtResult pixel = runRt({"probe", dir + "/simple.json", "--pixel", "2,2"});
  ASSERT_EQ(pixel.exitCode, 0) << pixel.err;
  const nlohmann::json p = nlohmann::json::parse(pixel.out);
  EXPECT_EQ(p["ray"]["origin"], nlohmann::json::parse("[0, 0, -10]"));
  EXPECT_EQ(p["ray"]["direction"], nlohmann::json::parse("[0, 0, 1]"));
  EXPECT_EQ(p["hits"][0]["t"], 10);

  // TC11: --pixel beyond the scene's resolution is refused; with --width it is inside
  EXPECT_EQ(runRt({"probe", dir + "/simple.json", "--pixel", "5,0"}).exitCode, 2);
  EXPECT_EQ(runRt({"probe", dir + "/simple.json", "--pixel", "5,0", "--width", "6"}).exitCode, 0);
}

// ---------------------------------------------------------------------------------------------
// export

TEST(ExportProcessTests, renderingTheExportGivesTheSameBytes) {
  const std::string dir = freshDirectory("exportRender");
  // One scene of each stage (small images: the equality is per pixel, the size does not matter).
  std::vector<std::string> names{"two-color"};
  for (auto table : {lightingScenes(), shadowScenes(), reflectionScenes()})
    if (!table.empty()) names.push_back(table.front().name);
  names.push_back(reflectionScenes().back().name);
  // and every scene of mini project 1 when the build has it: the galaxy (every star written) and
  // the demonstrations, whose beams, light sizes, lens and samplers the export must keep
  for (const BuiltinScene& s : builtinScenes())
    if (s.stage == "mini1_glossy") names.push_back(s.name);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const std::string json = dir + "/" + name + ".json";
    // TC01: export to a file, and to stdout: the same text
    test::RtResult r = runRt({"export", name, "-o", json});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "");
    r = runRt({"export", name});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, readFile(json));
    // TC02: the built-in scene and its export render to identical PNG files
    const std::vector<std::string> size{"--width", "48", "--height", "36", "--silent"};
    std::vector<std::string> a{"render", name, "-o", dir + "/" + name + "-builtin.png"};
    std::vector<std::string> b{"render", json, "-o", dir + "/" + name + "-export.png"};
    a.insert(a.end(), size.begin(), size.end());
    b.insert(b.end(), size.begin(), size.end());
    ASSERT_EQ(runRt(a).exitCode, 0);
    r = runRt(b);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string builtinPng = readFile(dir + "/" + name + "-builtin.png");
    EXPECT_FALSE(builtinPng.empty());
    EXPECT_EQ(builtinPng, readFile(dir + "/" + name + "-export.png"));
  }
}

// ---------------------------------------------------------------------------------------------
// meshes

/// A scene file of an inline mesh (a square tile of two triangles with normals, turned and
/// moved) and a sphere, lit.
const std::string kInlineMeshScene = R"({
  "camera": {"location": [0, 0, 10], "target": [0, 0, 0], "vpDistance": 10, "vpSize": [4, 4],
             "resolution": [40, 40]},
  "ambient": {"color": [255, 255, 255], "kA": 0.1},
  "lights": [{"type": "point", "intensity": [400, 400, 400], "position": [3, 4, 8]}],
  "geometries": [
    {"type": "mesh", "vertices": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]],
     "triangles": [[0, 1, 2], [0, 2, 3]], "normals": [[-1, -1, 3], [1, -1, 3], [1, 1, 3], [-1, 1, 3]],
     "rotation": [20, 30, 0], "translation": [0.3, 0, 0], "emission": [60, 10, 0],
     "material": {"kD": 0.5, "kS": 0.5, "shininess": 30}},
    {"type": "sphere", "center": [0, 0, -2], "radius": 1, "material": {"kD": 0.7}}
  ]
})";

TEST(MeshProcessTests, aSceneFileWithMeshesRendersAsItsExport) {
  const std::string dir = freshDirectory("meshExport");
  std::filesystem::create_directories(dir + "/out");
  std::vector<std::string> scenes{writeText(dir + "/inline.json", kInlineMeshScene)};
  // The shading scene's model file, when this build reads model files (its path then moves)
  if (modelFilesSupported()) scenes.push_back(std::string(RT_SCENES_DIR) + "/model-shading.json");
  for (const std::string& scene : scenes) {
    SCOPED_TRACE(scene);
    const std::string name = std::filesystem::path(scene).stem().string();
    const std::string exported = dir + "/out/" + name + ".json";
    // TC01: the export into another folder renders to the same bytes as the scene file
    test::RtResult r = runRt({"export", scene, "-o", exported});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<std::string> size{"--width", "64", "--silent"};
    std::vector<std::string> a{"render", scene, "-o", dir + "/" + name + "-file.png"};
    std::vector<std::string> b{"render", exported, "-o", dir + "/" + name + "-export.png"};
    a.insert(a.end(), size.begin(), size.end());
    b.insert(b.end(), size.begin(), size.end());
    ASSERT_EQ(runRt(a).exitCode, 0);
    r = runRt(b);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string filePng = readFile(dir + "/" + name + "-file.png");
    EXPECT_FALSE(filePng.empty());
    EXPECT_EQ(filePng, readFile(dir + "/" + name + "-export.png"));
  }
  // TC02: the model file's path is relative to the export's folder
  if (modelFilesSupported()) {
    const std::string text = readFile(dir + "/out/model-shading.json");
    const std::string expected =
        std::filesystem::path(RT_SCENES_DIR "/models/teapot.ply")
            .lexically_normal()
            .lexically_relative(std::filesystem::absolute(dir + "/out").lexically_normal())
            .generic_string();
    EXPECT_NE(text.find("\"file\": \"" + expected + "\""), std::string::npos) << text;
    EXPECT_EQ(expected.rfind("../", 0), 0u) << expected;
  }
}

TEST(MeshProcessTests, aBadMeshExitsWithTwoAndKeepsTheImage) {
  const std::string dir = freshDirectory("meshBad");
  const std::string out = writeText(dir + "/out.png", "the previous image");
  const std::string head =
      "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], \"vpDistance\": 1, "
      "\"vpSize\": [1, 1], \"resolution\": [8, 8]},\n \"geometries\": [\n";
  // TC01: a model file that does not exist: the scene file, the entry, the model file named
  const std::string missing =
      writeText(dir + "/missing.json", head + "  {\"type\": \"mesh\", \"file\": \"none.obj\"}]}\n");
  test::RtResult r = runRt({"render", missing, "-o", out});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(
      r.err.starts_with("rt: " + missing + ":3:28: geometries[0].file: " + dir + "/none.obj: "))
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(readFile(out), "the previous image");
  // TC02: an inline mesh's index out of range
  const std::string range = writeText(
      dir + "/range.json", head +
                               "  {\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, "
                               "0]], \"triangles\": [[0, 1, 3]]}]}\n");
  r = runRt({"render", range, "-o", out});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "rt: " + range +
                       ":3:88: geometries[0].triangles[0][2]: expected a vertex index from 0 to 2 "
                       "(the mesh has 3 vertices), got 3\n");
  EXPECT_EQ(readFile(out), "the previous image");
  // TC03: rt export refuses it too, and writes nothing
  r = runRt({"export", missing, "-o", dir + "/x.json"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.json"));
}

}  // namespace
}  // namespace rt::cli
