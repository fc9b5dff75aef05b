// The benchmarks' harness (benchmark/Scaling.h): what timeRenders and measureGalaxy
// report besides times, which are never asserted beyond > 0: the thread counts, the rays, the
// same bits on every thread count, a stop, the galaxy's shapes measured in a child process.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <optional>
#include <stdexcept>

#include "benchmark/Measure.h"
#include "benchmark/Scaling.h"
#include "camera/Camera.h"
#include "glossy/Galaxy.h"

namespace rt {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(ScalingTests, timeRendersComparesThreadCounts) {
  const GalaxyRender g(GalaxyParams{.stars = 1000, .diffusion = false});
  const Camera camera = referenceView(g.setup, 16, 16);
  const CenterSampler sampler;
  const RenderContext context{camera, *g.tracer, sampler};
  Image image(16, 16);
  const RayCounts expected = renderImage(context, image, {.threads = 1}).counts;
  // TC01: two thread counts, two renders each: the same rays and the same bits on both
  const TimedRenders t = timeRenders(context, {.threads = {1, 2}, .repeat = 2, .tileSize = 4});
  EXPECT_EQ(t.counts, 2);
  EXPECT_EQ(t.threads[0], 1);
  EXPECT_EQ(t.threads[1], 2);
  EXPECT_EQ(t.rays[0], expected);
  EXPECT_EQ(t.rays[1], expected);
  EXPECT_EQ(t.rays[0].primary, 256u);
  EXPECT_TRUE(t.sameImage);
  EXPECT_FALSE(t.interrupted);
  for (int k = 0; k < 2; ++k) {
    EXPECT_GT(t.wall[k], 0) << k;
    EXPECT_LE(t.fastest[k], t.wall[k]) << k;
  }
  // TC02: one thread count: nothing to compare, the same image by definition
  const TimedRenders one = timeRenders(context, {.threads = {3}, .tileSize = 4});
  EXPECT_EQ(one.counts, 1);
  EXPECT_EQ(one.threads[0], 3);
  EXPECT_TRUE(one.sameImage);
  // TC03: a stop raised before the first render: interrupted, nothing rendered
  const std::atomic<bool> stop{true};
  EXPECT_TRUE(timeRenders(context, {.threads = {1}, .stop = &stop}).interrupted);
  // TC04: invalid options, named
  EXPECT_THAT([&] { timeRenders(context, {.threads = {}}); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("0 thread counts, expected 1 or 2")));
  EXPECT_THAT(
      [&] {
        timeRenders(context, {.threads = {1, 2, 3}});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("3 thread counts, expected 1 or 2")));
  EXPECT_THAT([&] { timeRenders(context, {.repeat = 0}); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("repeat is 0, expected 1 or more")));
}

TEST(ScalingTests, measureGalaxyInAProcessOfItsOwn) {
  // TC01: the galaxy of 1000 stars (1065 shapes, as rt bench --scaling's tests count them),
  // one camera ray per pixel of an 8 x 8 image, a peak memory of the child's own
  const std::optional<ScalingMeasurement> m = measureGalaxy(1000, 8, 8, {.threads = {1}});
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->shapes, 1065u);
  EXPECT_GT(m->structureBytes, 0u);
  EXPECT_GT(m->peakBytes, 0);
  EXPECT_EQ(m->renders.counts, 1);
  EXPECT_EQ(m->renders.rays[0].primary, 64u);
  // TC02: through the grid: the same shapes and rays, the grid's memory
  const std::optional<ScalingMeasurement> g =
      measureGalaxy(1000, 8, 8, {.threads = {1}}, ScalingAccel::Grid);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->shapes, 1065u);
  EXPECT_GT(g->structureBytes, 0u);
  EXPECT_EQ(g->renders.rays[0].primary, 64u);
  EXPECT_EQ(g->renders.rays[0].secondary, m->renders.rays[0].secondary);
  EXPECT_EQ(g->renders.rays[0].shadow, m->renders.rays[0].shadow);
  // TC03: the child's exception, with its message
  EXPECT_THAT([] { measureGalaxy(-1, 8, 8, {}); },
              ThrowsMessage<std::runtime_error>(HasSubstr("stars")));
  // TC04: stopped: nothing
  const std::atomic<bool> stop{true};
  EXPECT_EQ(measureGalaxy(1000, 8, 8, {.stop = &stop}), std::nullopt);
}

TEST(ScalingTests, measureTeapotInAProcessOfItsOwn) {
  // TC01: the course's teapot, 992 triangles and no shape, a ray per pixel of an 8 x 8 image;
  // the mesh's arrays (800 vertices of 24 bytes, 992 index triples of 12) and the BVH's bytes,
  // a peak of the child's own
  const std::optional<ScalingMeasurement> m = measureTeapot(4, 8, 8, {.threads = {1}});
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->shapes, 0u);
  EXPECT_EQ(m->triangles, 992u);
  EXPECT_EQ(m->meshBytes, 800u * 24 + 992u * 12);
  EXPECT_GT(m->structureBytes, 0u);
  EXPECT_GT(m->peakBytes, 0);
  EXPECT_EQ(m->renders.rays[0].primary, 64u);
  // TC02: through the grid: the same triangles and rays
  const std::optional<ScalingMeasurement> g =
      measureTeapot(4, 8, 8, {.threads = {1}}, ScalingAccel::Grid);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->triangles, 992u);
  EXPECT_GT(g->structureBytes, 0u);
  EXPECT_EQ(g->renders.rays[0].primary, 64u);
  EXPECT_EQ(g->renders.rays[0].shadow, m->renders.rays[0].shadow);
  // TC03: a finer teapot: 64·d² − 8·d triangles
  EXPECT_EQ(measureTeapot(13, 4, 4, {.threads = {1}})->triangles, 10712u);
  // TC11: a detail out of range: the child's message
  EXPECT_THAT([] { measureTeapot(0, 8, 8, {}); },
              ThrowsMessage<std::runtime_error>(HasSubstr("detail")));
  // TC12: stopped: nothing
  const std::atomic<bool> stop{true};
  EXPECT_EQ(measureTeapot(4, 8, 8, {.stop = &stop}), std::nullopt);
}

}  // namespace
}  // namespace rt
