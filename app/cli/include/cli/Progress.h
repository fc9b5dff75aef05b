#pragma once
/// @file Progress.h
/// Progress of a render, reported from a thread of its own so that the render loop only counts.
///
/// The render loop adds a finished block's pixels to an atomic counter, once per block (never
/// per ray), and ProgressMonitor reads the count a few times a second and prints to stderr: on
/// a terminal a percentage redrawn in place (rows done, rays per second, time left), otherwise
/// one plain line per 10% with the same figures, which reads well in a log.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <iosfwd>
#include <mutex>
#include <string>
#include <thread>

namespace rt::cli {

/// Prints progress while it lives. Stop it (or destroy it) before writing to err again.
class ProgressMonitor {
 public:
  enum class Style { Terminal, Lines };

  /// @param done the pixels finished so far (the render loop adds each block's when it is done)
  /// @param total the image's pixels
  /// @param rays the rays of every kind cast so far (added with the pixels), for the rate
  /// @param rowLength pixels per image row (nX), to report rows on a terminal.
  ProgressMonitor(std::ostream& err, Style style, const std::atomic<std::uint64_t>& done,
                  const std::atomic<std::uint64_t>& rays, std::uint64_t total,
                  std::uint64_t rowLength);
  ~ProgressMonitor();
  ProgressMonitor(const ProgressMonitor&) = delete;
  ProgressMonitor& operator=(const ProgressMonitor&) = delete;

  /// Stops the thread after a last report (the terminal line is then ended).
  void stop();

 private:
  void run();
  void report(bool last);
  /// "1234567 rays/s, 12.3 s left" after done of total_ pixels, or "" before the first.
  std::string rateAndTimeLeft(std::uint64_t done) const;

  std::ostream& err_;
  Style style_;
  const std::atomic<std::uint64_t>& done_;
  const std::atomic<std::uint64_t>& rays_;
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
