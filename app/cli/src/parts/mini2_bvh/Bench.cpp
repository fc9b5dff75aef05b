// rt bench [SCENE] [--full] [--repeat N] [--csv | --json] [-o FILE] [the scene options of render]
// rt bench --scaling [--stars LIST] [--width W] [--height H] [--threads N] [--repeat N] [...]
// rt bench --scaling teapot [--details LIST] [...]
//
// The command's registration: its options, its help, and which of the two it runs (the timing
// table: BenchRows.cpp; the scalings: BenchScaling.cpp).
#include "Bench.h"

#include <algorithm>
#include <string>
#include <thread>

#include <CLI/App.hpp>

#include "BenchOutput.h"
#include "cli/CommandLine.h"
#include "cli/Values.h"
#include "geometries/UtahTeapot.h"
#include "glossy/Galaxy.h"
#include "parallel/TilePool.h"

namespace rt::cli {

namespace {

constexpr int MAX_REPEAT = 1000;

int bench(const BenchArgs& args, const Io& io) {
  const Destinations to = chooseDestinations(args);
  return args.scaling ? benchScaling(args, to, io) : benchRows(args, to, io);
}

}  // namespace

int benchThreads(const BenchArgs& args) {
  const int asked = args.scene.settings.threads.value_or(0);
  if (asked > 0) return asked;
  const unsigned cores = std::thread::hardware_concurrency();  // 0 when unknown
  return static_cast<int>(std::clamp(cores, 1u, unsigned{RenderOptions::MAX_THREADS}));
}

std::string threadsText(int n) { return std::to_string(n) + (n == 1 ? " thread" : " threads"); }

int benchInterrupted(const std::string& where, const BenchArgs& args, const Io& io) {
  io.err << "rt: interrupted at " << where << "; nothing written";
  for (std::size_t i = 0; i < args.outputs.size(); ++i)
    io.err << (i == 0 ? " to " : ", ") << args.outputs[i];
  io.err << "\n";
  return EXIT_INTERRUPTED;
}

void addBenchCommand(CommandLine& rt) {
  const auto [command, args] = rt.addCommand(
      "bench", "time one scene across stages and accelerations, in one table",
      "Renders SCENE (default: the built-in galaxy, 128 pixels wide; --full: the scene's own\n"
      "resolution, the reference report's 1280x720 for the galaxy) with the reference\n"
      "report's rows, its own times beside them for the galaxy: no acceleration on one\n"
      "thread; threads; threads + CBR; threads + CBR + BVH; then threads + wide BVH, + wide\n"
      "BVH + light buffers and + grid (no report times); Embree 3 (Intel's Embree, a\n"
      "measuring stick, where the build has it: install libembree-dev, scripts/deps.sh\n"
      "--embree, and reconfigure); all of these with the scene's tracer (or --tracer's); then\n"
      "every stage's tracer through the wide BVH with light buffers on every thread.\n"
      "The course's teapot and bubbles have the rows of the course lecturer's TeapotTest\n"
      "instead, his times beside them (in Java, on his machine): no acceleration on one\n"
      "thread; 2, 3 and 4 threads; threads (every core); then threads + CBR, + CBR + BVH,\n"
      "+ wide BVH, + wide BVH + light buffers, + grid, Embree 3, and every stage's tracer.\n"
      "Columns: row, tracer, accel, threads (that\n"
      "rendered), wall time, the reference report's time, primary, secondary and shadow rays,\n"
      "rays per second (every ray), BVH nodes (grid cells) visited per ray, speed-up over the\n"
      "first row, pixels differing from the first row's image (rows of its tracer; Embree's\n"
      "float tests make a few differ), a note. "
      "Markdown by "
      "default, --csv or --json,\n"
      "or by -o's ending (.md, .csv, .json); the file is written whole or not at all.\n\n"
      "--scaling renders the galaxy without diffusion with 10^3, 10^4, 10^5 and 10^6 stars\n"
      "(--stars LIST) at 400x400 through the BVH and through the grid on every thread, each in\n"
      "a process of its own, and prints for each the build's wall time (the BVH builds on every\n"
      "core), the render's wall time,\n"
      "the process's peak resident size, the bytes per star ((peak - an empty process's peak)\n"
      "/ stars) and the nodes (cells) visited per ray. --scaling teapot does the same for the\n"
      "course's teapot of about 10^3, 10^4, 10^5 and 10^6 flat triangles (--details LIST, the\n"
      "teapot's detail d: 64*d^2 - 8*d triangles), Whitted tracer, bytes per triangle.\n\n"
      "Everything is checked before the first ray. A line per row started goes to stderr,\n"
      "the table to stdout (or -o's file). Ctrl-C stops the bench within a row, writes\n"
      "nothing, and exits with code 130. Wall times on a loaded machine are noisy: compare\n"
      "the rows of one run, and give --repeat N for medians (rows taken in turn).\n",
      bench);
  addSceneArguments(*command, args->scene,
                    "image width in pixels, 1..32768 (default: 128; the scaling's 400)",
                    "image height in pixels, 1..32768 (default: the scene's aspect ratio)",
                    "the tracer of the rows before the stages' (default: the scene's)");
  // The rows choose the acceleration themselves; SCENE may be left out (the galaxy).
  command->remove_option(command->get_option("--accel"));
  command->get_option("--threads")
      ->description("threads of the multi-threaded rows, 0..1024 (default 0: one per core)");
  command->get_option("SCENE")->default_str("galaxy");
  args->scene.argument = "galaxy";
  command->add_flag("--full", args->full,
                    "the scene's own resolution (the galaxy's: the reference report's 1280x720)");
  command
      ->add_option("--repeat", args->repeat,
                   "renders per row, 1..1000; the table gives their medians (default: 1)")
      ->type_name("N")
      ->transform(integerValidator(1, MAX_REPEAT));
  command->add_flag("--csv", args->csv, "the table as CSV");
  command->add_flag("--json", args->json, "the table as JSON");
  command
      ->add_option("-o,--output", args->outputs,
                   "write the table to FILE instead of stdout, in the format of its ending; "
                   "repeatable (one run, several files; each file once)")
      ->type_name("FILE.md|.csv|.json")
      ->allow_extra_args(false);  // one file per -o: `-o x.md galaxy` leaves SCENE alone
  command->add_flag("--scaling", args->scaling,
                    "the galaxy's star scaling (SCENE teapot: the teapot's triangle scaling) "
                    "instead of the timing table");
  addOptional(*command, "--stars", args->stars,
              "with --scaling: the star counts, comma-separated, each 1..10000000 (default: " +
                  std::string(DEFAULT_STARS) + ")",
              "LIST")
      ->check(CLI::Validator(
          [](std::string& list) {
            return integerListError(list, 1, static_cast<int>(GalaxyParams::MAX_STARS));
          },
          ""));
  addOptional(*command, "--details", args->details,
              "with --scaling teapot: the teapot's details, comma-separated, each 1.." +
                  std::to_string(kUtahTeapotMaxDetail) +
                  " (default: " + std::string(DEFAULT_DETAILS) + ")",
              "LIST")
      ->check(CLI::Validator(
          [](std::string& list) { return integerListError(list, 1, kUtahTeapotMaxDetail); }, ""));
}

}  // namespace rt::cli
