// Tests of `rt bench` (mini project 2's command): the rows, their order and their exact counts on
// tiny images, the three formats, the star scaling (each galaxy in a process of its own), every
// usage error before the first ray, and Ctrl-C. Timings are never asserted beyond > 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "InProcess.h"
#include "RtProcess.h"
#include "cli/Commands.h"
#include "cli/Tracers.h"
#include "glossy/Galaxy.h"
#include "scenefile/ModelFile.h"

namespace rt::cli {
namespace {

using nlohmann::json;

using test::lines;
using test::Outcome;
using test::run;

/// The stages' tracers, in the course's order: every tracer of the full course (rt bench is
/// mini 2's) but stage 4's debugging views.
const std::vector<std::string> STAGE_TRACERS{"ambient", "phong", "shadow", "whitted", "beams"};

/// The rows' names in the documented order: the reference report's four, the wide BVH's alone
/// and with light buffers, the grid's, Embree's (rendered or not, as the build has Embree), then
/// one per stage's tracer, named by its stage.
std::vector<std::string> expectedNames() {
  std::vector<std::string> names{"no acceleration",    "threads",
                                 "threads + CBR",      "threads + CBR + BVH",
                                 "threads + wide BVH", "threads + wide BVH + light buffers",
                                 "threads + grid",     "Embree 3"};
  for (const std::string& name : STAGE_TRACERS) names.push_back(tracerNamed(name)->stage);
  return names;
}

/// Whether this build has Embree (RT_HAVE_EMBREE, from rt_embree): its row is rendered or not.
#if RT_HAVE_EMBREE
constexpr bool HAVE_EMBREE = true;
#else
constexpr bool HAVE_EMBREE = false;
#endif

/// The rows of the wide BVH alone and with light buffers, the row "Embree 3" and the first
/// stage's tracer's row, in the report's rows.
constexpr std::size_t WIDE = 4, LIGHTS = 5, EMBREE = 7, FIRST_STAGE = 8;

/// The note of the row "Embree 3" in a build without Embree.
const std::string NOT_BUILT =
    "not built: install libembree-dev (scripts/deps.sh --embree) and reconfigure";

int cores() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

// ---------------------------------------------------------------------------------------------
// The timing table

TEST(BenchTests, jsonRowsAreTheReferenceRowsThenEveryTracerWithExactCounts) {
  const Outcome r = run({"bench", "galaxy", "--width", "16", "--height", "9", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  // TC01: the header: scene, size, the threads of the multi-threaded rows, the machine
  EXPECT_EQ(j["scene"], "galaxy");
  EXPECT_EQ(j["width"], 16);
  EXPECT_EQ(j["height"], 9);
  EXPECT_EQ(j["threads"], cores());
  EXPECT_FALSE(j["machine"].get<std::string>().empty());
  EXPECT_EQ(j["reference"], "the reference report's times for its galaxy at 1280x720");
  // TC02: the rows in the documented order, each with exactly the documented keys
  const json& rows = j["rows"];
  const std::vector<std::string> names = expectedNames();
  ASSERT_EQ(rows.size(), names.size());
  const std::vector<std::string> keys{
      "name",    "tracer",           "accel",           "threads",       "seconds",
      "primary", "secondary",        "shadow",          "raysPerSecond", "nodesPerRay",
      "speedup", "referenceSeconds", "pixelsDiffering", "note"};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::vector<std::string> got;
    for (const auto& [key, value] : rows[i].items()) got.push_back(key);
    std::vector<std::string> sortedKeys = keys;
    std::sort(got.begin(), got.end());
    std::sort(sortedKeys.begin(), sortedKeys.end());
    EXPECT_EQ(got, sortedKeys) << i;
    EXPECT_EQ(rows[i]["name"], names[i]) << i;
  }
  // TC03: the reference rows, the wide BVH's (alone and with light buffers) and the grid's
  // render with the galaxy's tracer, beams, and the report's accelerations, then the wide BVH,
  // the wide BVH with a light buffer per point light ("+lights") and the grid
  const std::vector<std::string> accels{"none", "none",        "cbr", "bvh",
                                        "bvh4", "bvh4+lights", "grid"};
  for (std::size_t i = 0; i < EMBREE; ++i) {
    EXPECT_EQ(rows[i]["tracer"], "beams") << i;
    EXPECT_EQ(rows[i]["accel"], accels[i]) << i;
  }
  // TC03b: then Embree's row, with the same tracer, its accel "embree"
  EXPECT_EQ(rows[EMBREE]["tracer"], "beams");
  EXPECT_EQ(rows[EMBREE]["accel"], "embree");
  // TC04: then every stage's tracer, in the course's order, as a render goes by default: the
  // wide BVH with light buffers (not the debugging views rays, normals and hits)
  for (std::size_t i = FIRST_STAGE; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]["tracer"], STAGE_TRACERS[i - FIRST_STAGE]) << i;
    EXPECT_EQ(rows[i]["accel"], "bvh4+lights") << i;
  }
  // TC05: 16 x 9 is one tile of 32: every row rendered on one thread (never more than tiles);
  // the row not rendered keeps the threads asked for
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_EQ(rows[i]["threads"], i == EMBREE && !HAVE_EMBREE ? cores() : 1) << i;
  // TC06: one camera ray per pixel in every row rendered
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (i != EMBREE || HAVE_EMBREE) {
      EXPECT_EQ(rows[i]["primary"], 144) << i;
    }
  // TC07: the reference rows, the wide BVH's (alone and with light buffers) and the grid's
  // trace the same rays: the images are the same bits, so are the counts
  for (std::size_t i = 1; i < EMBREE; ++i)
    for (const char* kind : {"primary", "secondary", "shadow"})
      EXPECT_EQ(rows[i][kind], rows[0][kind]) << i << " " << kind;
  EXPECT_GT(rows[0]["secondary"].get<long>(), 0);
  EXPECT_GT(rows[0]["shadow"].get<long>(), 0);
  // TC08: the beams row through the wide BVH with light buffers is the sixth row again; the
  // wide tree visits fewer nodes than the binary one (its node holds four boxes)
  for (const char* kind : {"primary", "secondary", "shadow", "nodesPerRay"})
    EXPECT_EQ(rows.back()[kind], rows[LIGHTS][kind]) << kind;
  EXPECT_LT(rows[WIDE]["nodesPerRay"].get<double>(), rows[3]["nodesPerRay"].get<double>());
  // TC08b: the light buffers' row: the wide BVH's rays and image (no pixel differs from the
  // first row's), with fewer nodes per ray (a shadow ray a buffer answers enters no node)
  for (const char* kind : {"primary", "secondary", "shadow", "pixelsDiffering"})
    EXPECT_EQ(rows[LIGHTS][kind], rows[WIDE][kind]) << kind;
  EXPECT_EQ(rows[LIGHTS]["pixelsDiffering"], 0);
  EXPECT_LT(rows[LIGHTS]["nodesPerRay"].get<double>(), rows[WIDE]["nodesPerRay"].get<double>());
  // TC09: nodes per ray: none without a hierarchy, some through the BVH (and cells through the
  // grid)
  // (none for Embree, which does not report its nodes: null)
  EXPECT_EQ(rows[0]["nodesPerRay"], 0);
  EXPECT_EQ(rows[1]["nodesPerRay"], 0);
  EXPECT_TRUE(rows[EMBREE]["nodesPerRay"].is_null());
  for (std::size_t i = 3; i < rows.size(); ++i)
    if (i != EMBREE) {
      EXPECT_GT(rows[i]["nodesPerRay"].get<double>(), 0) << i;
    }
  // TC10: the reference report's times beside its four rows (1 h 21 min, 25 min 40 s, 13 min 57 s,
  // 6 min 47 s), null after them (the wide BVH's row first)
  const std::vector<int> reference{4860, 1540, 837, 407};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(rows[i]["referenceSeconds"], reference[i]) << i;
  for (std::size_t i = 4; i < rows.size(); ++i)
    EXPECT_TRUE(rows[i]["referenceSeconds"].is_null()) << i;
  // TC11: the speed-up is over the first row: exactly 1 there; the times and rates positive
  EXPECT_EQ(rows[0]["speedup"], 1);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i == EMBREE && !HAVE_EMBREE) continue;  // TC14
    EXPECT_GT(rows[i]["seconds"].get<double>(), 0) << i;
    EXPECT_GT(rows[i]["raysPerSecond"].get<double>(), 0) << i;
    EXPECT_GT(rows[i]["speedup"].get<double>(), 0) << i;
  }
  // TC12: one progress line per row started, on stderr
  const std::vector<std::string> err = lines(r.err);
  ASSERT_EQ(err.size(), names.size()) << r.err;
  EXPECT_EQ(err[0], "rt bench: row 1/" + std::to_string(names.size()) +
                        ": no acceleration (tracer beams, accel none, 1 thread)");
  EXPECT_EQ(err[LIGHTS], "rt bench: row 6/" + std::to_string(names.size()) +
                             ": threads + wide BVH + light buffers (tracer beams, accel "
                             "bvh4+lights, " +
                             std::to_string(cores()) + (cores() == 1 ? " thread)" : " threads)"));
  for (std::size_t i = 0; i < err.size(); ++i)
    EXPECT_TRUE(err[i].starts_with("rt bench: row " + std::to_string(i + 1) + "/" +
                                   std::to_string(names.size()) + ": " + names[i] + " ("))
        << err[i];
  // TC13: pixels differing from the first row's image: none for the project's structures and
  // for the stage row of the same tracer (beams, the last); not compared for the other tracers
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i == EMBREE) continue;
    if (i < EMBREE || i + 1 == rows.size())
      EXPECT_EQ(rows[i]["pixelsDiffering"], 0) << i;
    else
      EXPECT_TRUE(rows[i]["pixelsDiffering"].is_null()) << i;
    EXPECT_EQ(rows[i]["note"], "") << i;
  }
#if RT_HAVE_EMBREE
  // TC14: Embree's row: the same camera rays, its pixels differing and its other rays as
  // measured (float tests: a grazing ray may find another shape), its note naming its version
  EXPECT_EQ(rows[EMBREE]["primary"], 144);
  EXPECT_EQ(rows[EMBREE]["secondary"], rows[0]["secondary"]);
  EXPECT_EQ(rows[EMBREE]["shadow"], rows[0]["shadow"]);
  EXPECT_EQ(rows[EMBREE]["pixelsDiffering"], 0);
  EXPECT_EQ(rows[EMBREE]["note"], "Embree 3.13.5: float tests; t recomputed exactly");
#else
  // TC14: without Embree, its row has no figures and says how to get it
  for (const char* key : {"seconds", "primary", "secondary", "shadow", "raysPerSecond",
                          "nodesPerRay", "speedup", "pixelsDiffering", "referenceSeconds"})
    EXPECT_TRUE(rows[EMBREE][key].is_null()) << key;
  EXPECT_EQ(rows[EMBREE]["note"], NOT_BUILT);
  EXPECT_EQ(err[EMBREE],
            "rt bench: row 8/" + std::to_string(names.size()) + ": Embree 3 (" + NOT_BUILT + ")");
#endif
}

TEST(BenchTests, theTeapotsHaveTheLecturersRowsAndTimes) {
  // 96 x 96: nine tiles of 32, so that the rows of 2, 3 and 4 threads have them all.
  const Outcome r = run({"bench", "teapot", "--width", "96", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  // TC01: the caption's reference names whose times they are, and where they were measured
  EXPECT_EQ(j["scene"], "teapot");
  EXPECT_EQ(j["height"], 96);
  EXPECT_TRUE(j["reference"].get<std::string>().starts_with(
      "the course lecturer's times for his TeapotTest of 2025 (1000x1000 with 400 bubbles, no "
      "acceleration), in Java on his machine, not this one"))
      << j["reference"];
  // TC02: the lecturer's thread rows, then the structures with every core (the wide BVH alone
  // and with light buffers), then every stage's tracer through the wide BVH with light buffers
  std::vector<std::string> names{"no acceleration",
                                 "2 threads",
                                 "3 threads",
                                 "4 threads",
                                 "threads",
                                 "threads + CBR",
                                 "threads + CBR + BVH",
                                 "threads + wide BVH",
                                 "threads + wide BVH + light buffers",
                                 "threads + grid",
                                 "Embree 3"};
  for (const std::string& name : STAGE_TRACERS) names.push_back(tracerNamed(name)->stage);
  const json& rows = j["rows"];
  ASSERT_EQ(rows.size(), names.size());
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i]["name"], names[i]) << i;
  // TC03: the teapot's tracer (Whitted), the accelerations and the threads of each
  const int every = std::min(cores(), 9);
  const std::vector<std::string> accels{"none", "none", "none", "none",        "none",
                                        "cbr",  "bvh",  "bvh4", "bvh4+lights", "grid"};
  const std::vector<int> threads{1, 2, 3, 4, every, every, every, every, every, every};
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(rows[i]["tracer"], "whitted") << i;
    EXPECT_EQ(rows[i]["accel"], accels[i]) << i;
    EXPECT_EQ(rows[i]["threads"], threads[i]) << i;
  }
  // TC03b: Embree's row after the structures, with every core, the teapot's tracer
  EXPECT_EQ(rows[10]["tracer"], "whitted");
  EXPECT_EQ(rows[10]["accel"], "embree");
  EXPECT_EQ(rows[10]["threads"], every);
  // TC03c: every stage's tracer through the wide BVH with light buffers, with every core
  for (std::size_t i = 11; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]["tracer"], STAGE_TRACERS[i - 11]) << i;
    EXPECT_EQ(rows[i]["accel"], "bvh4+lights") << i;
    EXPECT_EQ(rows[i]["threads"], every) << i;
  }
  // TC04: his times beside his rows (his 0 threads: 25 s; 2, 3, 4: 13.6, 10.7, 10.7; every
  // core: 9.3), none beside the others
  const std::vector<double> reference{25, 13.6, 10.7, 10.7, 9.3};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(rows[i]["referenceSeconds"], reference[i]) << i;
  for (std::size_t i = 5; i < rows.size(); ++i)
    EXPECT_TRUE(rows[i]["referenceSeconds"].is_null()) << i;
  // TC05: the ten rows trace the same rays (the same image): a camera ray per pixel and
  // shadow rays, none reflected (the teapot is matte)
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(rows[i]["primary"], 96 * 96) << i;
    EXPECT_EQ(rows[i]["secondary"], 0) << i;
    EXPECT_EQ(rows[i]["shadow"], rows[0]["shadow"]) << i;
  }
  EXPECT_GT(rows[0]["shadow"].get<long>(), 0);
  // TC05b: the light buffers' row has the wide BVH's image: no pixel differs from the first
  // row's
  EXPECT_EQ(rows[7]["pixelsDiffering"], 0);
  EXPECT_EQ(rows[8]["pixelsDiffering"], 0);
  // TC06: the bubbles have the same rows and times; another scene has the report's rows and no
  // reference at all
  const json b = json::parse(run({"bench", "bubbles", "--width", "16", "--json"}).out);
  ASSERT_EQ(b["rows"].size(), names.size());
  EXPECT_EQ(b["rows"][1]["name"], "2 threads");
  EXPECT_EQ(b["rows"][4]["referenceSeconds"], 9.3);
  EXPECT_EQ(b["reference"], j["reference"]);
  const json other = json::parse(run({"bench", "two-color", "--width", "8", "--json"}).out);
  EXPECT_TRUE(other["reference"].is_null());
  EXPECT_EQ(other["rows"][1]["name"], "threads");
}

TEST(BenchTests, threadsAreTheCoresAskedForWhenTheImageHasTiles) {
  // Without diffusion and 64 x 9 (two tiles of 32): cheap, and two threads can share it.
  const Outcome r = run({"bench", "galaxy", "--param", "diffusion=off", "--width", "64", "--height",
                         "9", "--threads", "2", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  // TC01: --threads sets the multi-threaded rows' threads; the first row has one
  EXPECT_EQ(j["threads"], 2);
  const json& rows = j["rows"];
  ASSERT_EQ(rows.size(), expectedNames().size());
  EXPECT_EQ(rows[0]["threads"], 1);
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i]["threads"], 2) << i;
  // TC02: the same rays on one thread and on two
  for (std::size_t i = 1; i < EMBREE; ++i)
    for (const char* kind : {"primary", "secondary", "shadow"})
      EXPECT_EQ(rows[i][kind], rows[0][kind]) << i << " " << kind;
  EXPECT_EQ(rows[0]["primary"], 64 * 9);
}

TEST(BenchTests, markdownHasACaptionAndTheReferenceTimes) {
  const Outcome r =
      run({"bench", "galaxy", "--param", "diffusion=off", "--width", "16", "--height", "9"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<std::string> out = lines(r.out);
  ASSERT_EQ(out.size(), 4 + expectedNames().size()) << r.out;
  // TC01: a caption naming the scene, the size and the reference times, then an empty line
  EXPECT_TRUE(out[0].starts_with("rt bench galaxy: 16x9, " + std::to_string(cores()) +
                                 " threads for the multi-threaded rows, "))
      << out[0];
  EXPECT_TRUE(out[0].ends_with(
      "; one render per row; reference: the reference report's times for its galaxy at 1280x720; "
      "pixels differing: from the first row's image, for the rows of its tracer" +
      std::string(HAVE_EMBREE
                      ? " (Embree tests its boxes and its spheres, triangles and quads in "
                        "float: a ray that grazes a shape's edge can miss it there, where the "
                        "exact test hits it; every hit Embree offers is checked and ordered by "
                        "the project's exact test, so only such rays change a pixel; the "
                        "project's structures differ in none)"
                      : "")))
      << out[0];
  EXPECT_EQ(out[1], "");
  // TC02: the header and the alignment line, exactly
  EXPECT_EQ(out[2],
            "| row | tracer | accel | threads | wall | reference | primary | secondary | shadow | "
            "rays/s | nodes/ray | speed-up | pixels differing | note |");
  EXPECT_EQ(out[3],
            "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | "
            "---: | --- |");
  // TC03: the reference rows carry the report's times, written as the report has them
  const std::vector<std::string> reference{"1 h 21 min", "25 min 40 s", "13 min 57 s",
                                           "6 min 47 s"};
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NE(out[4 + i].find(" s | " + reference[i] + " | 144 | "), std::string::npos)
        << out[4 + i];
  EXPECT_TRUE(out[4].starts_with("| no acceleration | beams | none | 1 | ")) << out[4];
  EXPECT_TRUE(out[4].ends_with(" | 0.00 | 1.00 | 0 |  |")) << out[4];
  // TC04: an empty reference cell after them; the light buffers' row names its accel
  EXPECT_NE(out[8].find(" s |  | 144 | "), std::string::npos) << out[8];
  EXPECT_TRUE(out[4 + LIGHTS].starts_with(
      "| threads + wide BVH + light buffers | beams | bvh4+lights | 1 | "))
      << out[4 + LIGHTS];
  // TC05: Embree's row: "—" for the nodes it does not count (and, without Embree, for every
  // figure, with the note)
#if RT_HAVE_EMBREE
  EXPECT_TRUE(out[4 + EMBREE].starts_with("| Embree 3 | beams | embree | ")) << out[4 + EMBREE];
  EXPECT_NE(out[4 + EMBREE].find(" | — | "), std::string::npos) << out[4 + EMBREE];
  EXPECT_TRUE(out[4 + EMBREE].ends_with(" | Embree 3.13.5: float tests; t recomputed exactly |"))
      << out[4 + EMBREE];
#else
  EXPECT_EQ(out[4 + EMBREE], "| Embree 3 | beams | embree | " + std::to_string(cores()) +
                                 " | — |  | — | — | — | — | — | — | — | " + NOT_BUILT + " |");
#endif
  // TC06: the stage rows of other tracers are not compared: "—"
  EXPECT_TRUE(out[4 + FIRST_STAGE].ends_with(" | — |  |")) << out[4 + FIRST_STAGE];
}

TEST(BenchTests, csvOfAnotherSceneHasNoReferenceTimes) {
  const Outcome r = run({"bench", "two-color", "--width", "16", "--height", "16", "--csv"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<std::string> out = lines(r.out);
  ASSERT_EQ(out.size(), 1 + expectedNames().size()) << r.out;
  // TC01: the header line, exactly
  EXPECT_EQ(out[0],
            "name,tracer,accel,threads,seconds,primary,secondary,shadow,raysPerSecond,nodesPerRay,"
            "speedup,referenceSeconds,pixelsDiffering,note");
  // TC02: the first row: the scene's tracer (ambient), no acceleration, one thread, 256 camera
  // rays and no others, no nodes, speed-up 1, and no reference time (the report timed its galaxy
  // only)
  EXPECT_TRUE(out[1].starts_with("no acceleration,ambient,none,1,")) << out[1];
  EXPECT_NE(out[1].find(",256,0,0,"), std::string::npos) << out[1];
  EXPECT_TRUE(out[1].ends_with(",0,1,,0,")) << out[1];
  // TC03: every row has the fourteen fields and an empty reference field (the notes have no
  // comma)
  for (std::size_t i = 1; i < out.size(); ++i) {
    EXPECT_EQ(std::count(out[i].begin(), out[i].end(), ','), 13) << out[i];
    if (i != 1 + EMBREE) {
      EXPECT_TRUE(out[i].ends_with(",")) << out[i];
    }
  }
  // TC04: Embree's row: an empty nodes field; without Embree, empty figures and the note
#if RT_HAVE_EMBREE
  EXPECT_TRUE(out[1 + EMBREE].starts_with("Embree 3,ambient,embree,")) << out[1 + EMBREE];
  EXPECT_TRUE(out[1 + EMBREE].ends_with(",0,Embree 3.13.5: float tests; t recomputed exactly"))
      << out[1 + EMBREE];
#else
  EXPECT_EQ(out[1 + EMBREE],
            "Embree 3,ambient,embree," + std::to_string(cores()) + ",,,,,,,,,," + NOT_BUILT);
#endif
}

TEST(BenchTests, repeatTakesTheRowsInTurn) {
  const Outcome r =
      run({"bench", "two-color", "--width", "8", "--height", "8", "--repeat", "2", "--csv"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::size_t n = expectedNames().size();
  const std::vector<std::string> err = lines(r.err);
  ASSERT_EQ(err.size(), 2 * n) << r.err;
  // TC01: every row once, then every row again (round robin, not each row twice in a row)
  for (std::size_t k = 0; k < 2 * n; ++k)
    EXPECT_TRUE(err[k].starts_with("rt bench: row " + std::to_string(k % n + 1) + "/" +
                                   std::to_string(n) + ", repeat " + std::to_string(k / n + 1) +
                                   "/2: "))
        << err[k];
  // TC02: one table row per row, not per render
  EXPECT_EQ(lines(r.out).size(), 1 + n);
}

TEST(BenchTests, outputFilesTakeTheirFormatsFromTheirEndings) {
  const std::string dir = test::freshDirectory("benchOutput");
  const std::string jsonFile = dir + "/bench.json", mdFile = dir + "/bench.md";
  { std::ofstream(jsonFile) << "the previous table"; }
  // -o before SCENE takes one file: the scene is still two-color
  const Outcome r =
      run({"bench", "-o", jsonFile, "two-color", "--width", "8", "--height", "8", "-o", mdFile});
  ASSERT_EQ(r.code, 0) << r.err;
  // TC01: nothing on stdout; each file in the format of its ending, from the same run
  EXPECT_EQ(r.out, "");
  const json j = json::parse(test::readFile(jsonFile));
  EXPECT_EQ(j["scene"], "two-color");
  EXPECT_EQ(j["rows"].size(), expectedNames().size());
  const std::vector<std::string> table = lines(test::readFile(mdFile));
  ASSERT_EQ(table.size(), 4 + expectedNames().size());
  EXPECT_TRUE(table[0].starts_with("rt bench two-color: 8x8, ")) << table[0];
  // TC02: stderr names both files
  EXPECT_TRUE(r.err.ends_with("rt bench: wrote " + jsonFile + "\nrt bench: wrote " + mdFile + "\n"))
      << r.err;
  // TC03: no temporary file left beside them
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            2);
}

TEST(BenchTests, twoOutputsNamingOneFileAreRefusedBeforeAnyRay) {
  // Relative to the current directory, as "x" and "./x" are.
  const std::string dir = test::freshTestDirectory("benchSameOutput");
  const std::string file = dir + "/bench.md", absolute = std::filesystem::absolute(file).string();
  { std::ofstream(file) << "the previous table"; }
  std::filesystem::create_directory(dir + "/sub");
  std::filesystem::create_directory_symlink(std::filesystem::absolute(dir), dir + "/link");
  const std::string hard = dir + "/hard.md";  // a second name of bench.md's file
  std::filesystem::create_hard_link(file, hard);
  const std::string here = "bench-same-output.md";  // a new file in the current directory
  std::filesystem::remove(here);
  // A table of two-color at 8x8, or a scaling of 100 stars: fast, were they not refused.
  const std::vector<std::string> table{"bench", "two-color", "--width", "8", "--height", "8"},
      scaling{"bench", "--scaling", "--stars", "100", "--width", "8", "--height", "8"};
  struct Case {
    const char* partition;
    std::vector<std::string> run;
    std::vector<std::string> args;  // after run's
    std::string message;
  };
  const std::vector<Case> cases = {
      // TC01: the same name twice
      {"TC01", table, {"-o", file, "-o", file}, "rt: -o: '" + file + "' is given twice\n"},
      // TC02: a new file's name in the current directory and the same with "./"; a relative
      // name and the same with "./", and with the current directory's path
      {"TC02",
       table,
       {"-o", here, "-o", "./" + here},
       "rt: -o: '" + here + "' and './" + here + "' name the same file\n"},
      {"TC02",
       table,
       {"-o", file, "-o", "./" + file},
       "rt: -o: '" + file + "' and './" + file + "' name the same file\n"},
      {"TC02",
       table,
       {"-o", absolute, "-o", file},
       "rt: -o: '" + absolute + "' and '" + file + "' name the same file\n"},
      // TC03: a name with "." and ".." in it
      {"TC03",
       table,
       {"-o", file, "-o", dir + "/./sub/../bench.md"},
       "rt: -o: '" + file + "' and '" + dir + "/./sub/../bench.md' name the same file\n"},
      // TC04: through a symbolic link to the directory
      {"TC04",
       table,
       {"-o", dir + "/link/bench.md", "-o", file},
       "rt: -o: '" + dir + "/link/bench.md' and '" + file + "' name the same file\n"},
      // TC05: the third of three the same as the first; with a format flag
      {"TC05",
       table,
       {"--csv", "-o", dir + "/a.csv", "-o", dir + "/b.csv", "-o", dir + "/sub/../a.csv"},
       "rt: -o: '" + dir + "/a.csv' and '" + dir + "/sub/../a.csv' name the same file\n"},
      // TC06: the scaling's files too
      {"TC06",
       scaling,
       {"-o", file, "-o", dir + "/sub/../bench.md"},
       "rt: -o: '" + file + "' and '" + dir + "/sub/../bench.md' name the same file\n"},
      // TC07: two hard links to one existing file, whose names share nothing but the folder;
      // for the table and for the scaling
      {"TC07",
       table,
       {"-o", hard, "-o", file},
       "rt: -o: '" + hard + "' and '" + file + "' name the same file\n"},
      {"TC07",
       scaling,
       {"-o", dir + "/a.md", "-o", file, "-o", hard},
       "rt: -o: '" + file + "' and '" + hard + "' name the same file\n"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = c.run;
    args.insert(args.end(), c.args.begin(), c.args.end());
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 2) << c.partition;
    EXPECT_EQ(r.err, c.message) << c.partition;
    EXPECT_EQ(r.out, "") << c.partition;
  }
  // TC08: nothing written: the file untouched (under both its names), nothing beside it, no
  // file in the current directory
  EXPECT_EQ(test::readFile(file), "the previous table");
  EXPECT_EQ(test::readFile(hard), "the previous table");
  EXPECT_TRUE(std::filesystem::is_empty(dir + "/sub"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            4);  // bench.md, hard.md, sub, link
  EXPECT_FALSE(std::filesystem::exists(here));
}

TEST(BenchTests, aLinkToAFileNotMadeYetNamesThatFile) {
  namespace fs = std::filesystem;
  // Relative to the current directory, as the links' targets are to their folders.
  const std::string dir = test::freshTestDirectory("benchLinkToNewFile");
  const std::string file = dir + "/t.md";  // not made yet
  fs::create_directory(dir + "/sub");
  fs::create_symlink("t.md", dir + "/t_link.json");
  fs::create_symlink("t_link.json", dir + "/chain.csv");
  fs::create_symlink("../t.md", dir + "/sub/up.md");
  const std::vector<std::string> table{"bench", "two-color", "--width", "8"};
  struct Case {
    const char* partition;
    std::vector<std::string> args;  // after table's
    std::string message;
  };
  const std::vector<Case> cases = {
      // TC01: a link to a file that does not exist yet, after the file and before it (once both
      // were written, the file holding the last one's JSON, with exit 0)
      {"TC01",
       {"-o", file, "-o", dir + "/t_link.json"},
       "rt: -o: '" + file + "' and '" + dir + "/t_link.json' name the same file\n"},
      {"TC01",
       {"-o", dir + "/t_link.json", "-o", file},
       "rt: -o: '" + dir + "/t_link.json' and '" + file + "' name the same file\n"},
      // TC02: a chain of two links, and a link's two names
      {"TC02",
       {"-o", dir + "/chain.csv", "-o", file},
       "rt: -o: '" + dir + "/chain.csv' and '" + file + "' name the same file\n"},
      {"TC02",
       {"-o", dir + "/chain.csv", "-o", dir + "/t_link.json"},
       "rt: -o: '" + dir + "/chain.csv' and '" + dir + "/t_link.json' name the same file\n"},
      // TC03: a relative target starts from the link's folder, not the current directory
      {"TC03",
       {"-o", dir + "/sub/up.md", "-o", file},
       "rt: -o: '" + dir + "/sub/up.md' and '" + file + "' name the same file\n"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = table;
    args.insert(args.end(), c.args.begin(), c.args.end());
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 2) << c.partition;
    EXPECT_EQ(r.err, c.message) << c.partition;
    EXPECT_EQ(r.out, "") << c.partition;
  }
  // TC04: nothing written: the links still dangle
  EXPECT_FALSE(fs::exists(file));
  EXPECT_FALSE(fs::exists(dir + "/t.md"));
  // TC05: a link to another new file is another file: both written
  fs::create_symlink("other.md", dir + "/o_link.json");
  const Outcome r =
      run({"bench", "two-color", "--width", "8", "-o", file, "-o", dir + "/o_link.json"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(test::readFile(file).starts_with("rt bench two-color: 8x8, "));
  EXPECT_TRUE(test::readFile(dir + "/other.md").starts_with("{"));
}

/// A scene file of one mesh read from a model file beside it, dir/mesh.json and dir/m.obj (an
/// OBJ triangle in front of the camera, 8x8 pixels).
std::string writeMeshScene(const std::string& dir) {
  test::writeText(dir + "/m.obj", "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
  return test::writeText(
      dir + "/mesh.json",
      R"({"camera": {"location": [0, 0, 0], "to": [0, 0, -1], "up": [0, 1, 0], "vpDistance": 1,
                     "vpSize": [2, 2], "resolution": [8, 8]},
         "geometries": [{"type": "mesh", "file": "m.obj"}]})");
}

TEST(BenchTests, aTableNamingAFileTheSceneReadsIsRefusedBeforeAnyRay) {
  namespace fs = std::filesystem;
  const std::string dir = test::freshTestDirectory("benchOverInput");
  const std::string scene =
      test::writeText(dir + "/s.json", test::readFile(RT_SCENES_DIR "/two-color.json"));
  const std::string original = test::readFile(scene);
  fs::create_symlink("s.json", dir + "/to-scene.md");
  const std::string sceneRefusal = "' is SCENE ('" + scene +
                                   "'): the table would overwrite the scene file it reads; give "
                                   "another file\n";
  // ============ Equivalence Partitions Tests ==============
  // TC01: the scene file itself (once it was overwritten by the table, with exit 0)
  Outcome r = run({"bench", scene, "--width", "8", "-o", scene});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: -o: '" + scene + sceneRefusal);
  EXPECT_EQ(r.out, "");
  // TC02: another name of it (a symbolic link), and the last of several -o
  r = run({"bench", scene, "--width", "8", "-o", dir + "/t.csv", "-o", dir + "/to-scene.md"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: -o: '" + dir + "/to-scene.md" + sceneRefusal);
  EXPECT_EQ(r.out, "");
  // TC03: a model file of the scene, through a link
  if (modelFilesSupported()) {
    const std::string meshScene = writeMeshScene(dir);
    fs::create_symlink("m.obj", dir + "/to-model.md");
    r = run({"bench", meshScene, "--width", "8", "-o", dir + "/to-model.md"});
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "rt: -o: '" + dir + "/to-model.md' is a model file of SCENE ('" + dir +
                         "/m.obj'): the table would overwrite a file the scene reads; give another "
                         "file\n");
    EXPECT_EQ(test::readFile(dir + "/m.obj"), "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
  }
  // TC04: nothing written: the scene as it was, no table, no temporary file
  EXPECT_EQ(test::readFile(scene), original);
  EXPECT_FALSE(fs::exists(dir + "/t.csv"));
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    EXPECT_FALSE(e.path().filename().string().starts_with(".rt-tmp")) << e.path();
  // =============== Boundary Values Tests ==================
  // TC11: a file beside the scene is written
  r = run({"bench", scene, "--width", "8", "-o", dir + "/s.md"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(test::readFile(dir + "/s.md").starts_with("rt bench " + scene + ": 8x8, "));
}

// ---------------------------------------------------------------------------------------------
// The star scaling

TEST(BenchTests, scalingMeasuresEachGalaxyInItsOwnProcess) {
  const Outcome r = run(
      {"bench", "--scaling", "--stars", "1000,2000", "--width", "20", "--height", "20", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  // TC01: the documented header
  EXPECT_EQ(j["scene"], "galaxy");
  EXPECT_EQ(j["width"], 20);
  EXPECT_EQ(j["height"], 20);
  const json& rows = j["scaling"];
  ASSERT_EQ(rows.size(), 2u);
  // TC02: the star counts asked for, and every shape of those galaxies: 21 arms of 48 and of 95
  // positions (stars / 21, rounded), 1008 and 1995, less the suns' empty ones (12 and 33: a
  // tenth of the three sun arms'), plus 69 fixed shapes: the floor, the faces of the pedestal's
  // two boxes and of the glass box (18), the frame's 8 bars of 6 faces (48), the core, its halo
  const long stars[] = {1000, 2000};
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(rows[i]["stars"], stars[i]);
    EXPECT_EQ(rows[i]["shapes"],
              galaxy(GalaxyParams{.stars = stars[i], .diffusion = false}).scene.geometries.size());
    // TC03: a peak of the child's own, and times
    EXPECT_GT(rows[i]["peakBytes"].get<long>(), 0);
    EXPECT_GE(rows[i]["bytesPerStar"].get<long>(), 0);
    EXPECT_GE(rows[i]["buildSeconds"].get<double>(), 0);
    EXPECT_GT(rows[i]["renderSeconds"].get<double>(), 0);
    // TC04: the grid's figures beside the BVH's, from a process of their own; both visit nodes
    EXPECT_GT(rows[i]["gridPeakBytes"].get<long>(), 0);
    EXPECT_GE(rows[i]["gridBytesPerStar"].get<long>(), 0);
    EXPECT_GE(rows[i]["gridBuildSeconds"].get<double>(), 0);
    EXPECT_GT(rows[i]["gridRenderSeconds"].get<double>(), 0);
    EXPECT_GT(rows[i]["nodesPerRay"].get<double>(), 0);
    EXPECT_GT(rows[i]["gridCellsPerRay"].get<double>(), 0);
  }
  EXPECT_EQ(rows[0]["shapes"], 1065);
  EXPECT_EQ(rows[1]["shapes"], 2031);
  // TC05: one progress line per galaxy
  EXPECT_EQ(lines(r.err),
            (std::vector<std::string>{
                "rt bench: galaxy 1/2: 1000 stars, 20x20, " + std::to_string(cores()) +
                    (cores() == 1 ? " thread" : " threads"),
                "rt bench: galaxy 2/2: 2000 stars, 20x20, " + std::to_string(cores()) +
                    (cores() == 1 ? " thread" : " threads")}));
}

TEST(BenchTests, scalingCsvAndMarkdown) {
  // TC01: the CSV header line, exactly, and a line per galaxy
  Outcome r = run({"bench", "--scaling", "--stars", "100", "--width", "8", "--csv"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> out = lines(r.out);
  ASSERT_EQ(out.size(), 2u) << r.out;
  EXPECT_EQ(out[0],
            "stars,shapes,buildSeconds,renderSeconds,peakBytes,bytesPerStar,nodesPerRay,"
            "gridBuildSeconds,gridRenderSeconds,gridPeakBytes,gridBytesPerStar,gridCellsPerRay");
  EXPECT_TRUE(out[1].starts_with("100,")) << out[1];
  // TC02: Markdown: a caption, the header exactly, a line per galaxy
  r = run({"bench", "--scaling", "--stars", "100", "--height", "8"});
  ASSERT_EQ(r.code, 0) << r.err;
  out = lines(r.out);
  ASSERT_EQ(out.size(), 5u) << r.out;
  EXPECT_TRUE(out[0].starts_with("rt bench --scaling: the galaxy without diffusion, 8x8 "))
      << out[0];
  EXPECT_EQ(
      out[2],
      "| stars | shapes | BVH build | BVH render | BVH peak | BVH bytes/star | nodes/ray | grid "
      "build | grid render | grid peak | grid bytes/star | cells/ray |");
  EXPECT_EQ(
      out[3],
      "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
  EXPECT_TRUE(out[4].starts_with("| 100 | ")) << out[4];
}

TEST(BenchTests, scalingTheTeapotMeasuresEachDetailInItsOwnProcess) {
  const Outcome r =
      run({"bench", "--scaling", "teapot", "--details", "4,13", "--width", "20", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  // TC01: the documented header
  EXPECT_EQ(j["scene"], "teapot");
  EXPECT_EQ(j["width"], 20);
  EXPECT_EQ(j["height"], 20);
  const json& rows = j["scaling"];
  ASSERT_EQ(rows.size(), 2u);
  // TC02: each row has exactly the documented keys
  std::vector<std::string> keys{"detail",
                                "triangles",
                                "buildSeconds",
                                "renderSeconds",
                                "peakBytes",
                                "bytesPerTriangle",
                                "nodesPerRay",
                                "gridBuildSeconds",
                                "gridRenderSeconds",
                                "gridPeakBytes",
                                "gridBytesPerTriangle",
                                "gridCellsPerRay"};
  std::sort(keys.begin(), keys.end());
  for (const json& row : rows) {
    std::vector<std::string> got;
    for (const auto& [key, value] : row.items()) got.push_back(key);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, keys);
  }
  // TC03: the details asked for and their triangles, 64·d² − 8·d; a peak of each child's own
  EXPECT_EQ(rows[0]["detail"], 4);
  EXPECT_EQ(rows[0]["triangles"], 992);
  EXPECT_EQ(rows[1]["detail"], 13);
  EXPECT_EQ(rows[1]["triangles"], 10712);
  for (const json& row : rows) {
    EXPECT_GT(row["peakBytes"].get<long>(), 0);
    EXPECT_GT(row["gridPeakBytes"].get<long>(), 0);
    EXPECT_GE(row["bytesPerTriangle"].get<long>(), 0);
    EXPECT_GT(row["renderSeconds"].get<double>(), 0);
    EXPECT_GT(row["gridRenderSeconds"].get<double>(), 0);
    EXPECT_GT(row["nodesPerRay"].get<double>(), 0);
    EXPECT_GT(row["gridCellsPerRay"].get<double>(), 0);
  }
  // TC04: one progress line per teapot
  const std::string threads = std::to_string(cores()) + (cores() == 1 ? " thread" : " threads");
  EXPECT_EQ(lines(r.err),
            (std::vector<std::string>{
                "rt bench: teapot 1/2: detail 4 (992 triangles), 20x20, " + threads,
                "rt bench: teapot 2/2: detail 13 (10712 triangles), 20x20, " + threads}));
  // TC05: CSV: the header line, exactly, and a line per teapot
  Outcome c = run({"bench", "--scaling", "teapot", "--details", "2", "--width", "8", "--csv"});
  ASSERT_EQ(c.code, 0) << c.err;
  std::vector<std::string> out = lines(c.out);
  ASSERT_EQ(out.size(), 2u) << c.out;
  EXPECT_EQ(out[0],
            "detail,triangles,buildSeconds,renderSeconds,peakBytes,bytesPerTriangle,nodesPerRay,"
            "gridBuildSeconds,gridRenderSeconds,gridPeakBytes,gridBytesPerTriangle,"
            "gridCellsPerRay");
  EXPECT_TRUE(out[1].starts_with("2,240,")) << out[1];
  // TC06: Markdown: a caption, the header exactly, a line per teapot
  c = run({"bench", "--scaling", "teapot", "--details", "2", "--width", "8"});
  ASSERT_EQ(c.code, 0) << c.err;
  out = lines(c.out);
  ASSERT_EQ(out.size(), 5u) << c.out;
  EXPECT_TRUE(
      out[0].starts_with("rt bench --scaling teapot: the course's teapot of 64*d^2 - 8*d "
                         "flat triangles (detail d), 8x8 (the course's view), Whitted "
                         "tracer, through the BVH and through the grid, "))
      << out[0];
  EXPECT_TRUE(out[0].ends_with(" of an empty process) / triangles")) << out[0];
  EXPECT_EQ(out[2],
            "| detail | triangles | BVH build | BVH render | BVH peak | BVH bytes/triangle | "
            "nodes/ray | grid build | grid render | grid peak | grid bytes/triangle | cells/ray |");
  EXPECT_TRUE(out[4].starts_with("| 2 | 240 | ")) << out[4];
}

// ---------------------------------------------------------------------------------------------
// Usage errors, all before the first ray

TEST(BenchTests, badUsageExitsWithTwoBeforeAnyRay) {
  struct Case {
    const char* partition;
    std::vector<std::string> args;
    std::string message;
  };
  const std::string directory = test::freshDirectory("benchOutputIsADirectory");
  const std::vector<Case> cases = {
      // TC01: no renders at all
      {"TC01",
       {"bench", "--repeat", "0"},
       "rt: --repeat: expected an integer from 1 to 1000, got '0'\n"},
      // TC02: a galaxy without stars
      {"TC02",
       {"bench", "--scaling", "--stars", "1000,0"},
       "rt: --stars: expected an integer from 1 to 10000000, got '0'\n"},
      // TC03: a star list with an empty item
      {"TC03",
       {"bench", "--scaling", "--stars", "1000,"},
       "rt: --stars: expected an integer from 1 to 10000000, got ''\n"},
      // TC04: a file ending that names no format
      {"TC04",
       {"bench", "-o", "x.txt"},
       "rt: -o: the table's format follows the name's ending, which must be .md (Markdown), .csv "
       "or .json; got 'x.txt'\n"},
      // TC05: a format flag and another ending
      {"TC05",
       {"bench", "--json", "-o", "x.csv"},
       "rt: -o: --json writes JSON, so the name must end in .json; got 'x.csv'\n"},
      // TC06: two formats
      {"TC06",
       {"bench", "--csv", "--json"},
       "rt: --csv and --json: give one of them (Markdown without either)\n"},
      // TC07: -o naming a directory
      {"TC07",
       {"bench", "-o", directory},
       "rt: -o: cannot write '" + directory + "': it is a directory\n"},
      // TC08: an unknown scene
      {"TC08",
       {"bench", "galaxi"},
       "rt: unknown scene 'galaxi'; did you mean 'galaxy'? (rt list shows the built-in scenes; a "
       "scene file ends in .json)\n"},
      // TC09: the rows choose the acceleration
      {"TC09",
       {"bench", "--accel", "bvh"},
       "rt: unknown option '--accel' for rt bench (see rt bench --help)\n"},
      // TC10: --full and a size
      {"TC10",
       {"bench", "--full", "--width", "64"},
       "rt: --full: the scene's own resolution; give either --full or --width/--height\n"},
      // TC11: --stars without --scaling
      {"TC11",
       {"bench", "--stars", "1000"},
       "rt: --stars: only with --scaling (the galaxy's star counts)\n"},
      // TC12: the scaling of another scene
      {"TC12",
       {"bench", "two-color", "--scaling"},
       "rt: --scaling: renders the built-in galaxy or teapot only, got 'two-color'\n"},
      // TC13: the scaling with an option that would change its render
      {"TC13",
       {"bench", "--scaling", "--tracer", "phong"},
       "rt: --tracer: not with --scaling (it renders the galaxy of --stars stars without "
       "diffusion, beams tracer, BVH and grid)\n"},
      // TC14: a bad parameter of the galaxy
      {"TC14",
       {"bench", "--param", "stars=-1"},
       "rt: --param stars: expected an integer from 0 to 10000000, got '-1'\n"},
      // TC16: --details without --scaling
      {"TC16",
       {"bench", "teapot", "--details", "4"},
       "rt: --details: only with --scaling teapot (the teapot's details)\n"},
      // TC17: the galaxy's scaling with the teapot's details, and the teapot's with stars
      {"TC17",
       {"bench", "--scaling", "--details", "4"},
       "rt: --details: not with --scaling (it renders the galaxy of --stars stars without "
       "diffusion, beams tracer, BVH and grid)\n"},
      {"TC18",
       {"bench", "--scaling", "teapot", "--stars", "1000"},
       "rt: --stars: not with --scaling teapot (it renders the teapot of --details details, flat, "
       "Whitted tracer, BVH and grid)\n"},
      // TC19: the teapot's scaling with a parameter
      {"TC19",
       {"bench", "--scaling", "teapot", "--param", "smooth=on"},
       "rt: --param: not with --scaling teapot (it renders the teapot of --details details, flat, "
       "Whitted tracer, BVH and grid)\n"},
      // TC15: too many threads
      {"TC15",
       {"bench", "--threads", "1025"},
       "rt: --threads: expected an integer from 0 to 1024, got '1025'\n"},
      // TC21: one beyond the most repeats
      {"TC21",
       {"bench", "--repeat", "1001"},
       "rt: --repeat: expected an integer from 1 to 1000, got '1001'\n"},
      // TC23: a detail of 0, and one beyond the most
      {"TC23",
       {"bench", "--scaling", "teapot", "--details", "4,0"},
       "rt: --details: expected an integer from 1 to 256, got '0'\n"},
      {"TC24",
       {"bench", "--scaling", "teapot", "--details", "257"},
       "rt: --details: expected an integer from 1 to 256, got '257'\n"},
      // TC22: one beyond the most stars
      {"TC22",
       {"bench", "--scaling", "--stars", "10000001"},
       "rt: --stars: expected an integer from 1 to 10000000, got '10000001'\n"},
  };
  for (const Case& c : cases) {
    const Outcome r = run(c.args);
    EXPECT_EQ(r.code, 2) << c.partition;
    EXPECT_EQ(r.err, c.message) << c.partition;
    EXPECT_EQ(r.out, "") << c.partition;
  }
}

TEST(BenchTests, helpShowsTheSceneAsOptional) {
  const Outcome r = run({"bench", "--help"});
  EXPECT_EQ(r.code, 0);
  // TC01: SCENE may be left out (the galaxy); the options are listed
  EXPECT_TRUE(r.out.starts_with("Usage: rt bench [SCENE] [OPTIONS]\n")) << r.out;
  for (const char* text : {"--full", "--repeat N", "--csv", "--json", "--scaling", "--stars LIST",
                           "--details LIST", "--threads N", "-o, --output", "130"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
  EXPECT_EQ(r.out.find("--accel"), std::string::npos);
  // TC02: rt --help lists the command
  EXPECT_NE(run({"--help"}).out.find("\n  bench "), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Ctrl-C

TEST(BenchTests, stopBeforeTheFirstRowWritesNothing) {
  const std::string dir = test::freshDirectory("benchStopped");
  const std::string out = dir + "/bench.csv";
  { std::ofstream(out) << "the previous table"; }
  const std::atomic<bool> stop{true};
  // TC01: the table: exit 130 before the first row, the files untouched
  Outcome r = run({"bench", "two-color", "--width", "8", "-o", out, "-o", dir + "/b.md"}, &stop);
  EXPECT_EQ(r.code, 130);
  EXPECT_EQ(r.err, "rt: interrupted at row 1 of " + std::to_string(expectedNames().size()) +
                       "; nothing written to " + out + ", " + dir + "/b.md\n");
  EXPECT_EQ(test::readFile(out), "the previous table");
  // TC02: the scaling: its first child is stopped
  r = run({"bench", "--scaling", "--stars", "100", "--width", "8"}, &stop);
  EXPECT_EQ(r.code, 130);
  EXPECT_EQ(r.err, "rt: interrupted at the start; nothing written\n");
  EXPECT_EQ(r.out, "");
}

TEST(BenchProcessTests, ctrlCStopsTheBenchWithinARow) {
  // TC01: the reference report's size, whose first row takes minutes: SIGINT once it has started
  test::RtChild child({"bench", "--full", "--csv"});
  ASSERT_TRUE(child.waitForLine("rt bench: row 1/")) << child.err();
  child.signal(SIGINT);
  EXPECT_EQ(child.wait(), 130) << child.err();
  EXPECT_TRUE(child.err().ends_with("rt: interrupted at row 1 of " +
                                    std::to_string(expectedNames().size()) + "; nothing written\n"))
      << child.err();
}

TEST(BenchProcessTests, ctrlCStopsTheScalingsChildProcess) {
  // TC01: SIGINT to rt alone (not to its process group): rt stops its measuring child itself
  test::RtChild scaling({"bench", "--scaling", "--stars", "1000000", "--width", "2000"});
  ASSERT_TRUE(scaling.waitForLine("rt bench: galaxy 1/1")) << scaling.err();
  scaling.signal(SIGINT);
  EXPECT_EQ(scaling.wait(), 130) << scaling.err();
  EXPECT_TRUE(scaling.err().ends_with(
      "rt: interrupted at galaxy 1 of 1 (1000000 stars); nothing written\n"))
      << scaling.err();
}

}  // namespace
}  // namespace rt::cli
