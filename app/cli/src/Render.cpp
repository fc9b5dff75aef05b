// rt render SCENE [-o FILE.png] [--width W] [--height H] [--tracer T] [--quiet]
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

#include "CommandTable.h"
#include "camera/Camera.h"
#include "camera/ImageWriter.h"
#include "camera/RenderBlock.h"
#include "cli/Progress.h"
#include "cli/Registry.h"
#include "cli/Tracers.h"

namespace rt::cli {

namespace {

/// Refuses an image that cannot fit in memory before the camera allocates it: an Image keeps a
/// Color (three doubles) per pixel, and the PNG writer an RGB byte triple.
void checkImageFits(int nX, int nY) {
  const double bytes = static_cast<double>(nX) * nY * (sizeof(Color) + 3);
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0) return;  // unknown: let the allocation decide
  const double memory = static_cast<double>(pages) * static_cast<double>(pageSize);
  if (bytes > memory) {
    std::ostringstream os;
    os.precision(3);
    os << "a " << nX << "x" << nY << " image needs " << bytes / (1u << 30)
       << " GiB, more than this machine's " << memory / (1u << 30) << " GiB of memory";
    throw UsageError(os.str());
  }
}

/// rt render's arguments, as the command line binds them.
struct RenderArgs {
  SceneArguments scene;
  std::optional<std::string> output;
  bool quiet = false;
};

int render(const RenderArgs& args, const Io& io) {
  // Everything is checked before the first ray: the scene, the options, the output path and the
  // image's size. A mistake costs no render time.
  const std::string& sceneArg = args.scene.argument;
  SceneDocument doc = sceneFromArguments(args.scene);
  const std::optional<std::string>& outArg = args.output;
  const std::string output = outArg ? *outArg : defaultOutputPath(sceneArg);
  checkOutputWritable(output, PNG_IMAGE, outArg ? "-o" : "the default output");
  const int nX = doc.camera.nX, nY = doc.camera.nY;
  checkImageFits(nX, nY);

  const CliRegistry& registry = cliRegistry();
  const TracerKind& kind = findTracer(doc.render.tracer);
  const std::unique_ptr<Intersectable> accelerator =
      registry.makeAccelerator ? registry.makeAccelerator(doc) : nullptr;
  const std::unique_ptr<RayTracer> tracer = kind.make(doc, accelerator.get());
  const std::unique_ptr<PixelSampler> sampler = registry.makeSampler(doc.render);
  const Camera camera = doc.camera.builder().setResolution(nX, nY).build();
  Image image(nX, nY);

  const bool quiet = args.quiet;
  const std::uint64_t total = static_cast<std::uint64_t>(nX) * static_cast<std::uint64_t>(nY);
  const auto start = std::chrono::steady_clock::now();
  std::atomic<std::uint64_t> donePixels{0};
  RenderOutcome outcome;
  bool interrupted = false;
  {
    std::unique_ptr<ProgressMonitor> progress;
    if (!quiet) {
      io.err << "rt: rendering " << sceneArg << " (" << nX << "x" << nY << ", tracer " << kind.name
             << ") to " << output << "\n";
      progress = std::make_unique<ProgressMonitor>(
          io.err,
          io.errIsTerminal ? ProgressMonitor::Style::Terminal : ProgressMonitor::Style::Lines,
          donePixels, total, static_cast<std::uint64_t>(nX));
    }
    // The build's render loop (rows on this thread; tiles on a pool of threads from mini project
    // 2 on): it sees a stop request (Ctrl-C) within a block of pixels, adds each block's counts
    // once and reports its pixels to the progress thread once.
    outcome = registry.render(
        {camera, *tracer, *sampler, image, doc.render.threads, io.stop, donePixels});
    // A Ctrl-C that arrives after the last block still means "stop": nothing is written.
    interrupted = outcome.interrupted || (io.stop && io.stop->load());
  }  // the progress thread is stopped here, before anything else is printed
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (interrupted) {
    io.err << "rt: interrupted after " << donePixels.load() << " of " << total
           << " pixels; nothing written to " << output << "\n";
    return EXIT_INTERRUPTED;
  }
  PngImageWriter().write(image, output);
  const RayCounts& counts = outcome.counts;
  if (!quiet) {
    // The rate counts primary rays (pixels), the figure that compares across tracers; the
    // secondary and shadow rays the tracer cast are named when there are any.
    const double rate = seconds > 0 ? static_cast<double>(counts.primary) / seconds : 0;
    io.err << "rt: wrote " << output << ": " << nX << "x" << nY << ", tracer " << kind.name << ", "
           << counts.primary << " primary rays";
    if (counts.secondary > 0) io.err << " (+" << counts.secondary << " reflected/refracted)";
    if (counts.shadow > 0) io.err << " (+" << counts.shadow << " shadow)";
    io.err << " in " << formatDuration(seconds) << " (" << static_cast<std::uint64_t>(rate)
           << " primary rays/s)\n";
  }
  return EXIT_OK;
}

}  // namespace

void addRenderCommand(CommandLine& rt) {
  std::string tracers;
  for (const TracerKind& t : tracerKinds())
    tracers += "  " + std::string(t.name) + std::string(9 - t.name.size(), ' ') + "(" +
               std::string(t.stage.substr(0, t.stage.find('_'))) + ") " +
               std::string(t.description) + "\n";
  const auto [command, args] = rt.addCommand(
      "render", "render a scene to a PNG image",
      "SCENE is a built-in scene's name (see rt list) or a scene file ending in .json; the\n"
      "options override what the scene sets. Without -o the image is written to SCENE.png\n"
      "in the current directory (for a scene file: its name with .png for .json).\n\n"
      "Tracers (a built-in scene's default is its stage's; a file's is render.tracer):\n" +
          tracers +
          "\nBefore any ray is cast, everything is checked: the scene, the options, the\n"
          "resolution and that the output's directory can be written to. Progress goes to\n"
          "stderr (a percentage on a terminal, a line per 10% otherwise), then the wall\n"
          "time and the rate of primary rays. The image is written to a temporary file and\n"
          "renamed: Ctrl-C stops the render within a row, writes nothing, leaves an\n"
          "existing FILE.png as it was, and exits with code 130.\n",
      render);
  addOptional(*command, "-o,--output", args->output,
              "where to write the image (default: SCENE.png)", "FILE.png");
  addSceneArguments(*command, args->scene, "image width in pixels, 1..32768 (default: the scene's)",
                    "image height in pixels, 1..32768 (default: the scene's)",
                    "which stage's tracer renders it (default: the scene's)");
  command->add_flag("-q,--quiet", args->quiet, "print nothing but errors");
}

}  // namespace rt::cli
