// Mini project 1: the demonstration scenes. The table holds together (checkDemoTable), the scenes'
// parameters change what they name, and each scene shows its technique: its
// rays are counted exactly where a count is exact (a beam of N = 8 is 52 rays, 32 shadow rays per
// shaded point), and the pixels that depend on random numbers are exactly those of the technique.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "camera/Camera.h"
#include "glossy/BeamTracer.h"
#include "glossy/DemoScenes.h"
#include "glossy/DemoTable.h"
#include "glossy/RayBeam.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;

using test::sameBits;

const DemoScene& demoEntry(std::string_view name) {
  for (const DemoScene& e : demoScenes())
    if (name == e.course.name) return e;
  throw std::logic_error("no demonstration scene " + std::string(name));
}

DemoSetup built(std::string_view name) { return demoEntry(name).build(); }

/// A scene made with other parameters, sampled with the settings given.
DemoSetup setupOf(SceneSetup<LitScene> s, const SamplingSettings& sampling) {
  return {std::move(s.scene), s.camera, sampling};
}

/// The setup's camera at nX x nY pixels.
Camera cameraOf(const DemoSetup& d, int nX, int nY) {
  CameraSpec spec = d.camera;
  spec.nX = nX;
  spec.nY = nY;
  return spec.builder().build();
}

struct Rendered {
  Image image;
  RayCounts counts;
};

/// Renders the setup at nX x nY with the beams tracer and its own sampler, the seed replaced.
Rendered render(const DemoSetup& d, int nX, int nY, std::uint64_t seed = 0) {
  const Camera camera = cameraOf(d, nX, nY);
  const BeamTracer tracer(d.scene);
  SamplingSettings sampling = d.sampling;
  sampling.seed = seed;
  Rendered r{Image(nX, nY), {}};
  r.counts = renderBlock({camera, tracer, *makePixelSampler(sampling)}, {0, 0, nX, nY}, r.image);
  return r;
}

/// The shape the ray through pixel (x, y)'s centre meets first, or -1.
long shapeAt(const DemoSetup& d, const Camera& camera, int x, int y) {
  const auto hit = d.scene.geometries.closestHit(camera.ray(x + 0.5, y + 0.5));
  return hit ? static_cast<long>(hit->geometry) : -1;
}

/// The indices of the scene's spheres, in the order they were added.
std::vector<std::uint32_t> sphereIndices(const LitScene& s) {
  std::vector<std::uint32_t> out;
  const auto shapes = s.geometries.shapes();
  for (std::uint32_t i = 0; i < shapes.size(); ++i)
    if (std::holds_alternative<Sphere>(shapes[i])) out.push_back(i);
  return out;
}

/// Per shape index: whether its pixels (by their centre rays) differ between seeds 0 and 1, and
/// how many pixels it has. Shape -1 is the background.
struct SeedSplit {
  std::set<long> varying, steady;
};

SeedSplit splitBySeed(const DemoSetup& d, int nX, int nY) {
  const Rendered a = render(d, nX, nY, 0), b = render(d, nX, nY, 1);
  const Camera camera = cameraOf(d, nX, nY);
  SeedSplit split;
  for (int y = 0; y < nY; ++y)
    for (int x = 0; x < nX; ++x) {
      const long shape = shapeAt(d, camera, x, y);
      (sameBits(a.image.pixel(x, y), b.image.pixel(x, y)) ? split.steady : split.varying)
          .insert(shape);
    }
  return split;
}

/// The secondary rays the beams tracer casts for one ray from the camera to point p.
std::uint64_t secondaryRaysTowards(const DemoSetup& d, const Point& p) {
  const BeamTracer tracer(d.scene);
  RayCounts counts;
  SampleContext ctx(0, 0, 0, 7, counts);
  (void)tracer.traceRay(Ray(d.camera.location, (p - d.camera.location).normalized()), ctx);
  return counts.secondary;
}

// ---- the table ------------------------------------------------------------------------------

TEST(DemoScenesTests, theTable) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: one scene per technique, then all of them together, in this order
  std::vector<std::string> names;
  for (const DemoScene& e : demoScenes()) names.emplace_back(e.course.name);
  EXPECT_EQ(
      (std::vector<std::string>{"glossy-spheres", "frosted-glass", "soft-shadows", "antialiasing",
                                "depth-of-field", "adaptive", "super-sampling"}),
      names);
  // TC02: the table holds together (checkDemoTable, tested below) and the beams tracer accepts
  // every scene
  EXPECT_NO_THROW(checkDemoTable(demoScenes()));
  for (const DemoScene& e : demoScenes())
    EXPECT_NO_THROW(BeamTracer{e.build().scene}) << e.course.name;
  // TC03: the samplers the settings make: 4 x 4 jittered samples; 24 lens samples; the adaptive
  // lattice of depth 3, (2^3 + 1)^2 = 81 points at most
  EXPECT_EQ(16, makePixelSampler(built("antialiasing").sampling)->samplesPerPixel());
  EXPECT_EQ(24, makePixelSampler(built("depth-of-field").sampling)->samplesPerPixel());
  EXPECT_EQ(81, makePixelSampler(built("adaptive").sampling)->samplesPerPixel());
}

TEST(DemoScenesTests, parameters) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the defaults are the table's scenes: N = 8 beams, 32 shadow rays, a lens of radius
  // 0.2, and every technique of super-sampling off
  EXPECT_EQ(8, demo::GlossySpheresParams{}.beamGrid);
  EXPECT_EQ(8, demo::FrostedGlassParams{}.beamGrid);
  EXPECT_EQ(32, demo::SoftShadowsParams{}.shadowSamples);
  EXPECT_EQ(0.2, demo::DepthOfFieldParams{}.aperture);
  const demo::SuperSamplingParams off;
  EXPECT_EQ(1, off.glossyGrid);
  EXPECT_EQ(1, off.frostedGrid);
  EXPECT_EQ(1, off.shadowSamples);
  EXPECT_EQ(0, off.aperture);
  // TC02: each of super-sampling's parameters sets what it names: the glossy sphere's beam, the
  // pane's beam, the light's shadow rays, the lens
  const SceneSetup<LitScene> on = demo::superSampling(
      {.glossyGrid = 6, .frostedGrid = 7, .shadowSamples = 9, .aperture = 0.25});
  EXPECT_EQ(9, std::get<PointLight>(on.scene.lights[0]).shadowSamples);
  EXPECT_EQ(0.25, on.camera.aperture);
  int glossy = 0, frosted = 0;
  for (const Appearance& a : on.scene.appearances) {
    glossy += a.material.reflectedBeam == BeamSettings{1, 0.08, 6} ? 1 : 0;
    frosted += a.material.refractedBeam == BeamSettings{1, 0.08, 7} ? 1 : 0;
  }
  EXPECT_EQ(1, glossy);
  EXPECT_EQ(1, frosted);
  // TC03: the other scenes' parameters likewise: the three glossy spheres (radii 0.03, 0.08,
  // 0.2) and the two frosted panes (0.05, 0.15) take the grid, and no other beam is there
  int glossyBeams = 0, gridded = 0;
  for (const Appearance& a : demo::glossySpheres({.beamGrid = 3}).scene.appearances) {
    glossyBeams += a.material.reflectedBeam.radius > 0 ? 1 : 0;
    gridded += a.material.reflectedBeam.radius > 0 && a.material.reflectedBeam.grid == 3 ? 1 : 0;
  }
  EXPECT_EQ(3, glossyBeams);
  EXPECT_EQ(3, gridded);
  int frostedBeams = 0;
  gridded = 0;
  for (const Appearance& a : demo::frostedGlass({.beamGrid = 5}).scene.appearances) {
    frostedBeams += a.material.refractedBeam.radius > 0 ? 1 : 0;
    gridded += a.material.refractedBeam.radius > 0 && a.material.refractedBeam.grid == 5 ? 1 : 0;
  }
  EXPECT_EQ(2, frostedBeams);
  EXPECT_EQ(2, gridded);
  EXPECT_EQ(
      4,
      std::get<PointLight>(demo::softShadows({.shadowSamples = 4}).scene.lights[0]).shadowSamples);
  EXPECT_EQ(0.05, demo::depthOfField({.aperture = 0.05}).camera.aperture);

  // =============== Boundary Values Tests ==================
  // TC11: a beam grid or a shadow-ray count the engine refuses is refused when the scene is made
  EXPECT_NO_THROW(demo::glossySpheres({.beamGrid = BeamSettings::MAX_GRID}));
  EXPECT_THROW(demo::glossySpheres({.beamGrid = BeamSettings::MAX_GRID + 1}),
               std::invalid_argument);
  EXPECT_THROW(demo::softShadows({.shadowSamples = 0}), std::invalid_argument);
}

TEST(DemoScenesTests, checkDemoTable) {
  // The check of a table, and what it throws.
  const auto check = [](std::vector<DemoScene> table) {
    return [table] { checkDemoTable(table); };
  };
  const auto refused = [](const char* message) {
    return ThrowsMessage<std::logic_error>(StrEq(message));
  };
  const CourseScene course = demoEntry("soft-shadows").course;
  // ============ Equivalence Partitions Tests ==============
  // TC01: a valid entry
  EXPECT_NO_THROW(check({{course, {}}})());
  // TC02: what checkSceneTable finds (here a name that is not kebab-case) is its message
  CourseScene badName = course;
  badName.name = "Soft_Shadows";
  EXPECT_THAT(check({{badName, {}}}),
              refused("checkSceneTable: entry 0 ('Soft_Shadows'): the name is not kebab-case "
                      "(a-z, 0-9, '-')"));
  // TC03: sampling settings no sampler accepts
  EXPECT_THAT(check({{{"a", "a valid entry for the check", course.make}, {}},
                     {{"b", "a valid entry for the check", course.make}, {.samples = 0}}}),
              refused("checkDemoTable: entry 1 ('b'): its sampling settings are refused: "
                      "JitteredSampler: grid must be between 1 and 64, got 0"));
}

// ---- what each scene shows ------------------------------------------------------------------

TEST(DemoScenesTests, glossySpheres) {
  const DemoSetup d = built("glossy-spheres");
  const std::vector<std::uint32_t> spheres = sphereIndices(d.scene);
  ASSERT_EQ(4u, spheres.size());
  // ============ Equivalence Partitions Tests ==============
  // TC01: reflected beams of radius 0, 0.03, 0.08, 0.2 at distance 1, N = 8
  const std::vector<double> radii{0, 0.03, 0.08, 0.2};
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ((BeamSettings{1, radii[i], 8}),
              d.scene.appearanceOf(spheres[i]).material.reflectedBeam);
  // TC02: a ray at a sphere's centre: the mirror casts its one reflected ray, the glossy ones a
  // full beam, 52 rays for N = 8 (the rays go back towards the camera: none on the wrong side)
  EXPECT_EQ(52, beamCellCount(8));
  const std::vector<std::uint64_t> expected{1, 52, 52, 52};
  for (std::size_t i = 0; i < 4; ++i) {
    const Point centre = std::get<Sphere>(d.scene.geometries.shapes()[spheres[i]]).center();
    EXPECT_EQ(expected[i], secondaryRaysTowards(d, centre)) << "sphere " << i;
  }
  // TC03: another seed changes pixels of each glossy sphere, and nothing else: not the mirror,
  // not the floor, not the sky
  const SeedSplit split = splitBySeed(d, 64, 32);
  for (std::size_t i = 1; i < 4; ++i) EXPECT_TRUE(split.varying.count(spheres[i])) << i;
  std::set<long> glossy(spheres.begin() + 1, spheres.end());
  for (const long shape : split.varying) EXPECT_TRUE(glossy.count(shape)) << shape;
  EXPECT_TRUE(split.steady.count(spheres[0]));
}

TEST(DemoScenesTests, frostedGlass) {
  const DemoSetup d = built("frosted-glass");
  // The panes: the polygons with a transparency.
  std::vector<std::uint32_t> panes;
  for (std::uint32_t i = 0; i < d.scene.geometries.size(); ++i)
    if (d.scene.appearanceOf(i).material.kT.x > 0) panes.push_back(i);
  ASSERT_EQ(3u, panes.size());
  // ============ Equivalence Partitions Tests ==============
  // TC01: clear glass, then refracted beams of radius 0.05 and 0.15 at distance 1, N = 8
  const std::vector<double> radii{0, 0.05, 0.15};
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ((BeamSettings{1, radii[i], 8}),
              d.scene.appearanceOf(panes[i]).material.refractedBeam);
  // TC02: a ray at a pane's centre (x = -2.4, 0, 2.4; y = 1.45): the clear pane casts one
  // refracted and one reflected ray (kR 0.05); a frosted one 52 refracted rays and the reflected
  // one
  const std::vector<std::uint64_t> expected{2, 53, 53};
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(expected[i],
              secondaryRaysTowards(d, Point(-2.4 + 2.4 * static_cast<double>(i), 1.45, 0)))
        << i;
  // TC03: another seed changes pixels of the frosted panes only
  const SeedSplit split = splitBySeed(d, 64, 32);
  EXPECT_TRUE(split.varying.count(panes[1]));
  EXPECT_TRUE(split.varying.count(panes[2]));
  for (const long shape : split.varying)
    EXPECT_TRUE(shape == panes[1] || shape == panes[2]) << shape;
  EXPECT_TRUE(split.steady.count(panes[0]));
}

TEST(DemoScenesTests, softShadows) {
  DemoSetup d = built("soft-shadows");
  // ============ Equivalence Partitions Tests ==============
  // TC01: one light, of radius 1.2, 32 shadow rays per shaded point
  ASSERT_EQ(1u, d.scene.lights.size());
  EXPECT_EQ(1.2, std::get<PointLight>(d.scene.lights[0]).radius);
  EXPECT_EQ(32, std::get<PointLight>(d.scene.lights[0]).shadowSamples);
  // TC02: 32 shadow rays where one point light casts one: exactly 32 times as many (no shape
  // reflects or refracts, so every shaded point is a camera ray's)
  const Rendered soft = render(d, 60, 40);
  d = setupOf(demo::softShadows({.shadowSamples = 1}), d.sampling);
  const Rendered hard = render(d, 60, 40);
  EXPECT_GT(hard.counts.shadow, 0u);
  EXPECT_EQ(32 * hard.counts.shadow, soft.counts.shadow);
  EXPECT_EQ(0u, soft.counts.secondary);
  // TC03: with one shadow ray the image depends on no random number: another seed, same bits
  EXPECT_TRUE(splitBySeed(d, 60, 40).varying.empty());
  // TC04: with 32, the floor has pixels that do (the penumbrae), and the shapes' lit sides do not
  // (a sphere's pixel sees the whole disk or, turned away, none of it)
  d = setupOf(demo::softShadows({.shadowSamples = 32}), d.sampling);
  const SeedSplit split = splitBySeed(d, 60, 40);
  EXPECT_TRUE(split.varying.count(0));  // the floor
  EXPECT_TRUE(split.steady.count(0));   // fully lit floor
}

TEST(DemoScenesTests, antialiasing) {
  DemoSetup d = built("antialiasing");
  // No lights, no ambient light: a ray's colour is the emission of what it meets, or the sky.
  const std::set<std::vector<double>> flat{
      {235, 235, 235}, {15, 15, 15}, {30, 50, 90}, {220, 40, 30}, {250, 200, 40}};
  const auto colours = [](const Image& image) {
    std::set<std::vector<double>> out;
    for (int y = 0; y < image.nY(); ++y)
      for (int x = 0; x < image.nX(); ++x) {
        const Color& c = image.pixel(x, y);
        out.insert({c.r(), c.g(), c.b()});
      }
    return out;
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: one ray per pixel (samples=1): every pixel is one of the five flat colours, and all
  // five occur
  d.sampling.samples = 1;
  const Rendered one = render(d, 40, 30);
  EXPECT_EQ(flat, colours(one.image));
  EXPECT_EQ(40u * 30u, one.counts.primary);
  // TC02: the scene's 4 x 4 samples: 16 rays per pixel, and pixels on edges mix the colours
  d.sampling.samples = 4;
  const Rendered sixteen = render(d, 40, 30);
  EXPECT_EQ(16u * 40u * 30u, sixteen.counts.primary);
  EXPECT_GT(colours(sixteen.image).size(), 30u);
}

TEST(DemoScenesTests, depthOfField) {
  DemoSetup d = built("depth-of-field");
  const std::vector<std::uint32_t> spheres = sphereIndices(d.scene);
  ASSERT_EQ(7u, spheres.size());
  const auto centre = [&](std::size_t i) {
    return std::get<Sphere>(d.scene.geometries.shapes()[spheres[i]]).center();
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: the focal plane holds the fourth sphere's centre: (centre − location)·vTo is the
  // focal distance
  const Camera camera = cameraOf(d, 48, 27);
  EXPECT_NEAR(camera.focalDistance(), (centre(3) - camera.location()).dot(camera.vTo()), 1e-12);
  EXPECT_EQ(0.2, camera.aperture());
  // TC02: 24 lens samples per pixel
  const Rendered lens = render(d, 48, 27);
  EXPECT_EQ(24u * 48u * 27u, lens.counts.primary);
  // TC03: aperture 0 is the pinhole: one ray per pixel through its centre, the same bits as the
  // centre sampler's image
  const DemoSetup pinholeSetup = setupOf(demo::depthOfField({.aperture = 0}), d.sampling);
  const Rendered pinhole = render(pinholeSetup, 48, 27);
  EXPECT_EQ(48u * 27u, pinhole.counts.primary);
  Image centred(48, 27);
  (void)renderBlock({cameraOf(pinholeSetup, 48, 27), BeamTracer(d.scene), CenterSampler()},
                    {0, 0, 48, 27}, centred);
  for (int y = 0; y < 27; ++y)
    for (int x = 0; x < 48; ++x)
      ASSERT_TRUE(sameBits(centred.pixel(x, y), pinhole.image.pixel(x, y)));
  // TC04: through the lens, the pixels of the focused sphere stay closer to the pinhole's than
  // those of the nearest one: the mean difference over each sphere's pixels
  std::vector<double> sum(7, 0);
  std::vector<int> count(7, 0);
  for (int y = 0; y < 27; ++y)
    for (int x = 0; x < 48; ++x) {
      const long shape = shapeAt(d, camera, x, y);
      for (std::size_t i = 0; i < 7; ++i)
        if (shape == spheres[i]) {
          const Double3 diff = lens.image.pixel(x, y).rgb() - pinhole.image.pixel(x, y).rgb();
          sum[i] += std::abs(diff.x) + std::abs(diff.y) + std::abs(diff.z);
          ++count[i];
        }
    }
  ASSERT_GT(count[0], 0);
  ASSERT_GT(count[3], 0);
  EXPECT_LT(sum[3] / count[3], 0.25 * sum[0] / count[0]);
}

TEST(DemoScenesTests, adaptive) {
  const DemoSetup d = built("adaptive");
  const Camera camera = cameraOf(d, 30, 30);
  const BeamTracer tracer(d.scene);
  const auto sampler = makePixelSampler(d.sampling);
  const auto pixel = [&](int x, int y, RayCounts& counts) {
    return sampler->pixelColor(camera, tracer, x, y, counts);
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: a pixel inside the red disc (its centre (1.6, 0.4) is at pixel (22, 13) of 30 x 30 with
  // a 6.6-wide view plane, perspective aside): its four corners agree, four rays, exactly the
  // disc's emission
  RayCounts inside;
  EXPECT_EQ(Color(210, 50, 40), pixel(22, 13, inside));
  EXPECT_EQ(4u, inside.primary);
  // TC02: over the whole image, a pixel casts its 4 corner rays alone exactly when it has one of
  // the flat colours (the shapes' emissions and the sky differ by far more than the threshold
  // 16): every other pixel is an edge, subdivided, with at most the 81 rays of the lattice
  const std::set<std::vector<double>> flat{
      {25, 35, 70}, {240, 190, 40}, {210, 50, 40}, {40, 160, 90}, {235, 235, 240}};
  int edges = 0, flats = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 30; ++x) {
      RayCounts counts;
      const Color c = pixel(x, y, counts);
      const bool isFlat = flat.count({c.r(), c.g(), c.b()}) == 1;
      EXPECT_EQ(isFlat, counts.primary == 4) << x << "," << y;
      EXPECT_LE(counts.primary, 81u);
      (isFlat ? flats : edges) += 1;
    }
  EXPECT_GT(edges, 30);
  EXPECT_GT(flats, 500);
}

TEST(DemoScenesTests, superSampling) {
  const DemoSetup off = built("super-sampling");
  // ============ Equivalence Partitions Tests ==============
  // TC01: every technique off: the Whitted tracer's image, bit for bit, with the same rays
  const Rendered beams = render(off, 40, 30);
  Image whitted(40, 30);
  const RayCounts counts = renderBlock(
      {cameraOf(off, 40, 30), WhittedTracer(off.scene), CenterSampler()}, {0, 0, 40, 30}, whitted);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x)
      ASSERT_TRUE(sameBits(whitted.pixel(x, y), beams.image.pixel(x, y)));
  EXPECT_EQ(counts, beams.counts);
  // TC02: each technique costs the rays it names: N = 2 samples, 4 times the camera rays; 3 lens
  // samples, 3 times; a glossy or frosted beam, more secondary rays; 8 shadow rays, more shadow
  // rays but at most 8 times; adaptive, at least the 4 corners of every pixel
  const auto with = [&](const demo::SuperSamplingParams& params,
                        void (*sampling)(SamplingSettings&)) {
    DemoSetup d = setupOf(demo::superSampling(params), off.sampling);
    sampling(d.sampling);
    return render(d, 40, 30).counts;
  };
  const auto as = [](SamplingSettings&) {};
  const RayCounts& base = beams.counts;
  EXPECT_EQ(4 * base.primary, with({}, [](SamplingSettings& s) { s.samples = 2; }).primary);
  EXPECT_EQ(3 * base.primary,
            with({.aperture = 0.1}, [](SamplingSettings& s) { s.lensSamples = 3; }).primary);
  EXPECT_GT(with({.glossyGrid = 8}, as).secondary, base.secondary);
  EXPECT_GT(with({.frostedGrid = 8}, as).secondary, base.secondary);
  const RayCounts soft = with({.shadowSamples = 8}, as);
  EXPECT_GT(soft.shadow, base.shadow);
  EXPECT_LE(soft.shadow, 8 * base.shadow);
  EXPECT_GE(with({}, [](SamplingSettings& s) { s.adaptive = true; }).primary, 4 * base.primary);
}

}  // namespace
}  // namespace rt
