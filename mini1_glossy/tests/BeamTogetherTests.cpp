// Mini project 1: a beam's rays traced together (Intersectable::closestHits) give the image of
// tracing them one by one, bit for bit, and the same ray counts: where no shading draws a random
// number, where one does (the tracer then falls back to one by one), and at the limits of where
// the tracer tries it (the grid's size, a light with a size).
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <span>

#include "camera/Camera.h"
#include "geometries/Plane.h"
#include "glossy/BeamTracer.h"
#include "glossy/Galaxy.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;

/// Another structure's answers, with its batched queries counted: how often a tracer asked for
/// several rays' hits together, and for how many rays in all. Single-threaded use only.
class CountingBatches final : public Intersectable {
 public:
  explicit CountingBatches(const Intersectable& inner) : inner_(inner) {}

  std::optional<Hit> closestHit(const Ray& ray, double tMax,
                                QueryCounts* counts) const noexcept override {
    return inner_.closestHit(ray, tMax, counts);
  }
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts) const override {
    return inner_.forEachHit(ray, tMax, visit, counts);
  }
  void closestHits(std::span<const Ray> rays, double tMax, std::span<std::optional<Hit>> hits,
                   QueryCounts* counts) const noexcept override {
    ++batches;
    batchedRays += rays.size();
    Intersectable::closestHits(rays, tMax, hits, counts);
  }

  mutable std::uint64_t batches = 0, batchedRays = 0;

 private:
  const Intersectable& inner_;
};

/// BeamTracer whose shadows draw a random number wherever the shaded point has x > 0: a shading
/// that uses the stream between two of a beam's jitters, as a subclass of the course might.
class DrawingTracer final : public BeamTracer {
 public:
  using BeamTracer::BeamTracer;

 protected:
  Double3 transmittance(const HitContext& h, std::uint32_t light, const LightSample& sample,
                        const Double3& k, SampleContext& ctx) const override {
    if (h.point.x() > 0) ctx.random.next();
    return BeamTracer::transmittance(h, light, sample, k, ctx);
  }
};

/// A glossy mirror z = 0 (kR 1, beams of the given grid at distance 5, radius 0.1) under a
/// mirror z = 10 facing it; optionally a point light of radius 1 (4 shadow samples) above.
LitScene mirrors(int grid, bool sizedLight) {
  LitScene s;
  Material m;
  m.kR = Double3(1);
  m.kD = Double3(0.5);
  m.reflectedBeam = {5, 0.1, grid};
  const std::uint32_t glossy = s.addAppearance(Color(1, 2, 3), m);
  s.add(Plane(Point(0, 0, 0), Vector(0, 0, 1)), glossy);
  s.add(Plane(Point(0, 0, 10), Vector(0, 0, -1)), glossy);
  if (sizedLight)
    s.addLight(PointLight(Color(50, 50, 50), Point(1, 2, 5)).setRadius(1).setShadowSamples(4));
  return s;
}

/// What one ray straight down between the mirrors gives: its colour, its counts, and how the
/// tracer asked for hits (through a CountingBatches over the linear scan).
struct Traced {
  Color color;
  RayCounts counts;
  std::uint64_t batches, batchedRays;
};

Traced traceDown(const LitScene& s, bool together, BeamDepth depth = BeamDepth::FirstBounce) {
  const CountingBatches scan(s.geometries);
  const BeamTracer tracer(s, &scan, {.maxLevel = 3, .minK = 0},
                          {.beamDepth = depth, .together = together});
  RayCounts counts;
  SampleContext ctx(3, 4, 0, 9, counts);
  const Color c = tracer.traceRay(Ray(Point(0.3, 0.2, 5), Vector(0.1, 0, -1)), ctx);
  return {c, counts, scan.batches, scan.batchedRays};
}

/// The small galaxy (7 arms of 12, diffused glass) at 32 x 18 pixels through a CountingBatches,
/// with tracer type T and the together setting; the image, the counts and the batches.
template <class T>
struct GalaxyRender {
  Image image{32, 18};
  RayCounts counts;
  std::uint64_t batches = 0;

  GalaxyRender(const GalaxySetup& g, bool together) {
    const CountingBatches scan(g.scene.geometries);
    const T tracer(g.scene, &scan, {}, {.together = together});
    CameraSpec spec = g.views[0].camera;
    spec.nX = 32;
    spec.nY = 18;
    const Camera camera = spec.builder().build();
    counts = renderBlock({camera, tracer, CenterSampler(5)}, {0, 0, 32, 18}, image);
    batches = scan.batches;
  }
};

GalaxySetup smallGalaxy() {
  GalaxyParams p;
  p.arms = 7;
  p.perArm = 12;
  return galaxy(p);
}

template <class T>
void expectSameImages(const GalaxyRender<T>& a, const GalaxyRender<T>& b) {
  int differences = 0;
  for (int y = 0; y < 18; ++y)
    for (int x = 0; x < 32; ++x)
      if (!sameBits(a.image.pixel(x, y), b.image.pixel(x, y)) && ++differences <= 3)
        ADD_FAILURE() << "pixel (" << x << ", " << y << ")";
  EXPECT_EQ(differences, 0);
  EXPECT_EQ(a.counts, b.counts);
}

TEST(BeamTogetherTests, oneBeamTogetherIsTheBeamOneByOne) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: one ray between the mirrors, beams at the first bounce (grid 10: 80 rays): together,
  // the tracer asks for the beam's hits once, for its 80 rays; the colour is the same bits and
  // the counts the same as one by one, which never asks for several hits at once
  const LitScene s = mirrors(10, false);
  const Traced together = traceDown(s, true), oneByOne = traceDown(s, false);
  EXPECT_EQ(1u, together.batches);
  EXPECT_EQ(80u, together.batchedRays);
  EXPECT_EQ(0u, oneByOne.batches);
  EXPECT_TRUE(sameBits(oneByOne.color, together.color));
  EXPECT_EQ(oneByOne.counts, together.counts);
  EXPECT_EQ(160u, together.counts.secondary);  // 80 beam rays, each hit's one reflected ray
  // TC02: the default is together
  EXPECT_TRUE(BeamTracerSettings{}.together);
}

TEST(BeamTogetherTests, theGalaxyTogetherIsTheGalaxyOneByOne) {
  // TC01: the small galaxy, whose glass casts a beam at every pixel that sees it: the same image
  // and counts, and the beams were traced together
  const GalaxySetup g = smallGalaxy();
  const GalaxyRender<BeamTracer> together(g, true), oneByOne(g, false);
  expectSameImages(together, oneByOne);
  EXPECT_GT(together.counts.secondary, 0u);
  EXPECT_GT(together.batches, 0u);
  EXPECT_EQ(0u, oneByOne.batches);
}

TEST(BeamTogetherTests, aShadingThatDrawsFallsBackToOneByOne) {
  // TC01: shadows that draw a number at x > 0: some beams' shadings draw between two jitters.
  // Together, the tracer sees the stream move, puts the stream and the counts back as they were
  // and traces that beam one by one: the same image and counts as one by one throughout
  const GalaxySetup g = smallGalaxy();
  const GalaxyRender<DrawingTracer> together(g, true), oneByOne(g, false);
  expectSameImages(together, oneByOne);
  EXPECT_GT(together.batches, 0u);
  // and the draws do change the image (so the fallback had something to keep right)
  const GalaxyRender<BeamTracer> plain(g, false);
  bool changed = false;
  for (int y = 0; y < 18 && !changed; ++y)
    for (int x = 0; x < 32 && !changed; ++x)
      changed = !sameBits(plain.image.pixel(x, y), oneByOne.image.pixel(x, y));
  EXPECT_TRUE(changed);
}

TEST(BeamTogetherTests, whereTheTracerTriesIt) {
  // =============== Boundary Values Tests ==================
  // TC11: the largest grid traced together, TOGETHER_GRID (12): one batch of its cells
  const Traced largest = traceDown(mirrors(BeamTracer::TOGETHER_GRID, false), true);
  EXPECT_EQ(1u, largest.batches);
  EXPECT_EQ(static_cast<std::uint64_t>(beamCellCount(BeamTracer::TOGETHER_GRID)),
            largest.batchedRays);
  EXPECT_TRUE(
      sameBits(traceDown(mirrors(BeamTracer::TOGETHER_GRID, false), false).color, largest.color));
  // TC12: one more (13): one by one, the same bits as with together off
  const LitScene larger = mirrors(BeamTracer::TOGETHER_GRID + 1, false);
  const Traced tooLarge = traceDown(larger, true);
  EXPECT_EQ(0u, tooLarge.batches);
  EXPECT_TRUE(sameBits(traceDown(larger, false).color, tooLarge.color));
  // TC13: a light with a size (soft shadows draw numbers at every hit): never tried
  const LitScene sized = mirrors(10, true);
  const Traced soft = traceDown(sized, true), softOneByOne = traceDown(sized, false);
  EXPECT_EQ(0u, soft.batches);
  EXPECT_TRUE(sameBits(softOneByOne.color, soft.color));
  EXPECT_EQ(softOneByOne.counts, soft.counts);
  EXPECT_GT(soft.counts.shadow, 160u);  // the light is seen: soft shadows were cast
  // TC14: beams at every bounce (deeper beams draw their jitters inside a shading): never tried
  const LitScene s = mirrors(10, false);
  const Traced every = traceDown(s, true, BeamDepth::EveryBounce);
  const Traced everyOneByOne = traceDown(s, false, BeamDepth::EveryBounce);
  EXPECT_EQ(0u, every.batches);
  EXPECT_TRUE(sameBits(everyOneByOne.color, every.color));
  EXPECT_EQ(6480u, every.counts.secondary);  // 80 + 80·80
}

}  // namespace
}  // namespace rt
