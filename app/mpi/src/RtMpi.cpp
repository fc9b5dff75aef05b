// rt-mpi's commands: render and animate with rt's options (one definition of them, in rt_cli),
// run by every rank together.
//
//     every rank                 rank 0's command line, broadcast, parsed the same way
//     rank 0                     reads the scene file and every model file it names (recorded)
//                                and checks everything rt would; broadcasts the scene's text and
//                                the models' bytes, or its error (then every rank stops)
//     ranks > 0                  build the same scene from those bytes (no shared file system)
//     every rank                 builds the accelerator and the tracer; the first rank that
//                                fails is named by rank 0 (rank, host, message), and every rank
//                                stops
//     the job                    Distributed.h: units dealt on demand, rank 0 assembles, writes
#include "RtMpi.h"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/App.hpp>

#include "DealModel.h"
#include "Distributed.h"
#include "Wire.h"
#include "camera/Image.h"
#include "cli/Animation.h"
#include "cli/CommandLine.h"
#include "cli/Commands.h"
#include "cli/Progress.h"
#include "cli/Registry.h"
#include "cli/RenderCommand.h"
#include "cli/RenderRequest.h"
#include "parallel/TilePool.h"
#include "scenefile/SceneFile.h"

namespace rt::mpi {

namespace {

using cli::EXIT_BAD_INPUT;
using cli::EXIT_FAILURE_RUNTIME;
using cli::EXIT_INTERRUPTED;
using cli::EXIT_OK;

/// What every rank of the job knows of it.
struct World {
  MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, size = 1;
  bool threadsMayCallMpi = false;  ///< MPI_THREAD_MULTIPLE was provided
  std::vector<std::string> hosts;  ///< rank 0: every rank's host
};

/// A frame whose pixels outweigh a message (1 GiB) is dealt as tiles whatever the frame count.
constexpr std::uint64_t kMaxWholeFrameBytes = std::uint64_t{1} << 30;

/// What rank 0 read and checked, sent to every rank: an error (code != 0), or the scene file's
/// text and the model files' bytes (both empty for a built-in scene).
struct Package {
  int code = EXIT_OK;
  std::string error;
  std::string sceneText;
  ModelFileSet models;
};

std::string packed(const Package& p) {
  Packer out;
  out.u64(static_cast<std::uint64_t>(p.code));
  out.str(p.error);
  out.str(p.sceneText);
  out.u64(p.models.files.size());
  for (const auto& [path, bytes] : p.models.files) {
    out.str(path);
    out.str(bytes);
  }
  return std::move(out.bytes());
}

Package unpacked(const std::string& bytes) {
  Unpacker in(bytes);
  Package p;
  p.code = static_cast<int>(in.u64());
  p.error = in.str();
  p.sceneText = in.str();
  for (std::uint64_t n = in.u64(); n > 0; --n) {
    std::string path = in.str();
    p.models.files[std::move(path)] = in.str();
  }
  return p;
}

/// What a command resolves on each rank: the request, and the frames with their outputs.
struct Resolved {
  cli::RenderRequest request;
  std::vector<CameraSpec> cameras;
  std::vector<std::string> outputs;        ///< rank 0
  std::optional<cli::AnimationPlan> plan;  ///< animate
};

/// What distributeScene leaves on a rank.
struct Distributed {
  int rootCode = EXIT_OK;  ///< rank 0's: not EXIT_OK when it failed (it printed why)
  std::string error;       ///< this rank's own failure to resolve (the others than 0)
  Package package;         ///< what rank 0 sent (the model files are replayed from it)
  cli::SceneFileInput input;
  std::optional<Resolved> resolved;
};

/// Rank 0 resolves with the disk (its model files recorded) and sends what it read, or its
/// error; the others resolve from that. resolve(scene, writes) is the command's resolution.
template <typename Resolve>
void distributeScene(const World& world, cli::SceneArguments scene, Resolve resolve, Distributed& d,
                     const cli::Io& io) {
  std::string bytes;
  if (world.rank == 0) {
    try {
      if (cli::isSceneFileArgument(scene.argument)) {
        d.input.text = readSceneText(scene.argument);
        d.input.models.record = &d.package.models;
        scene.fileInput = &d.input;
      }
      d.resolved = resolve(scene, true);
      d.package.sceneText = d.input.text;
    } catch (...) {
      const cli::ErrorReport report = cli::describeError(std::current_exception());
      d.package = Package{report.code, report.message, {}, {}};
      d.resolved.reset();
      io.err << "rt-mpi: " << report.message << "\n";
    }
    bytes = packed(d.package);
  }
  broadcastBytes(bytes, 0, world.comm);
  if (world.rank != 0) d.package = unpacked(bytes);
  d.rootCode = d.package.code;
  if (world.rank == 0 || d.rootCode != EXIT_OK) return;
  d.input.text = d.package.sceneText;
  d.input.models.replay = &d.package.models;
  if (cli::isSceneFileArgument(scene.argument)) scene.fileInput = &d.input;
  try {
    d.resolved = resolve(scene, false);
  } catch (...) {
    // Reported through the status exchange that follows (the rank, its host, the message).
    d.error = "cannot build the scene: " + cli::describeError(std::current_exception()).message;
  }
}

/// The cores this process may run on: mpirun binds each rank to some (by default one core per
/// rank when there are at most two ranks, one socket otherwise), which a rank's threads share.
int coresAllowed() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

int coresOfMachine() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

/// Warns (rank 0), once, when mpirun's binding wastes cores: a rank with more threads than the
/// cores it may use (they share them), or a machine whose ranks together may use fewer cores
/// than it has (one rank per machine, bound to one core, by mpirun's default for two ranks), or
/// a machine with more render threads than cores.
void warnAboutBinding(const std::vector<int>& threads, const std::vector<int>& allowed,
                      const std::vector<int>& machine, const std::vector<std::string>& hosts,
                      const cli::Io& io) {
  std::map<std::string, int> usable, rendering;  // per host: its ranks' cores and threads
  for (std::size_t r = 0; r < threads.size(); ++r) {
    usable[hosts[r]] += allowed[r];
    rendering[hosts[r]] += threads[r];
  }
  for (std::size_t r = 0; r < threads.size(); ++r) {
    if (rendering[hosts[r]] > machine[r]) {
      io.err << "rt-mpi: warning: " << hosts[r] << " runs " << rendering[hosts[r]]
             << " render threads on its " << machine[r]
             << " cores; give each rank fewer threads (--threads) or run fewer ranks there\n";
      return;
    }
    const bool crowded = threads[r] > allowed[r];
    const bool idle = usable[hosts[r]] < machine[r];
    if (!crowded && !idle) continue;
    io.err << "rt-mpi: warning: rank " << r << " on " << hosts[r] << " is bound to " << allowed[r]
           << " of the machine's " << machine[r] << " cores and renders with " << threads[r]
           << (threads[r] == 1 ? " thread" : " threads")
           << (crowded ? ", which share them" : "; the machine's other cores stay idle")
           << "; for one rank per machine run mpirun with --bind-to none, or give each rank N "
              "cores with --map-by slot:PE=N (docs/distributed.md)\n";
    return;
  }
}

/// How many units each rank rendered: every rank's count up to 8 ranks ("rank 0: 3, rank 1: 2"),
/// beyond that the fewest and the most ("rank 5 the fewest, 2; rank 0 the most, 9").
std::string describeShares(const std::vector<std::uint64_t>& units) {
  std::ostringstream os;
  if (units.size() <= 8) {
    for (std::size_t r = 0; r < units.size(); ++r)
      os << (r ? ", " : "") << "rank " << r << ": " << units[r];
    return os.str();
  }
  const auto [fewest, most] = std::minmax_element(units.begin(), units.end());
  os << "rank " << (fewest - units.begin()) << " the fewest, " << *fewest << "; rank "
     << (most - units.begin()) << " the most, " << *most;
  return os.str();
}

std::string describeRanks(const std::vector<int>& threads) {
  const int ranks = static_cast<int>(threads.size());
  const bool same =
      std::all_of(threads.begin(), threads.end(), [&](int t) { return t == threads.front(); });
  std::ostringstream os;
  os << "on " << ranks << (ranks == 1 ? " rank" : " ranks");
  if (same) {
    os << " x " << threads.front() << (threads.front() == 1 ? " thread" : " threads");
  } else {
    int all = 0;
    for (int t : threads) all += t;
    os << " (" << all << " threads)";
  }
  return os.str();
}

std::string mebibytes(std::uint64_t bytes) {
  std::ostringstream os;
  os.precision(3);
  os << static_cast<double>(bytes) / (1 << 20) << " MiB";
  return os.str();
}

/// The command both render and animate end in: build, check every rank, run the job, report.
struct JobRequest {
  bool quiet = false, silent = false;
  std::optional<int> gridLines;
  std::string what;  ///< "galaxy" for the header
  bool animate = false;
};

int runJob(const World& world, Distributed& d, const JobRequest& job, const cli::Io& io) {
  if (d.rootCode != EXIT_OK) return d.rootCode;  // every rank stops with rank 0's code
  std::optional<Resolved>& resolved = d.resolved;
  // Every rank builds the accelerator, the tracer and the sampler; a failure anywhere stops all.
  std::string error = d.error;
  cli::TracerSetup traced;
  std::unique_ptr<PixelSampler> sampler;
  if (error.empty() && resolved) {
    try {
      traced = resolved->request.buildTracer();
      sampler = cli::cliRegistry().makeSampler(resolved->request.doc.render);
    } catch (...) {
      error = "cannot build the accelerator or the tracer: " +
              cli::describeError(std::current_exception()).message;
    }
  }
  if (const std::optional<RankFailure> failed = firstFailure(error, world.hosts, world.comm)) {
    if (world.rank == 0) {
      io.err << "rt-mpi: rank " << failed->rank << " on " << failed->host << ": "
             << failed->message;
      // An animation's folder, made by rank 0's checks, is not left behind empty.
      if (job.animate && resolved) io.err << "; " << resolved->plan->settleUnfinished(0);
      io.err << "\n";
    }
    return EXIT_FAILURE_RUNTIME;
  }

  const SceneDocument& doc = resolved->request.doc;
  const CameraSpec& first = resolved->cameras.front();
  const std::uint64_t framePixels =
      static_cast<std::uint64_t>(first.nX) * static_cast<std::uint64_t>(first.nY);
  const bool wholeFrames = job.animate &&
                           resolved->cameras.size() >= static_cast<std::size_t>(world.size) &&
                           framePixels * 3 * sizeof(double) <= kMaxWholeFrameBytes;
  const int allowed = coresAllowed(), machine = coresOfMachine();
  int threads = doc.render.threads > 0 ? doc.render.threads : allowed;
  const bool oneThreadOnly = world.rank != 0 && !wholeFrames && !world.threadsMayCallMpi;
  if (oneThreadOnly) threads = 1;
  // Every rank must cut the frames alike: the tile side from the job's threads in all.
  long long mine = threads, allRenderThreads = 0;
  MPI_Allreduce(&mine, &allRenderThreads, 1, MPI_LONG_LONG, MPI_SUM, world.comm);
  JobSpec spec{doc,
               *traced.tracer,
               *sampler,
               resolved->cameras,
               resolved->outputs,
               job.gridLines,
               wholeFrames,
               model::dealtTileSide(first.nX, first.nY, resolved->cameras.size(), allRenderThreads),
               threads};
  const std::size_t ranks = static_cast<std::size_t>(world.size);
  std::vector<int> allThreads(ranks), allAllowed(ranks), allMachine(ranks);
  MPI_Gather(&threads, 1, MPI_INT, allThreads.data(), 1, MPI_INT, 0, world.comm);
  MPI_Gather(&allowed, 1, MPI_INT, allAllowed.data(), 1, MPI_INT, 0, world.comm);
  MPI_Gather(&machine, 1, MPI_INT, allMachine.data(), 1, MPI_INT, 0, world.comm);
  if (world.rank == 0 && !job.silent)
    warnAboutBinding(allThreads, allAllowed, allMachine, world.hosts, io);

  int code = EXIT_OK;
  if (world.rank != 0) {
    runWorker(spec, world.comm);
  } else {
    const cli::TracerKind& kind = *resolved->request.tracer;
    const bool quiet = job.quiet || job.silent;
    const std::uint64_t total = framePixels * resolved->cameras.size();
    if (!job.silent && world.size > 1 && !world.threadsMayCallMpi && !wholeFrames && threads > 1)
      io.err << "rt-mpi: warning: this MPI library gives no MPI_THREAD_MULTIPLE: the ranks "
                "other than 0 render with one thread each\n";
    std::atomic<std::uint64_t> donePixels{0}, doneRays{0};
    const auto start = std::chrono::steady_clock::now();
    JobOutcome outcome;
    {
      std::unique_ptr<cli::ProgressMonitor> progress;
      if (!quiet) {
        io.err << "rt-mpi: " << (job.animate ? "animating " : "rendering ") << job.what << " (";
        if (job.animate)
          io.err << resolved->cameras.size()
                 << (resolved->cameras.size() == 1 ? " frame of " : " frames of ");
        io.err << first.nX << "x" << first.nY << ", tracer " << kind.name << ") "
               << describeRanks(allThreads) << ", dealing "
               << (wholeFrames ? "frames"
                               : "tiles of " + std::to_string(spec.tileSize) + "x" +
                                     std::to_string(spec.tileSize))
               << "\n";
        progress = std::make_unique<cli::ProgressMonitor>(
            io.err,
            io.errIsTerminal ? cli::ProgressMonitor::Style::Terminal
                             : cli::ProgressMonitor::Style::Lines,
            donePixels, doneRays, total, static_cast<std::uint64_t>(first.nX), "rt-mpi");
      }
      outcome = runDealer(spec, world.hosts, allThreads, donePixels, doneRays, world.comm);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string target =
        job.animate ? resolved->plan->directory.string() : resolved->outputs.front();
    // The frames a stopped or failed animation leaves (its folder removed when it holds none).
    const auto settled = [&](int written) {
      return resolved->plan->settleUnfinished(static_cast<std::size_t>(written));
    };
    if (outcome.failure) {
      io.err << "rt-mpi: rank " << outcome.failure->rank << " on " << outcome.failure->host << ": "
             << outcome.failure->message << "; "
             << (job.animate ? settled(outcome.framesWritten) : "nothing written to " + target)
             << "\n";
      code = EXIT_FAILURE_RUNTIME;
    } else if (outcome.interrupted) {
      io.err << "rt-mpi: interrupted after " << donePixels.load() << " of " << total << " pixels; "
             << (job.animate ? settled(outcome.framesWritten) : "nothing written to " + target)
             << "\n";
      code = EXIT_INTERRUPTED;
    } else {
      const std::string output = job.animate
                                     ? target + " (" + std::to_string(outcome.framesWritten) +
                                           (outcome.framesWritten == 1 ? " frame)" : " frames)")
                                     : target;
      if (!job.silent)
        io.err << "rt-mpi: "
               << cli::renderSummary(output, first.nX, first.nY, kind, outcome.counts, seconds,
                                     describeRanks(allThreads))
               << "\n";
      if (!quiet)
        io.err << "rt-mpi: dealt " << outcome.units << (wholeFrames ? " frame" : " tile")
               << (outcome.units == 1 ? "" : "s") << " on demand ("
               << describeShares(outcome.unitsByRank) << "): " << outcome.messages << " messages, "
               << mebibytes(outcome.bytes) << " through rank 0\n";
      if (job.animate && resolved->plan->video) {
        try {
          if (!cli::encodeVideo(*resolved->plan, &stopFlag())) {
            io.err << "rt-mpi: interrupted while encoding " << *resolved->plan->video
                   << " (nothing written to it; " << settled(outcome.framesWritten) << ")\n";
            code = EXIT_INTERRUPTED;
          } else if (!job.silent) {
            io.err << "rt-mpi: wrote " << *resolved->plan->video << ": " << outcome.framesWritten
                   << " frames at " << resolved->plan->fps << " frames/s (H.264)\n";
          }
        } catch (const std::exception& e) {
          io.err << "rt-mpi: " << e.what() << "\n";
          code = EXIT_FAILURE_RUNTIME;
        }
      }
    }
  }
  // Every rank ends with rank 0's code.
  MPI_Bcast(&code, 1, MPI_INT, 0, world.comm);
  return code;
}

int mpiRender(const World& world, const cli::RenderArgs& args, const cli::Io& io) {
  Distributed d;
  distributeScene(
      world, args.scene,
      [&](const cli::SceneArguments& scene, bool writes) {
        Resolved r{cli::resolveRenderRequest(scene, {.writesImage = writes,
                                                     .output = args.output,
                                                     .makesImage = true,
                                                     .renders = true}),
                   {},
                   {},
                   std::nullopt};
        r.cameras = {r.request.doc.camera};
        r.outputs = {r.request.output};
        if (writes && !args.silent)
          for (const std::string& w : r.request.warnings) io.err << "rt-mpi: " << w << "\n";
        return r;
      },
      d, io);
  return runJob(world, d, {args.quiet, args.silent, args.gridLines, args.scene.argument, false},
                io);
}

int mpiAnimate(const World& world, const cli::AnimateArgs& args, const cli::Io& io) {
  Distributed d;
  distributeScene(
      world, args.scene,
      [&](const cli::SceneArguments& scene, bool writes) {
        cli::AnimateArgs copy = args;
        copy.scene = scene;
        cli::AnimationPlan plan = cli::resolveAnimation(copy, writes);
        Resolved r{plan.request, {}, {}, std::nullopt};
        for (const int k : plan.frames) {
          r.cameras.push_back(plan.cameras[static_cast<std::size_t>(k)]);
          r.outputs.push_back(plan.framePath(k));
        }
        if (writes && !args.silent)
          for (const std::string& w : plan.request.warnings) io.err << "rt-mpi: " << w << "\n";
        r.plan = std::move(plan);
        return r;
      },
      d, io);
  return runJob(world, d, {args.quiet, args.silent, args.gridLines, args.scene.argument, true}, io);
}

constexpr const char* kDescription =
    ": rt's render and animate across the ranks of an MPI job (mpirun -np N rt-mpi ...)";
constexpr const char* kFooter =
    "Examples:\n"
    "  mpirun -np 2 rt-mpi render galaxy -o galaxy.png\n"
    "  mpirun --hostfile lab.txt rt-mpi animate galaxy --orbit 360 --frames 360 "
    "--video orbit.mp4\n\n"
    "Rank 0 reads the scene and its model files and sends them to the other ranks; tiles\n"
    "(or whole frames) are dealt on demand; rank 0 writes the image, the same bytes as rt\n"
    "render with the same options. A rank that fails stops the job: one message names\n"
    "the rank and its host, and nothing is written. docs/distributed.md has hostfiles,\n"
    "Slurm scripts and what to expect.\n\n"
    "Exit codes: 0 done, 1 a rank failed, 2 bad usage or input, 130 interrupted.\n";

}  // namespace

int runRtMpi(std::span<const std::string> args, const cli::Io& io, MPI_Comm comm,
             bool threadsMayCallMpi) {
  World world;
  world.comm = comm;
  world.threadsMayCallMpi = threadsMayCallMpi;
  MPI_Comm_rank(comm, &world.rank);
  MPI_Comm_size(comm, &world.size);
  world.hosts = gatherStrings(hostName(), 0, comm);

  // Rank 0's command line is the job's (an MPMD launch may give the others other arguments).
  std::string line;
  if (world.rank == 0) {
    Packer out;
    out.u64(args.size());
    for (const std::string& a : args) out.str(a);
    line = std::move(out.bytes());
  }
  broadcastBytes(line, 0, comm);
  std::vector<std::string> argv;
  {
    Unpacker in(line);
    for (std::uint64_t n = in.u64(); n > 0; --n) argv.push_back(in.str());
  }

  // The same parse on every rank: the same options, bound the same way; only rank 0 speaks.
  int code = EXIT_OK;
  try {
    cli::CommandLine rtMpi("rt-mpi", cli::versionString() + kDescription, kFooter,
                           cli::versionString());
    auto renderArgs = std::make_shared<cli::RenderArgs>();
    CLI::App& render = rtMpi.addCommand(
        "render", "render a scene to a PNG image across the job's ranks (rt render's options)",
        cli::renderCommandDetails(),
        [&world, renderArgs](const cli::Io& out) { return mpiRender(world, *renderArgs, out); });
    cli::addRenderOptions(render, *renderArgs);
    auto animateArgs = std::make_shared<cli::AnimateArgs>();
    CLI::App& animate = rtMpi.addCommand(
        "animate", "render a camera path to frames across the job's ranks (rt animate's options)",
        cli::animateCommandDetails() +
            "\nrt-mpi deals whole frames to the ranks (each rendered with all of its\n"
            "threads), or tiles when there are fewer frames than ranks.\n",
        [&world, animateArgs](const cli::Io& out) { return mpiAnimate(world, *animateArgs, out); });
    cli::addAnimateOptions(animate, *animateArgs);
    const cli::CommandLine::Parsed parsed = rtMpi.parse(argv);
    if (!parsed.run) {
      io.out << parsed.text;
      return EXIT_OK;
    }
    return parsed.run(io);
  } catch (...) {
    // Bad usage: every rank found the same mistake in the same command line; rank 0 says it.
    const cli::ErrorReport report = cli::describeError(std::current_exception());
    if (world.rank == 0) io.err << "rt-mpi: " << report.message << "\n";
    code = report.code;
  }
  return code;
}

}  // namespace rt::mpi
