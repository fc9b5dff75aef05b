// rt animate's plan: the camera path, the frames' folder and the video, checked before any frame.
#include "cli/Animation.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "camera/AtomicFile.h"
#include "cli/CommandLine.h"
#include "cli/Commands.h"
#include "common/NearestName.h"
#include "primitives/Double3.h"

namespace rt::cli {

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// v turned by angle (radians) about the unit axis k (Rodrigues' formula).
Double3 rotated(const Double3& v, const Double3& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + k.cross(v) * s + k * (k.dot(v) * (1 - c));
}

Point lerp(const Point& a, const Point& b, double t) {
  return Point(a.xyz() + (b.xyz() - a.xyz()) * t);
}
double lerp(double a, double b, double t) { return a + (b - a) * t; }

/// A unit vector orthogonal to the unit vector a: hint's part orthogonal to a, normalised; when
/// hint is (nearly) along a, the part of the coordinate axis least along a.
Double3 orthogonalTo(const Double3& a, const Double3& hint) {
  Double3 rest = hint - a * hint.dot(a);
  if (rest.lengthSquared() <= 1e-20 * hint.lengthSquared()) {  // a zero hint included
    const Double3 axis = std::fabs(a.x) <= std::fabs(a.y) && std::fabs(a.x) <= std::fabs(a.z)
                             ? Double3{1, 0, 0}
                         : std::fabs(a.y) <= std::fabs(a.z) ? Double3{0, 1, 0}
                                                            : Double3{0, 0, 1};
    rest = axis - a * axis.dot(a);
  }
  return rest / std::sqrt(rest.lengthSquared());
}

/// The unit vector a fraction t of the way from the unit vector a to the unit vector b along
/// the great circle through them (spherical interpolation: the angle turned grows evenly with
/// t). Opposite vectors have no one great circle: the turn is then towards `across` (its part
/// orthogonal to a), so that a path between opposite directions turns about the up vector
/// instead of passing through a zero direction, as a straight interpolation would.
Vector slerpUnit(const Vector& a, const Vector& b, double t, const Double3& across) {
  const double cosine = std::clamp(a.dot(b), -1.0, 1.0);
  const double angle = std::acos(cosine);
  const Double3 rest = b.xyz() - a.xyz() * cosine;  // b's part orthogonal to a
  const double restLength = std::sqrt(rest.lengthSquared());
  const Double3 towards = restLength > 1e-12 ? rest / restLength : orthogonalTo(a.xyz(), across);
  return Vector(a.xyz() * std::cos(angle * t) + towards * std::sin(angle * t)).normalized();
}

/// The unit direction a camera looks along.
Vector directionOf(const CameraSpec& c) {
  return c.target ? (*c.target - c.location).normalized() : c.to->normalized();
}

/// The orbit's centre of a camera.
Point orbitCentre(const CameraSpec& c) {
  if (c.target) return *c.target;
  const double d = c.focalDistance > 0 ? c.focalDistance : c.vpDistance;
  return c.location + c.to->normalized() * d;
}

/// The pieces of list between separators ("a,b" -> a, b; "" -> one empty piece).
std::vector<std::string> split(const std::string& list, char separator) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(separator, start);
    names.push_back(list.substr(start, comma - start));
    if (comma == std::string::npos) return names;
    start = comma + 1;
  }
}

}  // namespace

std::vector<CameraSpec> orbitCameras(const CameraSpec& camera, double degrees, int frames) {
  std::vector<CameraSpec> cameras;
  cameras.reserve(static_cast<std::size_t>(frames));
  const Point centre = orbitCentre(camera);
  const Double3 axis = camera.up.normalized().xyz();
  for (int k = 0; k < frames; ++k) {
    CameraSpec c = camera;
    const double angle = degrees * k / frames * kPi / 180;
    if (angle != 0) {  // frame 0 is the camera itself, bit for bit
      c.location = Point(centre.xyz() + rotated(camera.location.xyz() - centre.xyz(), axis, angle));
      if (c.to) c.to = Vector(rotated(camera.to->xyz(), axis, angle));
    }
    cameras.push_back(c);
  }
  return cameras;
}

std::vector<CameraSpec> viewPathCameras(const std::vector<CameraSpec>& views, int frames) {
  if (views.size() < 2) throw std::invalid_argument("viewPathCameras: fewer than two views");
  std::vector<CameraSpec> cameras;
  cameras.reserve(static_cast<std::size_t>(frames));
  const long long segments = static_cast<long long>(views.size()) - 1;
  for (int k = 0; k < frames; ++k) {
    // u = k·segments/(frames−1) = seg + t, in integers so that a view's frame is found exactly.
    const long long num = frames == 1 ? 0 : k * segments, den = frames == 1 ? 1 : frames - 1;
    const std::size_t seg = static_cast<std::size_t>(num / den);
    const long long rem = num % den;
    if (rem == 0) {
      cameras.push_back(views[seg]);
      continue;
    }
    const double t = static_cast<double>(rem) / static_cast<double>(den);
    const CameraSpec &a = views[seg], &b = views[seg + 1];
    CameraSpec c = a;
    c.location = lerp(a.location, b.location, t);
    const Vector aTo = directionOf(a), aUp = a.up.normalized();
    // Opposite up vectors turn through the direction's side; opposite directions about the up.
    Vector up = slerpUnit(aUp, b.up.normalized(), t, aTo.xyz().cross(aUp.xyz()));
    if (a.target && b.target) {
      c.target = lerp(*a.target, *b.target, t);
      c.to.reset();
    } else {
      const Vector to = slerpUnit(aTo, directionOf(b), t, aUp.xyz().cross(aTo.xyz()));
      up = Vector(orthogonalTo(to.xyz(), up.xyz()));  // orthogonal to the direction, as it must be
      c.to = to;
      c.target.reset();
    }
    c.up = up;
    c.vpWidth = lerp(a.vpWidth, b.vpWidth, t);
    c.vpHeight = lerp(a.vpHeight, b.vpHeight, t);
    c.vpDistance = lerp(a.vpDistance, b.vpDistance, t);
    c.aperture = lerp(a.aperture, b.aperture, t);
    c.focalDistance = lerp(a.focalDistance, b.focalDistance, t);
    cameras.push_back(c);
  }
  return cameras;
}

std::string AnimationPlan::framePath(int k) const {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%0*d.png", frameDigits(), k);
  return (directory / name).string();
}

int AnimationPlan::frameDigits() const {
  const int last = cameras.empty() ? 0 : static_cast<int>(cameras.size()) - 1;
  return std::max(4, static_cast<int>(std::to_string(last).size()));
}

std::string AnimationPlan::settleUnfinished(std::size_t written) const {
  const std::string dir = directory.string();
  if (written > 0)
    return std::to_string(written) + (written == 1 ? " whole frame" : " whole frames") +
           " written to " + dir;
  std::error_code ec;
  if (madeDirectory && fs::is_empty(directory, ec) && fs::remove(directory, ec))
    return "no frame written; " + dir + ", which this run made, removed";
  return "no frame written to " + dir;
}

std::optional<std::string> findOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  for (const std::string& dir : split(path, ':')) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / name;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate.string();
  }
  return std::nullopt;
}

AnimationPlan resolveAnimation(const AnimateArgs& args, bool writes) {
  if (args.orbit.has_value() == args.through.has_value())
    throw UsageError(args.orbit ? "--orbit and --through: give one camera path, not both"
                                : "give a camera path: --orbit DEGREES or --through VIEW,VIEW,...");
  if (args.orbit && !std::isfinite(*args.orbit))
    throw UsageError("--orbit: expected a finite number of degrees, got " +
                     formatNumber(*args.orbit));
  if (args.frame && (*args.frame < 0 || *args.frame >= args.frames))
    throw UsageError("--frame: expected a frame from 0 to " + std::to_string(args.frames - 1) +
                     " (--frames " + std::to_string(args.frames) + "), got " +
                     std::to_string(*args.frame));
  if (args.video && args.frame)
    throw UsageError("--video and --frame: a video needs every frame; render it without --frame");
  if (!(args.fps > 0) || !std::isfinite(args.fps) || args.fps > 1000)
    throw UsageError("--fps: expected a number of frames per second in (0, 1000], got " +
                     formatNumber(args.fps));

  AnimationPlan plan{
      resolveRenderRequest(args.scene, {.writesImage = false, .makesImage = true, .renders = true}),
      {},
      {},
      {},
      args.video,
      "",
      args.fps};
  const SceneDocument& doc = plan.request.doc;
  if (args.orbit) {
    plan.cameras = orbitCameras(doc.camera, *args.orbit, args.frames);
  } else {
    std::vector<std::string_view> known;
    for (const NamedView& v : doc.views) known.push_back(v.name);
    std::vector<std::string> names;
    if (*args.through == "all") {
      names.assign(known.begin(), known.end());
    } else {
      names = split(*args.through, ',');
    }
    if (names.size() < 2)
      throw UsageError("--through: a path needs at least two views, got " +
                       std::to_string(names.size()) + " ('" + *args.through + "'; " +
                       (known.empty() ? std::string("the scene has none")
                                      : "the scene's views: " + joinNames(known)) +
                       ")");
    std::vector<CameraSpec> views;
    for (const std::string& name : names) {
      const NamedView* found = nullptr;
      for (const NamedView& v : doc.views)
        if (v.name == name) found = &v;
      if (!found)
        throw UsageError(
            "--through: the scene has no view '" + name + "'" + didYouMean(name, known) + " (" +
            (known.empty() ? std::string("it has none") : "its views: " + joinNames(known)) + ")");
      CameraSpec c = found->camera;
      // A view gets --width/--height as `rt render --view` gives them, so that a frame on a
      // view is that render's image; a view whose size then differs from the scene camera's
      // is brought to it (every frame of an animation has one size).
      applyResolution(c, args.scene.width, args.scene.height);
      if (c.nX != doc.camera.nX || c.nY != doc.camera.nY)
        applyResolution(c, doc.camera.nX, doc.camera.nY);
      views.push_back(c);
    }
    // One frame cannot be both ends of the path.
    if (args.frames == 1)
      throw UsageError("--through: a path through " + std::to_string(views.size()) +
                       " views starts on '" + names.front() + "' and ends on '" + names.back() +
                       "', which takes at least 2 frames; got --frames 1 (one view alone: rt "
                       "render --view " +
                       names.front() + ")");
    plan.cameras = viewPathCameras(views, args.frames);
  }
  if (args.frame) {
    plan.frames = {*args.frame};
  } else {
    for (int k = 0; k < args.frames; ++k) plan.frames.push_back(k);
  }

  // The folder: created when missing (its parent must exist), then a frame's file tried there.
  const std::string dir = args.output.value_or((isSceneFileArgument(args.scene.argument)
                                                    ? fs::path(args.scene.argument).stem().string()
                                                    : args.scene.argument) +
                                               "-frames");
  plan.directory = dir;
  if (!writes) return plan;
  std::error_code ec;
  if (fs::exists(plan.directory, ec) && !fs::is_directory(plan.directory, ec))
    throw UsageError("-o: cannot write frames into '" + dir + "': it is not a directory");
  const fs::path parent =
      plan.directory.parent_path().empty() ? fs::path(".") : plan.directory.parent_path();
  if (!fs::is_directory(parent, ec))
    throw UsageError("-o: cannot write frames into '" + dir + "': the directory '" +
                     parent.string() + "' does not exist");
  // A video inside the frames' folder, which is made below: its checks once the folder exists.
  const bool videoInFrames =
      args.video && !fs::exists(plan.directory, ec) &&
      fs::path(*args.video).parent_path().lexically_normal() == plan.directory.lexically_normal();
  if (args.video && !videoInFrames) checkOutputWritable(*args.video, MP4_VIDEO, "--video");
  // Nothing written over a file the scene reads: the video (renamed over its path), and a frame
  // (written through a link) in a folder that is there already (a new one holds no file).
  if (args.video)
    checkOutputIsNoInput(*args.video, "--video", "the video", args.scene.argument, doc);
  if (fs::exists(plan.directory, ec))
    for (const int k : plan.frames)
      checkOutputIsNoInput(plan.framePath(k), "-o", "frame " + std::to_string(k),
                           args.scene.argument, doc);
  if (args.video) {
    const std::optional<std::string> ffmpeg = findOnPath("ffmpeg");
    if (!ffmpeg)
      throw UsageError(
          "--video: encoding a video needs ffmpeg, which is not on PATH; install it (apt-get "
          "install ffmpeg, or scripts/deps.sh --video), or leave out --video to write the frames "
          "only");
    plan.ffmpeg = *ffmpeg;
  }
  if (!fs::exists(plan.directory, ec)) {
    if (!fs::create_directory(plan.directory, ec))
      throw UsageError("-o: cannot create the directory '" + dir + "': " + ec.message());
    plan.madeDirectory = true;
  }
  try {
    if (videoInFrames) checkOutputWritable(*args.video, MP4_VIDEO, "--video");
    checkOutputWritable(plan.framePath(plan.frames.front()), PNG_IMAGE, "-o");
  } catch (...) {
    plan.settleUnfinished(0);  // a refusal leaves no folder behind
    throw;
  }
  return plan;
}

bool encodeVideo(const AnimationPlan& plan, const std::atomic<bool>* stop) {
  // ffmpeg picks the container from the name, so the temporary file keeps the ending.
  const fs::path video(*plan.video);
  const fs::path temporary =
      video.parent_path() / (".rt-" + std::to_string(::getpid()) + "-" + video.filename().string());
  const std::string pattern =
      (plan.directory / ("frame-%0" + std::to_string(plan.frameDigits()) + "d.png")).string();
  std::ostringstream fps;
  fps.precision(17);
  fps << plan.fps;
  // yuv420p, which every player reads, needs an even width and height: odd ones are padded.
  // The frames from 0 and exactly as many as this run rendered: frames an earlier run with more
  // of them left in the folder stay out. An option and its value a line.
  // clang-format off
  std::vector<std::string> argv{plan.ffmpeg,
                                "-hide_banner",
                                "-loglevel", "error",
                                "-nostdin",
                                "-y",
                                "-framerate", fps.str(),
                                "-start_number", "0",
                                "-i", pattern,
                                "-frames:v", std::to_string(plan.frames.size()),
                                "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                "-c:v", "libx264",
                                "-pix_fmt", "yuv420p",
                                temporary.string()};
  // clang-format on
  std::vector<char*> cargv;
  for (std::string& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  int pipeFd[2];
  if (::pipe(pipeFd) != 0)
    throw std::runtime_error(std::string("cannot start ffmpeg: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pipeFd[0]);
    ::close(pipeFd[1]);
    throw std::runtime_error(std::string("cannot start ffmpeg: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::dup2(pipeFd[1], STDERR_FILENO);
    ::dup2(pipeFd[1], STDOUT_FILENO);
    ::close(pipeFd[0]);
    ::close(pipeFd[1]);
    ::execv(cargv[0], cargv.data());
    ::_exit(127);
  }
  ::close(pipeFd[1]);
  // ffmpeg's messages, read until it closes its end; every tenth of a second the stop flag is
  // looked at, and once it is raised ffmpeg is ended (a terminal's Ctrl-C reaches ffmpeg too,
  // a signal to this process alone does not).
  std::string message;
  bool ended = false;
  for (;;) {
    if (!ended && stop != nullptr && stop->load()) {
      ::kill(pid, SIGTERM);
      ended = true;
    }
    pollfd ready{pipeFd[0], POLLIN, 0};
    const int events = ::poll(&ready, 1, 100);
    if (events == 0 || (events < 0 && errno == EINTR)) continue;
    char buffer[4096];
    const ssize_t n = events < 0 ? 0 : ::read(pipeFd[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    message.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipeFd[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::error_code ec;
  const bool encoded = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  // Stopped: ffmpeg failed once the flag was raised, or a Ctrl-C or kill ended it.
  if (!encoded &&
      (ended || (stop != nullptr && stop->load()) ||
       (WIFSIGNALED(status) && (WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGTERM)))) {
    fs::remove(temporary, ec);
    return false;
  }
  if (!encoded) {
    fs::remove(temporary, ec);
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r'))
      message.pop_back();
    throw std::runtime_error("ffmpeg could not encode " + *plan.video + " from " + pattern +
                             (message.empty() ? std::string(" (no message)") : ": " + message));
  }
  fs::rename(temporary, video, ec);
  if (ec) {
    // The rename's reason: removing the temporary file (when there is one) must not replace it.
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error("cannot write '" + *plan.video + "': " + ec.message());
  }
  return true;
}

}  // namespace rt::cli
