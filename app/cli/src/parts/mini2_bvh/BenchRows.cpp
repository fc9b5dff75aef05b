// rt bench's timing table: one scene rendered with the reference report's rows (no acceleration
// on one thread; threads; threads + CBR; threads + CBR + BVH) beside the report's own times and
// the course's other structure, the regular grid, beside them (threads + grid, no report time),
// the wide BVH alone and with a light buffer per point light for the shadow rays (the default),
// Intel's Embree 3 after them (a measuring stick, where the build has Embree), then by every
// stage's tracer through the BVH on every thread; rows taken in turn, the medians
// kept. The course's teapots have their lecturer's rows instead, his thread counts and times.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "Bench.h"
#include "BenchOutput.h"
#include "BenchTable.h"
#include "benchmark/Measure.h"
#include "bvh/Acceleration.h"
#include "camera/Camera.h"
#include "cli/Registry.h"
#include "cli/Tracers.h"
#include "lighting/LitScene.h"
#include "parallel/TilePool.h"
#if RT_HAVE_EMBREE
#include "embree/EmbreeScene.h"
#endif

namespace rt::cli {

namespace {

/// The default image's width: the galaxy at 128 x 72, a hundredth of the reference report's
/// 1280 x 720 pixels, renders the whole table in 2 min 20 s on two loaded cores (160 x 90 took
/// 5 min 30 s); --full: the scene's own resolution, the report's for the galaxy.
constexpr int DEFAULT_WIDTH = 128;

/// A row's threads: every core (--threads, default one per core), or a fixed count.
constexpr int EVERY_CORE = 0;

/// A row's accel with light buffers for its shadow rays (render.lightBuffers): the name and this.
constexpr std::string_view WITH_LIGHT_BUFFERS = "+lights";

/// Intel's Embree 3 (mini2_bvh/include/embree/EmbreeScene.h): a row after the project's
/// structures, a measuring stick; in a build without Embree, the row says how to get it.
constexpr const char* EMBREE_ROW = "Embree 3";
constexpr const char* EMBREE_ACCEL = "embree";

/// A row of the scene's tracer beside someone's time for the same configuration.
struct ReferenceRow {
  const char* name;
  const char* accel;
  int threads;                    ///< EVERY_CORE, or that many
  std::optional<double> seconds;  ///< the reference's time
};

/// The reference report's rows and times (the Java project the course started from): its galaxy
/// at 1280 x 720 (course catalogue §5); then the wide BVH and the regular grid, which the report
/// did not have, and Embree.
/// Every scene but the teapots has these rows (without the times).
constexpr ReferenceRow REPORT_ROWS[] = {
    {"no acceleration", "none", 1, 4860},             // 1 h 21 min
    {"threads", "none", EVERY_CORE, 1540},            // 25 min 40 s
    {"threads + CBR", "cbr", EVERY_CORE, 837},        // 13 min 57 s
    {"threads + CBR + BVH", "bvh", EVERY_CORE, 407},  // 6 min 47 s
    {"threads + wide BVH", "bvh4", EVERY_CORE, std::nullopt},
    {"threads + wide BVH + light buffers", "bvh4+lights", EVERY_CORE, std::nullopt},
    {"threads + grid", "grid", EVERY_CORE, std::nullopt},
    {EMBREE_ROW, EMBREE_ACCEL, EVERY_CORE, std::nullopt},
};

/// The course lecturer's TeapotTest of 2025 (1000 x 1000, 400 bubbles, no acceleration) timed
/// with his thread counts, in comments of the file (course catalogue §5): setMultithreading(0),
/// no threads, 25 s; 2, 3 and 4 threads 13.6, 10.7 and 10.7 s; -2, every core, 9.3 s. (One
/// worker thread took 25.8 s and parallel streams 9.6 s: the caption says so, no row has them.)
/// Then the structures, which he did not time there, and Embree.
constexpr ReferenceRow LECTURER_ROWS[] = {
    {"no acceleration", "none", 1, 25},
    {"2 threads", "none", 2, 13.6},
    {"3 threads", "none", 3, 10.7},
    {"4 threads", "none", 4, 10.7},
    {"threads", "none", EVERY_CORE, 9.3},
    {"threads + CBR", "cbr", EVERY_CORE, std::nullopt},
    {"threads + CBR + BVH", "bvh", EVERY_CORE, std::nullopt},
    {"threads + wide BVH", "bvh4", EVERY_CORE, std::nullopt},
    {"threads + wide BVH + light buffers", "bvh4+lights", EVERY_CORE, std::nullopt},
    {"threads + grid", "grid", EVERY_CORE, std::nullopt},
    {EMBREE_ROW, EMBREE_ACCEL, EVERY_CORE, std::nullopt},
};

/// The built-in scenes whose rows carry someone's times, and whose they are.
struct Reference {
  std::string_view scene;
  std::span<const ReferenceRow> rows;
  std::string_view source;  ///< the caption's "reference: ..."
};

constexpr std::string_view LECTURER =
    "the course lecturer's times for his TeapotTest of 2025 (1000x1000 with 400 bubbles, no "
    "acceleration), in Java on his machine, not this one (one worker thread: 25.8 s; parallel "
    "streams: 9.6 s)";
constexpr Reference REFERENCES[] = {
    {"galaxy", REPORT_ROWS, "the reference report's times for its galaxy at 1280x720"},
    {"teapot", LECTURER_ROWS, LECTURER},
    {"bubbles", LECTURER_ROWS, LECTURER},
};

/// The rows of scene: its reference's, or the report's rows without times.
Reference referenceOf(std::string_view scene) {
  for (const Reference& r : REFERENCES)
    if (r.scene == scene) return r;
  return {scene, REPORT_ROWS, ""};
}

/// The image's pixels as the PNG has them: 8 bits per channel, row by row.
std::vector<std::array<std::uint8_t, 3>> rgb8(const Image& image) {
  std::vector<std::array<std::uint8_t, 3>> out;
  out.reserve(static_cast<std::size_t>(image.nX()) * static_cast<std::size_t>(image.nY()));
  for (int y = 0; y < image.nY(); ++y)
    for (int x = 0; x < image.nX(); ++x) out.push_back(image.pixel(x, y).toRgb8());
  return out;
}

/// The pixels of image whose 8-bit colour is not reference's.
std::uint64_t pixelsDiffering(const std::vector<std::array<std::uint8_t, 3>>& reference,
                              const Image& image) {
  const std::vector<std::array<std::uint8_t, 3>> pixels = rgb8(image);
  std::uint64_t n = 0;
  for (std::size_t k = 0; k < pixels.size(); ++k) n += pixels[k] != reference[k] ? 1 : 0;
  return n;
}

/// A row ready to render: its tracer built over the scene and its acceleration.
struct PlannedRow {
  BenchRow row;
  std::unique_ptr<RayTracer> tracer;
};

}  // namespace

int benchRows(const BenchArgs& args, const Destinations& to, const Io& io) {
  if (args.stars) throw UsageError("--stars: only with --scaling (the galaxy's star counts)");
  if (args.details)
    throw UsageError("--details: only with --scaling teapot (the teapot's details)");
  SceneArguments sceneArgs = args.scene;
  if (args.full && (sceneArgs.width || sceneArgs.height))
    throw UsageError("--full: the scene's own resolution; give either --full or --width/--height");
  if (!args.full && !sceneArgs.width && !sceneArgs.height) sceneArgs.width = DEFAULT_WIDTH;
  const RenderRequest request = resolveRenderRequest(sceneArgs, {.makesImage = true});
  const SceneDocument& doc = request.doc;
  // No table over the scene file or a model file it reads (the only files a bench reads).
  for (const auto& file : to.files)
    checkOutputIsNoInput(file.first, "-o", "the table", args.scene.argument, doc);
  const int threads = benchThreads(args);

  // The rows: the reference's (the report's four, the wide BVH's and the grid's, or the
  // lecturer's) with the scene's tracer, then every stage's tracer through the default (wide) BVH
  // (stage 4's debugging views left out: they do not render the scene's light). A reference's times
  // belong to its scenes only.
  const Reference reference = referenceOf(args.scene.argument);
  const bool timed = !reference.source.empty();
  const TracerKind& sceneTracer = findTracer(doc.render.tracer);
  std::vector<std::pair<BenchRow, const TracerKind*>> plan;
  for (const ReferenceRow& s : reference.rows)
    plan.push_back({BenchRow{.name = s.name,
                             .tracer = sceneTracer.name,
                             .accel = s.accel,
                             .threads = s.threads == EVERY_CORE ? threads : s.threads,
                             .referenceSeconds = timed ? s.seconds : std::nullopt},
                    &sceneTracer});
  for (const TracerKind& kind : tracerKinds())
    if (!kind.debugView)
      plan.push_back(
          {BenchRow{.name = kind.stage,
                    .tracer = kind.name,
                    .accel = std::string(DEFAULT_ACCELERATION) + std::string(WITH_LIGHT_BUFFERS),
                    .threads = threads},
           &kind});

  // Every structure before the first ray: one acceleration of each kind used, the tracers, the
  // sampler, the camera and its image (which every row renders into).
  // Embree's scene is built where the build has Embree; without it, its row is not rendered.
  std::map<std::string, std::unique_ptr<Intersectable>> accelerations;
  for (auto& [row, kind] : plan) {
    if (row.accel == EMBREE_ACCEL) {
      row.countsNodes = false;  // Embree does not report its nodes
#if RT_HAVE_EMBREE
      row.note =
          std::string("Embree ") + EmbreeScene::version() + ": float tests; t recomputed exactly";
      if (!accelerations.contains(row.accel))
        accelerations[row.accel] = std::make_unique<EmbreeScene>(doc.scene->geometries);
#else
      row.rendered = false;
      row.note = std::string(EMBREE_NOT_BUILT);
#endif
      continue;
    }
    if (!accelerations.contains(row.accel)) {
      const bool buffered = row.accel.ends_with(WITH_LIGHT_BUFFERS);
      const std::string_view name = std::string_view(row.accel).substr(
          0, row.accel.size() - (buffered ? WITH_LIGHT_BUFFERS.size() : 0));
      const auto* lit = dynamic_cast<const LitScene*>(doc.scene.get());
      accelerations[row.accel] = makeAcceleration(
          name, doc.scene->geometries,
          lit ? std::span<const LightSource>(lit->lights) : std::span<const LightSource>(),
          buffered);
    }
  }
  std::vector<PlannedRow> rows;
  for (auto& [row, kind] : plan) {
    std::unique_ptr<RayTracer> tracer =
        row.rendered ? kind->make(doc, accelerations.at(row.accel).get()) : nullptr;
    rows.push_back({std::move(row), std::move(tracer)});
  }
  const std::unique_ptr<PixelSampler> sampler = cliRegistry().makeSampler(doc.render);
  Camera camera = doc.camera.builder().build();
  Image& image = camera.image();

  // Round robin: repeat r renders every row once, so that a change of the machine's load hits
  // every row alike; each row's time is the median of its renders.
  std::vector<std::vector<double>> seconds(rows.size());
  std::vector<std::array<std::uint8_t, 3>> reference8;  // the first row's image, 8 bits
  const std::size_t n = rows.size();
  for (int r = 0; r < args.repeat; ++r)
    for (std::size_t i = 0; i < n; ++i) {
      BenchRow& row = rows[i].row;
      const std::string where = "row " + std::to_string(i + 1) + " of " + std::to_string(n);
      if (io.stop && io.stop->load()) return benchInterrupted(where, args, io);
      io.err << "rt bench: row " << i + 1 << "/" << n;
      if (args.repeat > 1) io.err << ", repeat " << r + 1 << "/" << args.repeat;
      if (!row.rendered) {  // Embree 3 in a build without it: the line says how to get it
        io.err << ": " << row.name << " (" << row.note << ")" << std::endl;
        continue;
      }
      io.err << ": " << row.name << " (tracer " << row.tracer << ", accel " << row.accel << ", "
             << threadsText(row.threads) << ")" << std::endl;
      RenderOptions options;
      options.threads = row.threads;
      options.stop = io.stop;
      const RenderResult result = renderImage({camera, *rows[i].tracer, *sampler}, image, options);
      if (result.interrupted || (io.stop && io.stop->load()))
        return benchInterrupted(where, args, io);
      // Pixels differing from the first row's image: once (the renders are deterministic), for
      // the rows of the first row's tracer.
      if (r == 0 && i == 0) reference8 = rgb8(image);
      if (r == 0 && row.tracer == rows[0].row.tracer)
        row.pixelsDiffering = pixelsDiffering(reference8, image);
      seconds[i].push_back(result.seconds);
      row.counts = result.counts;  // the same every repeat: the render is deterministic
      row.threads = result.threads;
    }

  BenchTable table{.scene = args.scene.argument,
                   .width = doc.camera.nX,
                   .height = doc.camera.nY,
                   .threads = threads,
                   .machine = machineName(),
                   .repeat = args.repeat,
                   .reference = std::string(reference.source)};
  for (std::size_t i = 0; i < n; ++i) {
    rows[i].row.seconds = seconds[i].empty() ? 0 : median(seconds[i]);
    table.rows.push_back(rows[i].row);
  }
  emit(
      to, [&table](TableFormat f) { return formatBenchTable(table, f); }, io);
  return EXIT_OK;
}

}  // namespace rt::cli
