#include "cli/Progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

namespace rt::cli {

namespace {
constexpr auto kPollInterval = std::chrono::milliseconds(100);
}

std::string formatDuration(double seconds) {
  char buf[64];
  if (seconds < 10) {
    std::snprintf(buf, sizeof buf, "%.3f s", seconds);
  } else if (seconds < 60) {
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  } else if (seconds < 3600) {
    const long s = std::lround(seconds);
    std::snprintf(buf, sizeof buf, "%ld min %ld s", s / 60, s % 60);
  } else {
    const long m = std::lround(seconds / 60);
    std::snprintf(buf, sizeof buf, "%ld h %ld min", m / 60, m % 60);
  }
  return buf;
}

void TimeLeft::observe(double elapsed, std::uint64_t done) {
  recent_.push_back({elapsed, std::min(done, total_)});
  // Keep one observation at or before the window's start, none older.
  const double window = WINDOW * static_cast<double>(total_);
  while (recent_.size() > 2 && static_cast<double>(recent_.back().done - recent_[1].done) >= window)
    recent_.pop_front();
}

std::optional<double> TimeLeft::rateOver(double pixels) const {
  const Observation& now = recent_.back();
  // The latest observation at least `pixels` before now (recent_ starts at or before the window).
  for (auto it = recent_.rbegin(); it != recent_.rend(); ++it)
    if (static_cast<double>(now.done - it->done) >= pixels)
      return now.elapsed > it->elapsed ? std::optional(static_cast<double>(now.done - it->done) /
                                                       (now.elapsed - it->elapsed))
                                       : std::nullopt;
  return std::nullopt;
}

std::optional<double> TimeLeft::secondsLeft() const {
  if (recent_.empty()) return std::nullopt;
  const Observation& now = recent_.back();
  if (now.done >= total_ || now.elapsed < MIN_SECONDS) return std::nullopt;
  const double overall = static_cast<double>(now.done) / now.elapsed;
  const double window = WINDOW * static_cast<double>(total_);
  // Steady: the last window's rate and its last half's both near the whole render's (the
  // half catches a change of cost that the whole window only half sees yet).
  for (const double pixels : {window, window / 2}) {
    const std::optional<double> recent = rateOver(pixels);
    if (!recent || *recent > overall * MAX_CHANGE || *recent * MAX_CHANGE < overall)
      return std::nullopt;
  }
  return static_cast<double>(total_ - now.done) / overall;
}

ProgressMonitor::ProgressMonitor(std::ostream& err, Style style,
                                 const std::atomic<std::uint64_t>& done,
                                 const std::atomic<std::uint64_t>& rays, std::uint64_t total,
                                 std::uint64_t rowLength, std::string program)
    : err_(err),
      program_(std::move(program)),
      style_(style),
      done_(done),
      rays_(rays),
      total_(total == 0 ? 1 : total),
      rowLength_(rowLength == 0 ? 1 : rowLength),
      start_(std::chrono::steady_clock::now()),
      timeLeft_(total_),
      thread_([this] { run(); }) {}

ProgressMonitor::~ProgressMonitor() { stop(); }

void ProgressMonitor::stop() {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
  report(true);
}

void ProgressMonitor::run() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, kPollInterval, [this] { return stopping_; })) report(false);
}

std::string ProgressMonitor::rateAndTimeLeft(std::uint64_t done, double elapsed) const {
  if (elapsed <= 0 || done == 0) return "";
  // Rays of every kind per second: the figure that compares tracers, accelerations and thread
  // counts.
  const double rays = static_cast<double>(rays_.load(std::memory_order_relaxed));
  std::ostringstream os;
  os << static_cast<std::uint64_t>(rays / elapsed) << " rays/s";
  if (const std::optional<double> left = timeLeft_.secondsLeft())
    os << ", " << formatDuration(*left) << " left";
  return os.str();
}

void ProgressMonitor::report(bool last) {
  const std::uint64_t done = std::min(done_.load(std::memory_order_relaxed), total_);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  timeLeft_.observe(elapsed, done);  // every poll, so that the recent rate sees every step
  if (style_ == Style::Lines) {
    // One line per 10% step reached; steps passed between two polls are all printed, so the
    // log always reads 10%, 20%, ... in order (the figures are those of the poll).
    const int decile = static_cast<int>(done * 10 / total_);
    if (decile > lastDecile_) {
      const std::string figures = rateAndTimeLeft(done, elapsed);
      for (int d = lastDecile_ + 1; d <= decile; ++d) {
        err_ << program_ << ": rendering " << d * 10 << "%";
        if (!figures.empty()) err_ << " (" << figures << ")";
        err_ << "\n";
      }
      err_.flush();
    }
    lastDecile_ = std::max(lastDecile_, decile);
    return;
  }
  const std::uint64_t rows = done / rowLength_;
  if (rows != lastRow_ || last) {
    lastRow_ = rows;
    std::ostringstream line;
    line << "\r" << program_ << ": rendering " << (done * 100 / total_) << "% (" << rows << "/"
         << total_ / rowLength_ << " rows";
    if (const std::string figures = rateAndTimeLeft(done, elapsed); !figures.empty())
      line << ", " << figures;
    line << ")\x1b[K";  // erase what a longer previous line left
    err_ << line.str() << std::flush;
    drewLine_ = true;
  }
  if (last && drewLine_) err_ << "\n" << std::flush;
}

}  // namespace rt::cli
