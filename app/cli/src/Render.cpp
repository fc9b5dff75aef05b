// rt render SCENE [-o FILE.png] [--width W] [--height H] [--tracer T] [--grid-lines N]
// [--quiet|--silent] and the options stages add (mini project 2: --threads N, --accel A)
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

#include "CommandRegistration.h"
#include "camera/Camera.h"
#include "camera/Image.h"
#include "camera/ImageWriter.h"
#include "camera/RenderBlock.h"
#include "cli/CommandLine.h"
#include "cli/Progress.h"
#include "cli/Registry.h"
#include "cli/RenderCommand.h"
#include "cli/RenderRequest.h"
#include "cli/Tracers.h"

namespace rt::cli {

namespace {

int render(const RenderArgs& args, const Io& io) {
  // Everything is checked before the first ray (the scene, the options, the output path, the
  // image's size), in one step; then everything is built.
  const RenderRequest request = resolveRenderRequest(
      args.scene,
      {.writesImage = true, .output = args.output, .makesImage = true, .renders = true});
  if (!args.silent)
    for (const std::string& w : request.warnings) io.err << "rt: " << w << "\n";
  const SceneDocument& doc = request.doc;
  const std::string& output = request.output;
  const TracerKind& kind = *request.tracer;
  const int nX = doc.camera.nX, nY = doc.camera.nY;
  RenderSetup setup = request.build();
  Image& image = setup.camera.image();  // the camera's own image is the one rendered and written

  const bool quiet = args.quiet || args.silent;
  const std::uint64_t total = static_cast<std::uint64_t>(nX) * static_cast<std::uint64_t>(nY);
  const auto start = std::chrono::steady_clock::now();
  std::atomic<std::uint64_t> donePixels{0}, doneRays{0};
  RenderOutcome outcome;
  bool interrupted = false;
  {
    std::unique_ptr<ProgressMonitor> progress;
    if (!quiet) {
      io.err << "rt: rendering " << args.scene.argument << " (" << nX << "x" << nY << ", tracer "
             << kind.name << ") to " << output << "\n";
      progress = std::make_unique<ProgressMonitor>(
          io.err,
          io.errIsTerminal ? ProgressMonitor::Style::Terminal : ProgressMonitor::Style::Lines,
          donePixels, doneRays, total, static_cast<std::uint64_t>(nX));
    }
    // The build's render loop (rows on this thread; tiles on a pool of threads from mini project
    // 2 on): it sees a stop request (Ctrl-C) within a block of pixels, adds each block's counts
    // once and reports its pixels and rays to the progress thread once.
    outcome = cliRegistry().render(
        {setup.context(), image, doc.render.threads, io.stop, donePixels, doneRays});
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
  finishImage(setup.camera, doc, args.gridLines, output);
  if (!args.silent)
    io.err << "rt: "
           << renderSummary(
                  output, nX, nY, kind, outcome.counts, seconds,
                  outcome.threads > 1 ? "on " + std::to_string(outcome.threads) + " threads" : "")
           << "\n";
  return EXIT_OK;
}

}  // namespace

void finishImage(Camera& camera, const SceneDocument& doc, const std::optional<int>& gridLines,
                 const std::string& path) {
  // The course's grid lines go on the finished image (its printGrid after renderImage), so they
  // change no ray and no count.
  if (const int every = gridLines.value_or(doc.render.gridLines); every > 0)
    camera.printGrid(every, doc.render.gridColor);
  PngImageWriter().write(camera.image(), path);
}

std::string renderSummary(const std::string& output, int nX, int nY, const TracerKind& kind,
                          const RayCounts& counts, double seconds, const std::string& where) {
  // The rate of primary rays (pixels) compares across tracers; the rays of every kind per
  // second, named when the tracer cast secondary or shadow rays, compare the work done.
  const auto perSecond = [seconds](std::uint64_t n) {
    return static_cast<std::uint64_t>(seconds > 0 ? static_cast<double>(n) / seconds : 0);
  };
  std::ostringstream os;
  os << "wrote " << output << ": " << nX << "x" << nY << ", tracer " << kind.name << ", "
     << counts.primary << (counts.primary == 1 ? " primary ray" : " primary rays");
  if (counts.secondary > 0) os << " (+" << counts.secondary << " reflected/refracted)";
  if (counts.shadow > 0) os << " (+" << counts.shadow << " shadow)";
  os << " in " << formatDuration(seconds);
  if (!where.empty()) os << " " << where;
  os << " (" << perSecond(counts.primary) << " primary rays/s";
  if (counts.total() > counts.primary) os << ", " << perSecond(counts.total()) << " rays/s";
  os << ")";
  return os.str();
}

std::string renderCommandDetails() {
  std::string tracers;
  for (const TracerKind& t : tracerKinds())
    tracers += "  " + std::string(t.name) + std::string(9 - t.name.size(), ' ') + "(" +
               std::string(t.stage.substr(0, t.stage.find('_'))) + ") " +
               std::string(t.description) + "\n";
  return "SCENE is a built-in scene's name (see rt list) or a scene file ending in .json; the\n"
         "options override what the scene sets. Without -o the image is written to SCENE.png\n"
         "in the current directory (for a scene file: its name with .png for .json).\n\n"
         "Tracers (a built-in scene's default is its stage's; a file's is render.tracer):\n" +
         tracers +
         "\nBefore any ray is cast, everything is checked: the scene, the options, the\n"
         "resolution and that the output's directory can be written to. Progress goes to\n"
         "stderr (a percentage on a terminal, a line per 10% otherwise, with the rays per\n"
         "second and, while the rate is steady, the time left), then the wall time, the\n"
         "threads and the rates of primary rays and of all rays. The image is written to\n"
         "a temporary file and renamed: Ctrl-C stops the render within a row, writes\n"
         "nothing, leaves an existing FILE.png as it was, and exits with code 130.\n";
}

void addRenderOptions(CLI::App& command, RenderArgs& into) {
  addOptional(command, "-o,--output", into.output, "where to write the image (default: SCENE.png)",
              "FILE.png");
  addSceneArguments(command, into.scene, "image width in pixels, 1..32768 (default: the scene's)",
                    "image height in pixels, 1..32768 (default: the scene's)",
                    "which stage's tracer renders it (default: the scene's)");
  addGridLinesOption(command, into.gridLines);
  command.add_flag("-q,--quiet", into.quiet, "no progress; only the final timing line");
  command.add_flag("-s,--silent", into.silent, "print nothing but errors");
}

void addGridLinesOption(CLI::App& command, std::optional<int>& into) {
  addOptional(command, "--grid-lines", into,
              "draw the course's grid lines every N pixels on the image, 0..32768; 0: none "
              "(default: the scene's render.gridLines; their colour: render.gridColor, yellow)",
              "N")
      ->transform(integerValidator(0, Image::MAX_SIDE));
}

void addRenderCommand(CommandLine& rt) {
  const auto [command, args] =
      rt.addCommand("render", "render a scene to a PNG image", renderCommandDetails(), render);
  addRenderOptions(*command, *args);
}

}  // namespace rt::cli
