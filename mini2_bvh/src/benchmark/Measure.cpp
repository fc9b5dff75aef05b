#include "benchmark/Measure.h"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <chrono>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <ctime>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>

namespace rt {

namespace {

double seconds(const timeval& t) {
  return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

[[noreturn]] void throwErrno(const char* what) {
  throw std::system_error(errno, std::generic_category(), what);
}

/// The first byte the child sends: what follows it.
enum class ChildStatus : unsigned char {
  Done = 0,    ///< the result's bytes
  Failed = 1,  ///< the message of the exception work threw
};

/// Writes all of bytes to fd (the child's end of the pipe); gives up silently on an error (the
/// parent then sees a short message and says so).
void writeAll(int fd, const void* bytes, std::size_t size) {
  const char* p = static_cast<const char*>(bytes);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
}

/// The child's side: runs work, sends its status and result (or message), ends. Never returns.
[[noreturn]] void childMain(int fd, const std::function<void(std::span<std::byte>)>& work,
                            std::span<std::byte> result) {
  ChildStatus status = ChildStatus::Done;
  std::string message;
  try {
    work(result);
  } catch (const std::bad_alloc&) {
    status = ChildStatus::Failed;
    message = "out of memory";
  } catch (const std::exception& e) {
    status = ChildStatus::Failed;
    message = e.what();
  } catch (...) {
    status = ChildStatus::Failed;
    message = "an unknown exception";
  }
  writeAll(fd, &status, 1);
  if (status == ChildStatus::Done)
    writeAll(fd, result.data(), result.size());
  else
    writeAll(fd, message.data(), message.size());
  ::close(fd);
  ::_exit(0);
}

}  // namespace

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double processCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return seconds(u.ru_utime) + seconds(u.ru_stime);
}

double median(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("median: no values");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

const Intersectable* TimedStructure::get() const noexcept {
  return bvh ? static_cast<const Intersectable*>(bvh.get()) : grid.get();
}

std::size_t TimedStructure::memoryBytes() const noexcept {
  return bvh ? bvh->memoryBytes() : grid ? grid->memoryBytes() : 0;
}

TimedStructure buildTimed(const Geometries& geometries, ScalingAccel accel) {
  TimedStructure s;
  // Wall time: the BVH builds on every core (the calling thread's CPU time would miss the
  // others' share).
  const auto start = std::chrono::steady_clock::now();
  if (accel == ScalingAccel::Grid)
    s.grid = std::make_unique<Grid>(geometries);
  else
    s.bvh = std::make_unique<WideBvh>(geometries);
  s.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

GalaxyRender::GalaxyRender(const GalaxyParams& params, ScalingAccel accel) {
  const double start = threadCpuSeconds();
  setup = galaxy(params);
  generateSeconds = threadCpuSeconds() - start;
  structure = buildTimed(setup.scene.geometries, accel);
  tracer = std::make_unique<BeamTracer>(setup.scene, structure.get());
}

TeapotRender::TeapotRender(int detail, ScalingAccel accel) {
  const double start = threadCpuSeconds();
  setup = teapotScene({.detail = detail});
  generateSeconds = threadCpuSeconds() - start;
  structure = buildTimed(setup.scene.geometries, accel);
  tracer = std::make_unique<WhittedTracer>(setup.scene, structure.get());
}

Camera middleView(CameraSpec spec, int nX, int nY) {
  if (nX * spec.vpHeight < nY * spec.vpWidth)
    spec.vpWidth = spec.vpHeight * nX / nY;
  else
    spec.vpHeight = spec.vpWidth * nY / nX;
  spec.nX = nX;
  spec.nY = nY;
  return spec.builder().build();
}

Camera referenceView(const GalaxySetup& g, int nX, int nY) { return middleView(g.camera, nX, nY); }

std::optional<std::int64_t> runInChildProcess(const std::function<void(std::span<std::byte>)>& work,
                                              std::span<std::byte> result,
                                              const std::atomic<bool>* stop) {
  int fds[2];
  if (::pipe(fds) != 0) throwErrno("runInChildProcess: pipe");
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    errno = error;
    throwErrno("runInChildProcess: fork");
  }
  if (pid == 0) {
    // The child must not outlive this process (killed by a second Ctrl-C, say): it would go on
    // rendering for nobody. Linux's parent-death signal, and a check for a parent already gone.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(1);
    ::close(fds[0]);
    childMain(fds[1], work, result);
  }
  ::close(fds[1]);

  // Read until the child closes its end (it has sent everything, or died), looking at the stop
  // flag between polls.
  std::string received;
  bool stopped = false;
  for (;;) {
    if (stop != nullptr && stop->load()) {
      stopped = true;
      ::kill(pid, SIGKILL);
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, 50);
    if (ready < 0 && errno != EINTR) {
      const int error = errno;
      ::kill(pid, SIGKILL);
      ::close(fds[0]);
      ::waitpid(pid, nullptr, 0);
      errno = error;
      throwErrno("runInChildProcess: poll");
    }
    if (ready <= 0) continue;
    char buffer[4096];
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file (or an error: the message check below says so)
    received.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);

  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR) throwErrno("runInChildProcess: wait4");
  if (stopped) return std::nullopt;
  if (WIFSIGNALED(status))
    throw std::runtime_error("the measuring child process was ended by signal " +
                             std::to_string(WTERMSIG(status)));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the measuring child process exited with status " +
                             std::to_string(WEXITSTATUS(status)));
  if (!received.empty() && received[0] == static_cast<char>(ChildStatus::Failed))
    throw std::runtime_error(received.substr(1));
  if (received.size() != 1 + result.size() || received[0] != static_cast<char>(ChildStatus::Done))
    throw std::runtime_error("the measuring child process sent " + std::to_string(received.size()) +
                             " bytes, expected " + std::to_string(1 + result.size()));
  std::copy(received.begin() + 1, received.end(), reinterpret_cast<char*>(result.data()));
  return static_cast<std::int64_t>(usage.ru_maxrss) * 1024;  // Linux: ru_maxrss is in kB
}

}  // namespace rt
