// The progress line's time left (cli/Progress.h's TimeLeft), fed the pixels a render finished
// over time: said on a render whose pixels cost the same, held back while the cost per pixel
// changes (the galaxy: empty sky above and below, a core that costs 40 times more per pixel).
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "cli/Progress.h"

namespace rt::cli {
namespace {

constexpr std::uint64_t TOTAL = 1000;
/// A step of the feed: this many more pixels done, after this many more seconds.
using Step = std::pair<std::uint64_t, double>;

/// The time left after every step (the first observation is 0 pixels at 0 s). Seconds are
/// multiples of 1/16, so the elapsed sums are exact.
std::vector<std::optional<double>> feed(const std::vector<Step>& steps) {
  TimeLeft left(TOTAL);
  left.observe(0, 0);
  std::vector<std::optional<double>> out;
  double elapsed = 0;
  std::uint64_t done = 0;
  for (const auto& [pixels, seconds] : steps) {
    done += pixels;
    elapsed += seconds;
    left.observe(elapsed, done);
    out.push_back(left.secondsLeft());
  }
  return out;
}

std::vector<Step> repeated(int times, Step step) {
  return std::vector<Step>(static_cast<std::size_t>(times), step);
}

std::vector<Step> concat(std::initializer_list<std::vector<Step>> parts) {
  std::vector<Step> all;
  for (const auto& p : parts) all.insert(all.end(), p.begin(), p.end());
  return all;
}

/// (total - done) / (done / elapsed): what the estimate says at done pixels after elapsed s.
double expected(std::uint64_t done, double elapsed) {
  return static_cast<double>(TOTAL - done) / (static_cast<double>(done) / elapsed);
}

TEST(ProgressTests, timeLeftOfAnEvenRender) {
  // 50 pixels every 0.5 s: nothing before MIN_SECONDS (1 s), then the exact time left, nothing
  // once done.
  const auto left = feed(repeated(20, {50, 0.5}));
  EXPECT_EQ(left[0], std::nullopt);  // 50 pixels, 0.5 s
  for (std::size_t i = 1; i < 19; ++i) {
    const std::uint64_t done = 50 * (i + 1);
    ASSERT_TRUE(left[i].has_value()) << done << " pixels";
    EXPECT_EQ(*left[i], 10.0 - 0.5 * static_cast<double>(i + 1)) << done << " pixels";
  }
  EXPECT_EQ(left[19], std::nullopt);  // every pixel done
}

TEST(ProgressTests, nothingWhileTheCostChanges) {
  // The galaxy: the top 30 % is sky (50 pixels in 1/16 s), the middle 40 % the core
  // (50 pixels in 2.5 s), the bottom 30 % sky again; 20.75 s in all. Counting pixels said
  // "0.5 s left" at 10 % and 20 % (and 1.2 min at 40 %); the cost per pixel never settles for a
  // whole window, so nothing is said at all.
  const auto left =
      feed(concat({repeated(6, {50, 0.0625}), repeated(8, {50, 2.5}), repeated(6, {50, 0.0625})}));
  for (std::size_t i = 0; i < left.size(); ++i)
    EXPECT_EQ(left[i], std::nullopt) << 50 * (i + 1) << " pixels";
}

TEST(ProgressTests, saidOnceTheCostSettles) {
  // Sky for 20 %, a core of 70 %, sky for the last 10 % (35.375 s in all): nothing over the sky
  // nor while the core's cost is new to the whole render's rate; from 60 % (20.25 s in, 15.1 s
  // truly left) the whole render's rate is within 1.5 times the core's, and it is said; nothing
  // again once the last window's rate changes (the bottom sky, 95 %).
  const auto left =
      feed(concat({repeated(4, {50, 0.0625}), repeated(14, {50, 2.5}), repeated(2, {50, 0.0625})}));
  for (std::size_t i = 0; i < 11; ++i)
    EXPECT_EQ(left[i], std::nullopt) << 50 * (i + 1) << " pixels";
  double elapsed = 0.25;  // the sky's 200 pixels
  for (std::size_t i = 11; i < 18; ++i) {
    const std::uint64_t done = 50 * (i + 1);
    elapsed = 0.25 + 2.5 * static_cast<double>(done / 50 - 4);
    ASSERT_TRUE(left[i].has_value()) << done << " pixels";
    EXPECT_EQ(*left[i], expected(done, elapsed)) << done << " pixels";
  }
  EXPECT_EQ(*left[11], 13.5);  // at 600 pixels, 20.25 s: 400 / (600 / 20.25)
  EXPECT_EQ(left[18], std::nullopt);
  EXPECT_EQ(left[19], std::nullopt);
}

TEST(ProgressTests, waitsForAWindowOfPixels) {
  // Two seconds of render but less than a tenth of the pixels: no rate to compare yet.
  TimeLeft left(TOTAL);
  left.observe(0, 0);
  left.observe(2, 99);
  EXPECT_EQ(left.secondsLeft(), std::nullopt);
  left.observe(2.5, 100);  // a window, at an even rate since the start
  ASSERT_TRUE(left.secondsLeft().has_value());
  EXPECT_EQ(*left.secondsLeft(), expected(100, 2.5));
  // No observation at all: nothing.
  EXPECT_EQ(TimeLeft(TOTAL).secondsLeft(), std::nullopt);
}

}  // namespace
}  // namespace rt::cli
