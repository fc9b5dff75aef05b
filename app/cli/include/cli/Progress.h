#pragma once
/// @file Progress.h
/// Progress of a render, reported from a thread of its own so that the render loop only counts.
///
/// The render loop adds a finished block's pixels to an atomic counter, once per block (never
/// per ray), and ProgressMonitor reads the count a few times a second and prints to stderr: on
/// a terminal a percentage redrawn in place (rows done, rays per second, time left), otherwise
/// one plain line per 10% with the same figures, which reads well in a log. The time left is
/// said only while it means something (TimeLeft).

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <iosfwd>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace rt::cli {

/// The time left of a render, from the pixels done over time, said only when it means
/// something. The pool hands out tiles band by band from the top, and tiles cost very different
/// amounts (the galaxy's top rows are empty sky, one ray a pixel; its core costs a thousand
/// times more): a rate measured on the finished tiles alone says nothing of the others. So the
/// time left is the pixels left at the whole render's rate, said only while that rate is steady:
///
///     overall   = done / elapsed
///     recent    = the rates over the last WINDOW of the image's pixels and over its last half
///     time left = (total - done) / overall,  when elapsed >= MIN_SECONDS and both recent rates
///                                            are within a factor MAX_CHANGE of overall
///
/// Before that (and while the cost per pixel changes) it says nothing. Ray counts would not do
/// better: rays per pixel so far times the pixels left, at the rays per second so far, is the
/// same figure as the pixels' own rate.
class TimeLeft {
 public:
  /// The share of the image's pixels the recent rate is measured over.
  static constexpr double WINDOW = 0.1;
  /// The most the recent rate may differ from the overall one, as a factor, for a time left.
  static constexpr double MAX_CHANGE = 1.5;
  /// Less than this much render time is too little to tell a rate (a 0.1 s render needs none).
  static constexpr double MIN_SECONDS = 1.0;

  /// @param total the image's pixels (at least 1)
  explicit TimeLeft(std::uint64_t total) noexcept : total_(total == 0 ? 1 : total) {}

  /// Adds an observation: done pixels finished after elapsed seconds (both never decreasing).
  void observe(double elapsed, std::uint64_t done);
  /// The seconds left after the last observation, or nothing while the rate is not steady.
  std::optional<double> secondsLeft() const;

 private:
  struct Observation {
    double elapsed;
    std::uint64_t done;
  };
  /// The rate (pixels per second) over the last `pixels` pixels done, or nothing before them.
  std::optional<double> rateOver(double pixels) const;

  std::uint64_t total_;
  /// The observations of the last WINDOW of pixels, and the last one before them.
  std::deque<Observation> recent_;
};

/// Prints progress while it lives. Stop it (or destroy it) before writing to err again.
class ProgressMonitor {
 public:
  enum class Style { Terminal, Lines };

  /// @param done the pixels finished so far (the render loop adds each block's when it is done)
  /// @param total the image's pixels
  /// @param rays the rays of every kind cast so far (added with the pixels), for the rate
  /// @param rowLength pixels per image row (nX), to report rows on a terminal.
  /// @param program what each line starts with ("rt: rendering 10%")
  ProgressMonitor(std::ostream& err, Style style, const std::atomic<std::uint64_t>& done,
                  const std::atomic<std::uint64_t>& rays, std::uint64_t total,
                  std::uint64_t rowLength, std::string program = "rt");
  ~ProgressMonitor();
  ProgressMonitor(const ProgressMonitor&) = delete;
  ProgressMonitor& operator=(const ProgressMonitor&) = delete;

  /// Stops the thread after a last report (the terminal line is then ended).
  void stop();

 private:
  void run();
  void report(bool last);
  /// "1234567 rays/s, 12.3 s left" after done of total_ pixels ("1234567 rays/s" while the time
  /// left means nothing: TimeLeft), or "" before the first.
  std::string rateAndTimeLeft(std::uint64_t done, double elapsed) const;

  std::ostream& err_;
  std::string program_;
  Style style_;
  const std::atomic<std::uint64_t>& done_;
  const std::atomic<std::uint64_t>& rays_;
  std::uint64_t total_, rowLength_;
  std::chrono::steady_clock::time_point start_;
  TimeLeft timeLeft_;
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
