// Mini project 1: every random number depends only on (seed, pixel, sample, dimension), so a
// sampled image is the same however it is cut into blocks, a pixel rendered alone has the colour
// it has in the whole image, and the seed changes the noise.
#include <gtest/gtest.h>

#include <memory>

#include "camera/Camera.h"
#include "glossy/BeamTracer.h"
#include "glossy/Galaxy.h"
#include "glossy/Samplers.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;

/// The image's size, and its tiles' side: tiles that do not divide it, so that some are cut.
constexpr int W = 16, H = 10, TILE = 5;

/// A small galaxy (7 arms of 12), with its glass blurring (beams), sized lights (soft shadows,
/// two rays each: the cost of a test under the sanitizers), seen from "inside" at W x H pixels.
struct Fixture {
  GalaxySetup g = [] {
    GalaxyParams p;
    p.arms = 7;
    p.perArm = 12;
    GalaxySetup setup = galaxy(p);
    for (LightSource& light : setup.scene.lights)
      std::get<SpotLight>(light).setRadius(1.5).setShadowSamples(2);
    for (Appearance& a : setup.scene.appearances)
      if (a.material.refractedBeam.isBeam())
        a.material.reflectedBeam = a.material.refractedBeam = {12, 0.2, 3};
    return setup;
  }();
  BeamTracer tracer{g.scene};
  Camera camera = [this] {
    CameraSpec spec = g.views[2].camera;  // "inside"
    spec.nX = W;
    spec.nY = H;
    spec.aperture = 0.3;
    spec.focalDistance = 28;
    return spec.builder().build();
  }();
};

TEST(DeterminismTests, blocksPixelsAndSeeds) {
  const Fixture f;
  for (const SamplingSettings& settings :
       {SamplingSettings{.samples = 2, .lensSamples = 2, .seed = 5},
        SamplingSettings{
            .adaptive = true, .adaptiveThreshold = 8, .adaptiveDepth = 2, .seed = 5}}) {
    const std::unique_ptr<PixelSampler> sampler = makePixelSampler(settings);
    // ============ Equivalence Partitions Tests ==============
    // TC01: the whole image in one block, and the same image in 5 x 5 tiles rendered last tile
    // first (the last column of tiles one pixel wide): the same bits, and the same ray counts
    Image whole(W, H), tiled(W, H);
    const RayCounts a = renderBlock({f.camera, f.tracer, *sampler}, {0, 0, W, H}, whole);
    RayCounts b;
    for (int y0 = (H - 1) / TILE * TILE; y0 >= 0; y0 -= TILE)
      for (int x0 = (W - 1) / TILE * TILE; x0 >= 0; x0 -= TILE)
        b += renderBlock({f.camera, f.tracer, *sampler},
                         {x0, y0, std::min(x0 + TILE, W), std::min(y0 + TILE, H)}, tiled);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        ASSERT_TRUE(sameBits(whole.pixel(x, y), tiled.pixel(x, y))) << x << "," << y;
    EXPECT_EQ(a, b);
    EXPECT_GT(a.secondary, a.primary);  // the glass's beams were cast
    EXPECT_GT(a.shadow, a.primary);     // and the soft shadows' rays
    // TC02: one pixel rendered alone has its colour in the whole image
    Image alone(W, H);
    renderBlock({f.camera, f.tracer, *sampler}, {13, 7, 14, 8}, alone);
    EXPECT_TRUE(sameBits(whole.pixel(13, 7), alone.pixel(13, 7)));
    // TC03: another seed changes the noise: some pixel differs
    SamplingSettings other = settings;
    other.seed = 6;
    Image reseeded(W, H);
    renderBlock({f.camera, f.tracer, *makePixelSampler(other)}, {0, 0, W, H}, reseeded);
    int different = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        different += sameBits(whole.pixel(x, y), reseeded.pixel(x, y)) ? 0 : 1;
    EXPECT_GT(different, 0);
  }
}

}  // namespace
}  // namespace rt
