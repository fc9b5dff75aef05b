// rt animate SCENE (--orbit DEGREES | --through VIEW,VIEW,...) --frames N [--frame K] [-o DIR]
// [--video FILE.mp4] [--fps F] and rt render's scene options: a camera path rendered frame by
// frame (cli/Animation.h).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <ostream>

#include <CLI/App.hpp>

#include "CommandRegistration.h"
#include "camera/Camera.h"
#include "cli/Animation.h"
#include "cli/CommandLine.h"
#include "cli/Progress.h"
#include "cli/Registry.h"
#include "cli/RenderCommand.h"
#include "cli/RenderRequest.h"

namespace rt::cli {

namespace {

int animate(const AnimateArgs& args, const Io& io) {
  const AnimationPlan plan = resolveAnimation(args);  // everything checked before any frame
  if (!args.silent)
    for (const std::string& w : plan.request.warnings) io.err << "rt: " << w << "\n";
  const SceneDocument& doc = plan.request.doc;
  const TracerKind& kind = *plan.request.tracer;
  const int nX = doc.camera.nX, nY = doc.camera.nY;
  const TracerSetup traced = plan.request.buildTracer();
  const std::unique_ptr<PixelSampler> sampler = cliRegistry().makeSampler(doc.render);

  const bool quiet = args.quiet || args.silent;
  const std::uint64_t perFrame = static_cast<std::uint64_t>(nX) * static_cast<std::uint64_t>(nY);
  const auto start = std::chrono::steady_clock::now();
  std::atomic<std::uint64_t> donePixels{0}, doneRays{0};
  RayCounts counts;
  int threads = 1;
  std::size_t written = 0;
  bool interrupted = false;
  try {
    // Stopped as this block is left, before anything else is printed.
    std::unique_ptr<ProgressMonitor> progress;
    if (!quiet) {
      io.err << "rt: animating " << args.scene.argument << " (" << plan.frames.size()
             << (plan.frames.size() == 1 ? " frame" : " frames") << " of " << nX << "x" << nY
             << ", tracer " << kind.name << ") into " << plan.directory.string() << "\n";
      progress = std::make_unique<ProgressMonitor>(
          io.err,
          io.errIsTerminal ? ProgressMonitor::Style::Terminal : ProgressMonitor::Style::Lines,
          donePixels, doneRays, perFrame * plan.frames.size(), static_cast<std::uint64_t>(nX));
    }
    for (const int k : plan.frames) {
      Camera camera = plan.cameras[static_cast<std::size_t>(k)].builder().build();
      const RenderOutcome outcome = cliRegistry().render({{camera, *traced.tracer, *sampler},
                                                          camera.image(),
                                                          doc.render.threads,
                                                          io.stop,
                                                          donePixels,
                                                          doneRays});
      if (outcome.interrupted || (io.stop && io.stop->load())) {
        interrupted = true;
        break;
      }
      counts += outcome.counts;
      threads = outcome.threads;
      finishImage(camera, doc, args.gridLines, plan.framePath(k));
      ++written;
    }
  } catch (...) {
    if (written == 0) plan.settleUnfinished(0);  // a failed first frame leaves no folder behind
    throw;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (interrupted) {
    io.err << "rt: interrupted after " << written << " of " << plan.frames.size() << " frames ("
           << plan.settleUnfinished(written)
           << (written > 0 ? "; the one in progress not written)\n" : ")\n");
    return EXIT_INTERRUPTED;
  }
  if (!args.silent)
    io.err << "rt: "
           << renderSummary(plan.directory.string() + " (" + std::to_string(written) +
                                (written == 1 ? " frame)" : " frames)"),
                            nX, nY, kind, counts, seconds,
                            threads > 1 ? "on " + std::to_string(threads) + " threads" : "")
           << "\n";
  if (plan.video) {
    if (!encodeVideo(plan, io.stop)) {
      io.err << "rt: interrupted while encoding " << *plan.video << " (nothing written to it; the "
             << written << (written == 1 ? " frame is" : " frames are") << " in "
             << plan.directory.string() << ")\n";
      return EXIT_INTERRUPTED;
    }
    if (!args.silent)
      io.err << "rt: wrote " << *plan.video << ": " << written << " frames at " << plan.fps
             << " frames/s (H.264)\n";
  }
  return EXIT_OK;
}

}  // namespace

std::string animateCommandDetails() {
  return "SCENE and its options are rt render's. The camera moves along one path:\n"
         "  --orbit DEGREES  about the camera's target, about its up vector; frame k at\n"
         "                   k*DEGREES/N, so --orbit 360 loops without a repeated frame and\n"
         "                   frame 0 is the scene's camera (a camera given by a direction\n"
         "                   orbits the point at its focal distance, or its view plane's)\n"
         "  --through A,B,C  the scene's named views in that order (all: every view), every\n"
         "                   quantity interpolated linearly; the first frame is view A and\n"
         "                   the last view C, exactly (so at least 2 frames)\n\n"
         "Frames go to DIR/frame-0000.png, ... (at least 4 digits), each written whole\n"
         "(a temporary file renamed). A frame is a function of the scene, the options and\n"
         "its number only: --frame K renders frame K alone, the same bytes as in the whole\n"
         "sequence. --video FILE.mp4 encodes the frames with ffmpeg (H.264, yuv420p, odd\n"
         "sizes padded by a pixel) once they are all written; without ffmpeg it is refused\n"
         "before any frame. Ctrl-C stops within a row: the frames done stay, the one in\n"
         "progress is not written, the exit code is 130 (with no frame written, a folder\n"
         "this run made is removed); during the encoding it ends ffmpeg, and the video is\n"
         "not written (an earlier one stays as it was).\n";
}

void addAnimateOptions(CLI::App& command, AnimateArgs& into) {
  addSceneArguments(command, into.scene, "frame width in pixels, 1..32768 (default: the scene's)",
                    "frame height in pixels, 1..32768 (default: the scene's)",
                    "which stage's tracer renders it (default: the scene's)");
  addOptional(command, "--orbit", into.orbit,
              "orbit the camera's target by DEGREES over the frames (negative: the other way)",
              "DEGREES")
      ->check(numberValidator());
  addOptional(command, "--through", into.through,
              "a path through the scene's named views, in this order (all: every view)",
              "VIEW,VIEW,...");
  command
      .add_option("--frames", into.frames, "frames in the path, 1.." + std::to_string(MAX_FRAMES))
      ->type_name("N")
      ->required()
      ->transform(integerValidator(1, MAX_FRAMES));
  // Any integer here: resolveAnimation names the range that --frames gives.
  addOptional(command, "--frame", into.frame, "render only frame K (0-based) of the path", "K")
      ->transform(
          integerValidator(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
  addOptional(command, "-o,--output", into.output,
              "the frames' folder, created if missing (default: SCENE-frames)", "DIR");
  CLI::Option* video =
      addOptional(command, "--video", into.video,
                  "encode the frames into FILE.mp4 with ffmpeg (when it is installed)", "FILE.mp4");
  // The frames have no rate of their own: --fps alone would change nothing.
  command
      .add_option("--fps", into.fps, "the video's frames per second, with --video (default: 30)")
      ->type_name("F")
      ->check(numberValidator())
      ->needs(video);
  addGridLinesOption(command, into.gridLines);
  command.add_flag("-q,--quiet", into.quiet, "no progress; only the final timing line");
  command.add_flag("-s,--silent", into.silent, "print nothing but errors");
}

void addAnimateCommand(CommandLine& rt) {
  const auto [command, args] = rt.addCommand(
      "animate", "render a camera path (an orbit, or a path through the scene's views) to frames",
      animateCommandDetails(), animate);
  addAnimateOptions(*command, *args);
}

}  // namespace rt::cli
