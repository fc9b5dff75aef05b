// rt bench [SCENE] [--full] [--repeat N] [--csv | --json] [-o FILE] [the scene options of render]
// rt bench --scaling [--stars LIST] [--width W] [--height H] [--threads N] [--repeat N] [...]
//
// The timing table of the course: one scene rendered with the seed report's rows (no
// acceleration on one thread; threads; threads + CBR; threads + CBR + BVH) beside the seed's own
// times, then by every stage's tracer through the BVH on every thread; or the galaxy's star
// scaling, each galaxy measured in a process of its own (bvh/Measure.h, which
// mini2_render_bench uses too).
#include "Bench.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/App.hpp>

#include "BenchTable.h"
#include "CommandTable.h"
#include "bvh/Acceleration.h"
#include "bvh/Measure.h"
#include "bvh/TilePool.h"
#include "camera/AtomicFile.h"
#include "camera/Camera.h"
#include "cli/CommandLine.h"
#include "cli/Registry.h"
#include "cli/Tracers.h"
#include "cli/Values.h"
#include "common/Integers.h"

namespace rt::cli {

namespace {

/// The default image's width: the galaxy at 128 x 72, a hundredth of the seed's 1280 x 720
/// pixels, renders the whole table in 2 min 20 s on two loaded cores (160 x 90 took 5 min 30 s);
/// --full: the scene's own resolution, the seed's for the galaxy.
constexpr int DEFAULT_WIDTH = 128;
/// The scaling's image: the middle of the seed's view, as mini2_render_bench's.
constexpr int SCALING_SIDE = 400;
constexpr int MAX_REPEAT = 1000;
constexpr const char* DEFAULT_STARS = "1000,10000,100000,1000000";

/// rt bench's arguments, as the command line binds them.
struct BenchArgs {
  SceneArguments scene;
  bool full = false;
  int repeat = 1;
  bool csv = false, json = false;
  std::vector<std::string> outputs;  ///< -o FILE, repeatable: one run, several files
  bool scaling = false;
  std::optional<std::string> stars;
};

/// The seed report's rows and times: its galaxy at 1280 x 720 (course catalogue §5).
struct SeedRow {
  const char* name;
  const char* accel;
  bool threads;        ///< every core, or one thread
  double seedSeconds;  ///< the seed report's time
};
constexpr SeedRow SEED_ROWS[] = {
    {"no acceleration", "none", false, 4860},   // 1 h 21 min
    {"threads", "none", true, 1540},            // 25 min 40 s
    {"threads + CBR", "cbr", true, 837},        // 13 min 57 s
    {"threads + CBR + BVH", "bvh", true, 407},  // 6 min 47 s
};

// ---- The output: its format and its file ----

/// A format's file ending, and the rule a file named with another breaks when the format is
/// asked for by its flag.
OutputKind outputKindOf(TableFormat format) {
  switch (format) {
    case TableFormat::Csv:
      return {".csv", "--csv writes CSV, so the name must end in .csv"};
    case TableFormat::Json:
      return {".json", "--json writes JSON, so the name must end in .json"};
    case TableFormat::Markdown:
      break;
  }
  return {".md", "Markdown is the default, so the name must end in .md"};
}

/// Where the table goes: stdout, or each -o file, in its format.
struct Destinations {
  TableFormat stdoutFormat = TableFormat::Markdown;  ///< when there is no -o
  std::vector<std::pair<std::string, TableFormat>> files;
};

/// The format of one -o file: the flag's (its ending must agree), else its ending's; the path
/// checked writable before any work. @throws UsageError.
TableFormat fileFormat(const std::string& path, std::optional<TableFormat> flag) {
  if (flag) {
    checkOutputWritable(path, outputKindOf(*flag));
    return *flag;
  }
  for (const TableFormat f : {TableFormat::Markdown, TableFormat::Csv, TableFormat::Json}) {
    const OutputKind kind = outputKindOf(f);
    if (path.ends_with(kind.ending)) {
      checkOutputWritable(path, kind);
      return f;
    }
  }
  // A directory, a missing parent, or the ending: checkOutputWritable names what is wrong.
  checkOutputWritable(path, {".md",
                             "the table's format follows the name's ending, which must be .md "
                             "(Markdown), .csv or .json"});
  return TableFormat::Markdown;  // not reached: the path does not end in .md
}

/// The table's destinations: stdout in --csv's or --json's format (Markdown without either), or
/// every -o file in its own. @throws UsageError.
Destinations chooseDestinations(const BenchArgs& args) {
  if (args.csv && args.json)
    throw UsageError("--csv and --json: give one of them (Markdown without either)");
  const std::optional<TableFormat> flag = args.csv    ? std::optional(TableFormat::Csv)
                                          : args.json ? std::optional(TableFormat::Json)
                                                      : std::nullopt;
  Destinations d;
  d.stdoutFormat = flag.value_or(TableFormat::Markdown);
  for (const std::string& path : args.outputs) d.files.emplace_back(path, fileFormat(path, flag));
  return d;
}

/// Prints the table, or writes it to each -o file (whole or not at all). format turns the
/// table into text in a format.
template <typename Format>
void emit(const Destinations& d, const Format& format, const Io& io) {
  if (d.files.empty()) {
    io.out << format(d.stdoutFormat) << std::flush;
    return;
  }
  for (const auto& [path, f] : d.files) {
    writeFileAtomically(path, format(f));
    io.err << "rt bench: wrote " << path << "\n";
  }
}

/// "AMD EPYC 7B13, 2 CPUs": /proc/cpuinfo's first model name and the CPUs std::thread sees.
std::string machineName() {
  std::string model;
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; model.empty() && std::getline(in, line);) {
    if (!line.starts_with("model name")) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    model = line.substr(line.find_first_not_of(" \t", colon + 1));
  }
  if (model.empty()) model = "unknown CPU";
  const unsigned cpus = std::max(1u, std::thread::hardware_concurrency());
  return model + ", " + std::to_string(cpus) + (cpus == 1 ? " CPU" : " CPUs");
}

/// The threads of the multi-threaded rows: --threads, 0 (the default) meaning every core.
int threadsOf(const BenchArgs& args) {
  const int asked = args.scene.settings.threads.value_or(0);
  return asked > 0 ? asked : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

std::string threadsText(int n) { return std::to_string(n) + (n == 1 ? " thread" : " threads"); }

int interrupted(const std::string& where, const BenchArgs& args, const Io& io) {
  io.err << "rt: interrupted at " << where << "; nothing written";
  for (std::size_t i = 0; i < args.outputs.size(); ++i)
    io.err << (i == 0 ? " to " : ", ") << args.outputs[i];
  io.err << "\n";
  return EXIT_INTERRUPTED;
}

// ---- The timing table ----

/// A row ready to render: its tracer built over the scene and its acceleration.
struct PlannedRow {
  BenchRow row;
  std::unique_ptr<RayTracer> tracer;
};

int benchRows(const BenchArgs& args, const Destinations& to, const Io& io) {
  if (args.stars) throw UsageError("--stars: only with --scaling (the galaxy's star counts)");
  SceneArguments sceneArgs = args.scene;
  if (args.full && (sceneArgs.width || sceneArgs.height))
    throw UsageError("--full: the scene's own resolution; give either --full or --width/--height");
  if (!args.full && !sceneArgs.width && !sceneArgs.height) sceneArgs.width = DEFAULT_WIDTH;
  const RenderRequest request = resolveRenderRequest(sceneArgs, {.makesImage = true});
  const SceneDocument& doc = request.doc;
  const int threads = threadsOf(args);

  // The rows: the seed's four with the scene's tracer, then every stage's tracer through the BVH
  // (stage 4's debugging views left out: they do not render the scene's light).
  // The seed's times belong to its galaxy only.
  const bool seedScene = args.scene.argument == "galaxy";
  const TracerKind& sceneTracer = findTracer(doc.render.tracer);
  std::vector<std::pair<BenchRow, const TracerKind*>> plan;
  for (const SeedRow& s : SEED_ROWS)
    plan.push_back(
        {BenchRow{.name = s.name,
                  .tracer = sceneTracer.name,
                  .accel = s.accel,
                  .threads = s.threads ? threads : 1,
                  .seedSeconds = seedScene ? std::optional(s.seedSeconds) : std::nullopt},
         &sceneTracer});
  for (const TracerKind& kind : tracerKinds())
    if (!kind.debugView)
      plan.push_back(
          {BenchRow{.name = kind.stage, .tracer = kind.name, .accel = "bvh", .threads = threads},
           &kind});

  // Every structure before the first ray: one acceleration of each kind used, the tracers, the
  // sampler, the camera and its image (which every row renders into).
  std::map<std::string, std::unique_ptr<Intersectable>> accelerations;
  for (const auto& [row, kind] : plan)
    if (!accelerations.contains(row.accel))
      accelerations[row.accel] = makeAcceleration(row.accel, doc.scene->geometries);
  std::vector<PlannedRow> rows;
  for (auto& [row, kind] : plan) {
    std::unique_ptr<RayTracer> tracer = kind->make(doc, accelerations.at(row.accel).get());
    rows.push_back({std::move(row), std::move(tracer)});
  }
  const std::unique_ptr<PixelSampler> sampler = cliRegistry().makeSampler(doc.render);
  Camera camera = doc.camera.builder().build();
  Image& image = camera.image();

  // Round robin: repeat r renders every row once, so that a change of the machine's load hits
  // every row alike; each row's time is the median of its renders.
  std::vector<std::vector<double>> seconds(rows.size());
  const std::size_t n = rows.size();
  for (int r = 0; r < args.repeat; ++r)
    for (std::size_t i = 0; i < n; ++i) {
      BenchRow& row = rows[i].row;
      const std::string where = "row " + std::to_string(i + 1) + " of " + std::to_string(n);
      if (io.stop && io.stop->load()) return interrupted(where, args, io);
      io.err << "rt bench: row " << i + 1 << "/" << n;
      if (args.repeat > 1) io.err << ", repeat " << r + 1 << "/" << args.repeat;
      io.err << ": " << row.name << " (tracer " << row.tracer << ", accel " << row.accel << ", "
             << threadsText(row.threads) << ")" << std::endl;
      RenderOptions options;
      options.threads = row.threads;
      options.stop = io.stop;
      const RenderResult result = renderImage({camera, *rows[i].tracer, *sampler}, image, options);
      if (result.interrupted || (io.stop && io.stop->load())) return interrupted(where, args, io);
      seconds[i].push_back(result.seconds);
      row.counts = result.counts;  // the same every repeat: the render is deterministic
      row.threads = result.threads;
    }

  BenchTable table{.scene = args.scene.argument,
                   .width = doc.camera.nX,
                   .height = doc.camera.nY,
                   .threads = threads,
                   .machine = machineName(),
                   .repeat = args.repeat};
  for (std::size_t i = 0; i < n; ++i) {
    rows[i].row.seconds = median(seconds[i]);
    table.rows.push_back(rows[i].row);
  }
  emit(
      to, [&table](TableFormat f) { return formatBenchTable(table, f); }, io);
  return EXIT_OK;
}

// ---- The star scaling ----

/// "1000,10000" → {1000, 10000}, each from 1 to GalaxyParams::MAX_STARS. Returns the message of
/// the first bad item (without the option's name), or the list.
std::string starsError(const std::string& list, std::vector<long>* stars = nullptr) {
  constexpr int maxStars = static_cast<int>(GalaxyParams::MAX_STARS);
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    const std::optional<int> value = integerInText(item, 1, maxStars);
    if (!value) return integerError(item, 1, maxStars);
    if (stars) stars->push_back(*value);
    if (comma == list.size()) return {};
    start = comma + 1;
  }
}

/// What the child process measuring one galaxy sends back.
struct GalaxyFigures {
  std::uint64_t shapes = 0;
  double buildSeconds = 0, renderSeconds = 0;
  bool interrupted = false;
};

int benchScaling(const BenchArgs& args, const Destinations& to, const Io& io) {
  // The scaling renders the galaxy of --stars stars, without diffusion, with the beams tracer:
  // the options that would choose another scene or render are refused, by name.
  const SceneArguments& s = args.scene;
  if (!s.argument.empty() && s.argument != "galaxy")
    throw UsageError("--scaling: renders the built-in galaxy only, got '" + s.argument + "'");
  const char* refused = !s.params.empty() ? "--param"
                        : s.view          ? "--view"
                        : s.tracer        ? "--tracer"
                        : s.seed          ? "--seed"
                        : args.full       ? "--full"
                                          : nullptr;
  if (refused)
    throw UsageError(std::string(refused) +
                     ": not with --scaling (it renders the galaxy of --stars stars without "
                     "diffusion, beams tracer, BVH)");
  std::vector<long> stars;
  starsError(args.stars.value_or(DEFAULT_STARS), &stars);  // checked when parsed
  // A side given alone makes the image square too.
  const int nX = s.width.value_or(s.height.value_or(SCALING_SIDE));
  const int nY = s.height.value_or(s.width.value_or(SCALING_SIDE));
  checkImageFits(nX, nY);
  const int threads = threadsOf(args);

  ScalingTable table{.width = nX,
                     .height = nY,
                     .threads = threads,
                     .machine = machineName(),
                     .repeat = args.repeat};
  // The baseline: what a child shares with this process at the fork, and its own start.
  const std::optional<std::int64_t> baseline =
      runInChildProcess([](std::span<std::byte>) {}, {}, io.stop);
  if (!baseline) return interrupted("the start", args, io);
  table.baselineBytes = *baseline;
  for (std::size_t i = 0; i < stars.size(); ++i) {
    const long n = stars[i];
    const std::string where = "galaxy " + std::to_string(i + 1) + " of " +
                              std::to_string(stars.size()) + " (" + std::to_string(n) + " stars)";
    io.err << "rt bench: galaxy " << i + 1 << "/" << stars.size() << ": " << n << " stars, " << nX
           << "x" << nY << ", " << threadsText(threads) << std::endl;
    const std::atomic<bool>* stop = io.stop;
    const int repeat = args.repeat;
    const auto measured = measureInChildProcess<GalaxyFigures>(
        [n, nX, nY, threads, repeat, stop] {
          const GalaxyRender g(GalaxyParams{.stars = n, .diffusion = false});
          const Camera camera = seedView(g.setup, nX, nY);
          const CenterSampler sampler;
          Image image(nX, nY);
          GalaxyFigures f{.shapes = g.setup.scene.geometries.size(),
                          .buildSeconds = g.buildSeconds};
          std::vector<double> seconds;
          for (int r = 0; r < repeat && !f.interrupted; ++r) {
            const RenderResult result = renderImage({camera, *g.tracer, sampler}, image,
                                                    {.threads = threads, .stop = stop});
            seconds.push_back(result.seconds);
            f.interrupted = result.interrupted;
          }
          f.renderSeconds = median(seconds);
          return f;
        },
        io.stop);
    if (!measured || measured->value.interrupted) return interrupted(where, args, io);
    const GalaxyFigures& f = measured->value;
    const std::int64_t grown = std::max<std::int64_t>(0, measured->peakBytes - *baseline);
    table.rows.push_back(
        {.stars = n,
         .shapes = f.shapes,
         .buildSeconds = f.buildSeconds,
         .renderSeconds = f.renderSeconds,
         .peakBytes = measured->peakBytes,
         .bytesPerStar = std::llround(static_cast<double>(grown) / static_cast<double>(n))});
  }
  emit(
      to, [&table](TableFormat f) { return formatScalingTable(table, f); }, io);
  return EXIT_OK;
}

int bench(const BenchArgs& args, const Io& io) {
  const Destinations to = chooseDestinations(args);
  return args.scaling ? benchScaling(args, to, io) : benchRows(args, to, io);
}

}  // namespace

void addBenchCommand(CommandLine& rt) {
  const auto [command, args] = rt.addCommand(
      "bench", "time one scene across stages and accelerations, in one table",
      "Renders SCENE (default: the built-in galaxy, 128 pixels wide; --full: the scene's own\n"
      "resolution, the seed's 1280x720 for the galaxy) with the seed report's rows, its own\n"
      "times beside them for the galaxy: no acceleration on one thread; threads; threads +\n"
      "CBR; threads + CBR + BVH; then with every stage's tracer through the BVH on every\n"
      "thread. Columns: row, tracer, accel, threads (that rendered), wall time, the seed's\n"
      "time, primary, secondary and shadow rays, rays per second (every ray), BVH nodes\n"
      "visited per ray, speed-up over the first row. Markdown by default, --csv or --json,\n"
      "or by -o's ending (.md, .csv, .json); the file is written whole or not at all.\n\n"
      "--scaling renders the galaxy without diffusion with 10^3, 10^4, 10^5 and 10^6 stars\n"
      "(--stars LIST) at 400x400 through the BVH on every thread, each in a process of its\n"
      "own, and prints the BVH's build time (CPU), the render's wall time, the process's peak\n"
      "resident size and the bytes per star ((peak - an empty process's peak) / stars).\n\n"
      "Everything is checked before the first ray. A line per row started goes to stderr,\n"
      "the table to stdout (or -o's file). Ctrl-C stops the bench within a row, writes\n"
      "nothing, and exits with code 130. Wall times on a loaded machine are noisy: compare\n"
      "the rows of one run, and give --repeat N for medians (rows taken in turn).\n",
      bench);
  addSceneArguments(*command, args->scene,
                    "image width in pixels, 1..32768 (default: 128; the scaling's 400)",
                    "image height in pixels, 1..32768 (default: the scene's aspect ratio)",
                    "the tracer of the first four rows (default: the scene's)");
  // The rows choose the acceleration themselves; SCENE may be left out (the galaxy).
  command->remove_option(command->get_option("--accel"));
  command->get_option("--threads")
      ->description("threads of the multi-threaded rows, 0..1024 (default 0: one per core)");
  command->get_option("SCENE")->default_str("galaxy");
  args->scene.argument = "galaxy";
  command->add_flag("--full", args->full,
                    "the scene's own resolution (the galaxy's: the seed's 1280x720)");
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
                   "repeatable (one run, several files)")
      ->type_name("FILE.md|.csv|.json")
      ->allow_extra_args(false);  // one file per -o: `-o x.md galaxy` leaves SCENE alone
  command->add_flag("--scaling", args->scaling,
                    "the galaxy's star scaling instead of the timing table");
  addOptional(*command, "--stars", args->stars,
              "with --scaling: the star counts, comma-separated, each 1..10000000 (default: "
              "1000,10000,100000,1000000)",
              "LIST")
      ->check(CLI::Validator([](std::string& list) { return starsError(list); }, ""));
}

}  // namespace rt::cli
