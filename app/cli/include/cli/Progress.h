#pragma once
/// @file Progress.h
/// Progress of a render, reported from a thread of its own so that the render loop only counts.
///
/// The camera asks its tracer for one colour per pixel; CountingTracer sits between the two and
/// counts those primary rays (one relaxed atomic increment, nothing else), and ProgressMonitor
/// reads the count a few times a second and prints to stderr: on a terminal a percentage
/// redrawn in place (rows done, rate, time left), otherwise one plain line per 10%, which reads
/// well in a log.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <iosfwd>
#include <mutex>
#include <string>
#include <thread>

#include "camera/RayTracer.h"

namespace rt::cli {

/// Passes every ray on to inner and counts them. Safe to call from several threads.
class CountingTracer final : public RayTracer {
 public:
  /// @param inner must outlive this tracer.
  explicit CountingTracer(const RayTracer& inner)
      : RayTracer(inner.scene(), &inner.intersector()), inner_(inner) {}

  Color traceRay(const Ray& ray) const override {
    const Color c = inner_.traceRay(ray);
    count_.fetch_add(1, std::memory_order_relaxed);
    return c;
  }

  std::uint64_t count() const { return count_.load(std::memory_order_relaxed); }

 private:
  const RayTracer& inner_;
  mutable std::atomic<std::uint64_t> count_{0};
};

/// Prints progress while it lives. Stop it (or destroy it) before writing to err again.
class ProgressMonitor {
 public:
  enum class Style { Terminal, Lines };

  /// @param rowLength rays per image row (nX), to report rows on a terminal.
  ProgressMonitor(std::ostream& err, Style style, const CountingTracer& counter,
                  std::uint64_t total, std::uint64_t rowLength);
  ~ProgressMonitor();
  ProgressMonitor(const ProgressMonitor&) = delete;
  ProgressMonitor& operator=(const ProgressMonitor&) = delete;

  /// Stops the thread after a last report (the terminal line is then ended).
  void stop();

 private:
  void run();
  void report(bool last);

  std::ostream& err_;
  Style style_;
  const CountingTracer& counter_;
  std::uint64_t total_, rowLength_;
  std::chrono::steady_clock::time_point start_;
  int lastDecile_ = 0;                         ///< Lines: the last 10% step printed
  std::uint64_t lastRow_ = ~std::uint64_t{0};  ///< Terminal: the last row count shown
  bool drewLine_ = false;                      ///< Terminal: a line is open and must be ended
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

/// "0.042 s", "12.3 s", "1 min 21 s", "1 h 21 min": how long a render took.
std::string formatDuration(double seconds);

}  // namespace rt::cli
