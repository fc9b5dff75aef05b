// mini2: the tile pool. The image and the ray counts are the same bits for any number of threads
// and any tile size (sampled scenes included, through the BVH; the same image through the grid,
// the CBR and the linear scan; a triangle mesh among them); a stop is seen within a tile row;
// a tracer's exception arrives on the calling thread after every thread has been joined;
// progress is reported once per tile; bad options are refused. No test measures time.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>

#include "bvh/Bvh.h"
#include "bvh/Cbr.h"
#include "bvh/WideBvh.h"
#include "camera/Camera.h"
#include "geometries/UtahTeapot.h"
#include "glossy/BeamTracer.h"
#include "glossy/Galaxy.h"
#include "glossy/Samplers.h"
#include "grid/Grid.h"
#include "parallel/TilePool.h"
#include "reflections/CourseScenes.h"
#include "support/AllocationCounter.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// The first pixel whose bits differ, as "x,y", or "" when the images are the same bits.
std::string firstDifference(const Image& a, const Image& b) {
  for (int y = 0; y < a.nY(); ++y)
    for (int x = 0; x < a.nX(); ++x)
      if (!sameBits(a.pixel(x, y), b.pixel(x, y)))
        return std::to_string(x) + "," + std::to_string(y);
  return "";
}

/// A scene seen through the BVH, through the grid, through the CBR and through the linear
/// Geometries, with a sampler.
struct SampledScene {
  std::string name;
  std::unique_ptr<LitScene> scene;
  std::unique_ptr<Bvh> bvh;
  std::unique_ptr<Grid> grid;
  std::unique_ptr<Cbr> cbr;
  std::unique_ptr<WideBvh> wide;
  std::unique_ptr<RayTracer> linear, accelerated, gridded, boxed, widened;
  std::unique_ptr<PixelSampler> sampler;
  Camera camera;
};

template <typename Tracer>
SampledScene sampledScene(std::string name, LitScene scene, const CameraSpec& camera,
                          std::unique_ptr<PixelSampler> sampler) {
  SampledScene s{std::move(name),
                 std::make_unique<LitScene>(std::move(scene)),
                 nullptr,
                 nullptr,
                 nullptr,
                 nullptr,
                 nullptr,
                 nullptr,
                 nullptr,
                 nullptr,
                 nullptr,
                 std::move(sampler),
                 camera.builder().build()};
  s.bvh = std::make_unique<Bvh>(s.scene->geometries);
  s.linear = std::make_unique<Tracer>(*s.scene);
  s.accelerated = std::make_unique<Tracer>(*s.scene, s.bvh.get());
  s.grid = std::make_unique<Grid>(s.scene->geometries);
  s.gridded = std::make_unique<Tracer>(*s.scene, s.grid.get());
  s.cbr = std::make_unique<Cbr>(s.scene->geometries);
  s.boxed = std::make_unique<Tracer>(*s.scene, s.cbr.get());
  s.wide = std::make_unique<WideBvh>(s.scene->geometries);
  s.widened = std::make_unique<Tracer>(*s.scene, s.wide.get());
  return s;
}

/// The galaxy of 7 arms of 12 stars, its glass's beams of grid x grid cells (distance 12,
/// radius 0.3).
GalaxySetup smallGalaxy(int grid) {
  GalaxySetup g = galaxy(GalaxyParams{.arms = 7, .perArm = 12});
  for (Appearance& a : g.scene.appearances)
    if (a.material.refractedBeam.isBeam())
      a.material.reflectedBeam = a.material.refractedBeam =
          BeamSettings{.distance = 12, .radius = 0.3, .grid = grid};
  return g;
}

/// A small galaxy (7 arms of 12 stars) with the glass's beams (2 x 2 rays) and soft spot lights
/// (radius 2, 2 shadow rays), seen from "inside" through a lens, 16 x 9 pixels (every pixel
/// looks through the glass: about 130 rays per camera ray).
SampledScene galaxyScene(std::unique_ptr<PixelSampler> sampler, std::string name) {
  GalaxySetup g = smallGalaxy(2);
  for (LightSource& light : g.scene.lights)
    std::get<SpotLight>(light).setRadius(2).setShadowSamples(2);
  CameraSpec view = g.views[2].camera;
  view.nX = 16;
  view.nY = 9;
  view.aperture = 0.25;
  view.focalDistance = 30;
  return sampledScene<BeamTracer>(std::move(name), std::move(g.scene), view, std::move(sampler));
}

/// The same small galaxy with its own point-like spot lights and the glass's beams of 4 x 4 cells
/// (12 rays): the beam tracer traces each beam's rays together (BeamTracerSettings::together),
/// through the wide BVH as packets of 8 and 4 rays; 16 x 9 pixels, one centred ray each.
SampledScene galaxyTogetherScene() {
  GalaxySetup g = smallGalaxy(4);
  CameraSpec view = g.views[2].camera;
  view.nX = 16;
  view.nY = 9;
  SampledScene s =
      sampledScene<BeamTracer>("galaxy, beams traced together, point spots", std::move(g.scene),
                               view, std::make_unique<CenterSampler>());
  EXPECT_TRUE(static_cast<const BeamTracer&>(*s.widened).beamSettings().together);
  return s;
}

/// The report authors' all-features scene from above, its point light and spot light given a
/// size (soft shadows), 30 x 30 pixels, 2 x 2 jittered samples.
SampledScene softShadowScene() {
  SceneSetup<LitScene> setup = course::allFeaturesAbove();
  int sized = 0;
  for (LightSource& light : setup.scene.lights)
    if (auto* point = std::get_if<PointLight>(&light)) {
      point->setRadius(6).setShadowSamples(4);
      ++sized;
    } else if (auto* spot = std::get_if<SpotLight>(&light)) {
      spot->setRadius(10).setShadowSamples(5);
      ++sized;
    }
  EXPECT_EQ(sized, 2);  // the scene's point and spot lights
  setup.camera.nX = setup.camera.nY = 30;
  return sampledScene<BeamTracer>("all features, soft shadows, jittered 2x2",
                                  std::move(setup.scene), setup.camera,
                                  std::make_unique<JitteredSampler>(2, 1, 11));
}

/// The hall of mirrors with the Whitted tracer, one ray per pixel: the course's render.
SampledScene mirrorScene() {
  SceneSetup<LitScene> setup = course::hallOfMirrors();
  setup.camera.nX = 40;
  setup.camera.nY = 30;
  return sampledScene<WhittedTracer>("hall of mirrors, Whitted, centre", std::move(setup.scene),
                                     setup.camera, std::make_unique<CenterSampler>());
}

/// The course's teapot as a triangle mesh (992 triangles, smooth normals) on a reflecting floor
/// in the plane of its bottom, a mirror sphere and a glass sphere beside it, a point light and a
/// spot light with a size (soft shadows through the mesh), 24 x 24 pixels, 2 x 2 jittered samples.
SampledScene teapotScene() {
  LitScene scene;
  scene.ambientLight = AmbientLight(Color(40, 40, 40), 0.2);
  Material pot;
  pot.kD = Double3(0.5);
  pot.kS = Double3(0.5);
  pot.shininess = 60;
  scene.addMesh(std::make_shared<const TriangleMesh>(utahTeapot(4)),
                scene.addAppearance(Color(60, 10, 0), pot));
  Material floor;
  floor.kD = Double3(0.6);
  floor.kR = Double3(0.2);
  scene.add(Plane(Point(0, 0, 0), Vector(0, 0, 1)), Color(10, 10, 10), floor);
  Material mirror;
  mirror.kR = Double3(0.8);
  scene.add(Sphere(Point(4, 3, 1), 1), Color::BLACK, mirror);
  Material glass;
  glass.kS = Double3(0.3);
  glass.shininess = 40;
  glass.kT = Double3(0.7);
  glass.ior = 1.5;
  scene.add(Sphere(Point(-4, 3, 1.2), 1.2), Color(0, 0, 20), glass);
  scene.addLight(PointLight(Color(400, 400, 400), Point(3, 6, 8))
                     .setKl(0.01)
                     .setKq(0.001)
                     .setRadius(1)
                     .setShadowSamples(3));
  scene.addLight(SpotLight(Color(300, 200, 100), Point(-5, -6, 6), Vector(1, 1, -1))
                     .setKl(0.01)
                     .setRadius(0.5)
                     .setShadowSamples(2));
  return sampledScene<BeamTracer>(
      "teapot mesh, soft shadows, mirror and glass, jittered 2x2", std::move(scene),
      CameraSpec::squareView(Point(0, 14, 5), Point(0, 0, 1.5), 10, 14, 24),
      std::make_unique<JitteredSampler>(2, 1, 13));
}

struct PoolShape {
  int threads, tileSize;
};

TEST(TilePoolTests, sameBitsForAnyThreadsAndTiles) {
  std::vector<SampledScene> scenes;
  scenes.push_back(galaxyScene(std::make_unique<JitteredSampler>(2, 2, 5),
                               "galaxy, beams, soft spots, jittered 2x2 x 2 lens samples"));
  scenes.push_back(galaxyScene(std::make_unique<AdaptiveSampler>(8, 2, 5),
                               "galaxy, beams, soft spots, adaptive, lens"));
  scenes.push_back(galaxyTogetherScene());
  scenes.push_back(softShadowScene());
  scenes.push_back(mirrorScene());
  scenes.push_back(teapotScene());
  for (const SampledScene& s : scenes) {
    SCOPED_TRACE(s.name);
    const int nX = s.camera.nX(), nY = s.camera.nY();
    const PixelBlock all{0, 0, nX, nY};
    // The references, serial (stage 4's renderBlock over the whole image): the linear scan's
    // image, and the BVH's counts; the BVH's image is the linear scan's (part 1).
    Image linear(nX, nY), serial(nX, nY);
    renderBlock({s.camera, *s.linear, *s.sampler}, all, linear);
    const RayCounts counts = renderBlock({s.camera, *s.accelerated, *s.sampler}, all, serial);
    ASSERT_EQ(firstDifference(linear, serial), "");
    EXPECT_GT(counts.total(), counts.primary);  // secondary or shadow rays were cast
    // ============ Equivalence Partitions Tests ==============
    // TC01: 1 to 4 threads, tiles of 5 to 32 pixels (the default): the same bits, the same
    // counts, every pixel rendered
    // =============== Boundary Values Tests ==================
    // TC11: tiles of one pixel; one tile larger than the image
    for (const PoolShape& p : {PoolShape{1, 32}, PoolShape{2, 32}, PoolShape{2, 7}, PoolShape{3, 5},
                               PoolShape{4, 1}, PoolShape{2, 1000}}) {
      SCOPED_TRACE(std::to_string(p.threads) + " threads, tiles of " + std::to_string(p.tileSize));
      Image image(nX, nY);
      const RenderResult r = renderImage({s.camera, *s.accelerated, *s.sampler}, image,
                                         {.threads = p.threads, .tileSize = p.tileSize});
      EXPECT_EQ(firstDifference(serial, image), "");
      EXPECT_EQ(r.counts, counts);
      EXPECT_EQ(r.pixels, all.pixels());
      EXPECT_FALSE(r.interrupted);
    }
    // TC02: through the grid, serial and on 3 threads (tiles of 7): the linear scan's image
    Image serialGrid(nX, nY), pooledGrid(nX, nY);
    renderBlock({s.camera, *s.gridded, *s.sampler}, all, serialGrid);
    EXPECT_EQ(firstDifference(linear, serialGrid), "");
    const RenderResult r =
        renderImage({s.camera, *s.gridded, *s.sampler}, pooledGrid, {.threads = 3, .tileSize = 7});
    EXPECT_EQ(firstDifference(linear, pooledGrid), "");
    EXPECT_EQ(r.pixels, all.pixels());
    // TC03: through the CBR, serial and on 2 threads: the linear scan's image
    Image serialCbr(nX, nY), pooledCbr(nX, nY);
    renderBlock({s.camera, *s.boxed, *s.sampler}, all, serialCbr);
    EXPECT_EQ(firstDifference(linear, serialCbr), "");
    renderImage({s.camera, *s.boxed, *s.sampler}, pooledCbr, {.threads = 2, .tileSize = 5});
    EXPECT_EQ(firstDifference(linear, pooledCbr), "");
    // TC04: through the wide BVH, serial and on 1 to 4 threads: the linear scan's image, and the
    // binary BVH's ray counts (the same rays; only the nodes visited differ)
    Image serialWide(nX, nY);
    const RayCounts wideCounts = renderBlock({s.camera, *s.widened, *s.sampler}, all, serialWide);
    EXPECT_EQ(firstDifference(linear, serialWide), "");
    EXPECT_EQ(wideCounts.primary, counts.primary);
    EXPECT_EQ(wideCounts.secondary, counts.secondary);
    EXPECT_EQ(wideCounts.shadow, counts.shadow);
    for (int threads = 1; threads <= 4; ++threads) {
      Image pooledWide(nX, nY);
      renderImage({s.camera, *s.widened, *s.sampler}, pooledWide,
                  {.threads = threads, .tileSize = 3 + threads});
      EXPECT_EQ(firstDifference(linear, pooledWide), "") << threads << " threads";
    }
  }
}

// ---- The pool's own behaviour, with a tracer that sees every call ----

/// Pixel (x, y) gets the colour (x, y, 1), so a rendered pixel has blue 1 and an untouched one
/// (black) has 0. Every call is counted; `onRay` (given the call's number, from 1, and the
/// sample) may raise a stop flag or throw. Safe from several threads, as a tracer must be.
class ProbeTracer final : public RayTracer {
 public:
  using Hook = std::function<void(std::uint64_t call, const SampleContext& ctx)>;
  explicit ProbeTracer(Hook onRay = {}) : RayTracer(emptyScene()), onRay_(std::move(onRay)) {}

  Color traceRay(const Ray&, SampleContext& ctx) const override {
    const std::uint64_t call = calls_.fetch_add(1, std::memory_order_relaxed) + 1;
    if (onRay_) onRay_(call, ctx);
    return Color(ctx.x, ctx.y, 1);
  }
  std::uint64_t calls() const { return calls_.load(); }

 private:
  static const Scene& emptyScene() {
    static const Scene scene;
    return scene;
  }
  Hook onRay_;
  mutable std::atomic<std::uint64_t> calls_{0};
};

Camera cameraOf(int nX, int nY) {
  return Camera::builder()
      .setLocation(Point(0, 0, 10))
      .setDirection(Point(0, 0, 0))
      .setVpDistance(10)
      .setVpSize(nX, nY)
      .setResolution(nX, nY)
      .build();
}

std::uint64_t renderedPixels(const Image& image) {
  std::uint64_t n = 0;
  for (int y = 0; y < image.nY(); ++y)
    for (int x = 0; x < image.nX(); ++x) n += image.pixel(x, y).rgb().z == 1 ? 1 : 0;
  return n;
}

/// Every pixel has its own colour (x, y, 1).
bool complete(const Image& image) {
  for (int y = 0; y < image.nY(); ++y)
    for (int x = 0; x < image.nX(); ++x)
      if (!sameBits(image.pixel(x, y), Color(x, y, 1))) return false;
  return true;
}

/// Renders a 64 x 64 image in tiles of 8 x 8 on `threads` threads, with a stop flag raised
/// before the render when stopAt is 0, else by the tracer during its stopAt-th ray. Checks that
/// the render says interrupted and that what was rendered is exactly what was traced, counted,
/// reported and written; returns how many pixels that is.
std::uint64_t pixelsBeforeStop(int threads, std::uint64_t stopAt) {
  std::atomic<bool> stop{stopAt == 0};
  const ProbeTracer tracer([&stop, stopAt](std::uint64_t call, const SampleContext&) {
    if (call == stopAt) stop = true;
  });
  std::atomic<std::uint64_t> done{0};
  Image image(64, 64);
  const RenderResult r =
      renderImage({cameraOf(64, 64), tracer, CenterSampler()}, image,
                  {.threads = threads, .tileSize = 8, .stop = &stop, .donePixels = &done});
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(r.counts.total(), r.pixels);
  EXPECT_EQ(r.counts.primary, r.pixels);
  EXPECT_EQ(done.load(), r.pixels);
  EXPECT_EQ(tracer.calls(), r.pixels);
  EXPECT_EQ(renderedPixels(image), r.pixels);
  return r.pixels;
}

TEST(TilePoolTests, stop) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a stop raised before the render starts: nothing is rendered, traced or counted
  EXPECT_EQ(pixelsBeforeStop(1, 0), 0u);
  EXPECT_EQ(pixelsBeforeStop(3, 0), 0u);
  // TC02: raised by the tracer during the 101st ray, on one thread: tile 0 (64 pixels) is done,
  // and tile 1 stops at the end of the row that ray is in, its 5th: 64 + 5·8 = 104 pixels
  EXPECT_EQ(pixelsBeforeStop(1, 101), 104u);
  // TC03: the same on 3 threads: each thread finishes at most the row it is in when the stop is
  // raised, so at most 100 + 3·8 rays are traced in all
  const std::uint64_t pixels = pixelsBeforeStop(3, 101);
  EXPECT_GE(pixels, 101u);
  EXPECT_LE(pixels, 100u + 3 * 8);
  // =============== Boundary Values Tests ==================
  // TC11: a stop flag given but never raised: the whole image, not interrupted
  const ProbeTracer tracer;
  const std::atomic<bool> never{false};
  Image image(64, 64);
  const RenderResult r = renderImage({cameraOf(64, 64), tracer, CenterSampler()}, image,
                                     {.threads = 2, .stop = &never});
  EXPECT_FALSE(r.interrupted);
  EXPECT_TRUE(complete(image));
}

TEST(TilePoolTests, exceptions) {
  const Camera camera = cameraOf(64, 64);
  const CenterSampler sampler;
  // ============ Equivalence Partitions Tests ==============
  // TC01: a tracer that throws on its 150th ray: the message arrives on the calling thread, for
  // 1 to 4 threads (every thread joined: no std::terminate)
  for (int threads : {1, 2, 4}) {
    const ProbeTracer tracer([](std::uint64_t call, const SampleContext& ctx) {
      if (call == 150)
        throw std::runtime_error("tracer failed at pixel " + std::to_string(ctx.x) + "," +
                                 std::to_string(ctx.y));
    });
    Image image(64, 64);
    EXPECT_THAT(
        [&] {
          renderImage({camera, tracer, sampler}, image, {.threads = threads, .tileSize = 8});
        },
        ThrowsMessage<std::runtime_error>(HasSubstr("tracer failed at pixel")))
        << threads << " threads";
    // TC02: on one thread, nothing is traced after the exception
    if (threads == 1) {
      EXPECT_EQ(tracer.calls(), 150u);
    }
  }
  // TC03: every ray throws, on every thread at once: one exception (the first) arrives
  {
    const ProbeTracer tracer(
        [](std::uint64_t, const SampleContext&) { throw std::out_of_range("every ray fails"); });
    Image image(64, 64);
    EXPECT_THAT(
        [&] {
          renderImage({camera, tracer, sampler}, image, {.threads = 4, .tileSize = 4});
        },
        ThrowsMessage<std::out_of_range>(HasSubstr("every ray fails")));
  }
}

TEST(TilePoolTests, progressOncePerTile) {
  const Camera camera = cameraOf(64, 64);
  const CenterSampler sampler;
  // ============ Equivalence Partitions Tests ==============
  // TC01: on one thread, in tiles of 8 x 8, every ray of tile k sees exactly 64·k pixels done:
  // the counter moves once per tile, not per pixel
  std::atomic<std::uint64_t> done{0};
  std::atomic<int> wrong{0};
  const ProbeTracer tracer([&](std::uint64_t call, const SampleContext&) {
    if (done.load() != (call - 1) / 64 * 64) ++wrong;
  });
  Image image(64, 64);
  renderImage({camera, tracer, sampler}, image, {.threads = 1, .tileSize = 8, .donePixels = &done});
  EXPECT_EQ(wrong.load(), 0);
  // TC02: at the end, every pixel, on several threads too (added to what the counter held)
  EXPECT_EQ(done.load(), 64u * 64u);
  renderImage({camera, tracer, sampler}, image, {.threads = 3, .tileSize = 7, .donePixels = &done});
  EXPECT_EQ(done.load(), 2u * 64u * 64u);
}

/// Renders an nX x nY image with options; checks that every pixel was rendered once (traced,
/// counted and written); returns how many threads rendered it.
int completeRender(int nX, int nY, const RenderOptions& options) {
  const ProbeTracer tracer;
  Image image(nX, nY);
  const RenderResult r = renderImage({cameraOf(nX, nY), tracer, CenterSampler()}, image, options);
  const auto pixels = static_cast<std::uint64_t>(nX) * static_cast<std::uint64_t>(nY);
  EXPECT_FALSE(r.interrupted);
  EXPECT_EQ(r.pixels, pixels);
  EXPECT_EQ(r.counts.primary, pixels);
  EXPECT_EQ(tracer.calls(), pixels);
  EXPECT_TRUE(complete(image));
  return r.threads;
}

TEST(TilePoolTests, threadsAndSizes) {
  const CenterSampler sampler;
  // ============ Equivalence Partitions Tests ==============
  // TC01: one thread renders on the calling thread: no thread is created
  {
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<int> elsewhere{0};
    const ProbeTracer tracer([&](std::uint64_t, const SampleContext&) {
      if (std::this_thread::get_id() != caller) ++elsewhere;
    });
    const Camera camera = cameraOf(40, 40);
    Image image(40, 40);
    const RenderResult r =
        renderImage({camera, tracer, sampler}, image, {.threads = 1, .tileSize = 8});
    EXPECT_EQ(r.threads, 1);
    EXPECT_EQ(elsewhere.load(), 0);
    EXPECT_TRUE(complete(image));
  }
  // TC02: threads = 0: one per core (never more than the tiles)
  EXPECT_EQ(completeRender(64, 64, {.threads = 0, .tileSize = 1}),
            static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  // =============== Boundary Values Tests ==================
  // TC11: more threads than tiles (8 threads, 4 tiles): 4 threads render
  EXPECT_EQ(completeRender(10, 10, {.threads = 8, .tileSize = 5}), 4);
  // TC12: a 1 x 1 image on 4 threads: one tile, one thread
  EXPECT_EQ(completeRender(1, 1, {.threads = 4}), 1);
  // TC13: a tile larger than the image: one tile, one thread
  EXPECT_EQ(completeRender(20, 10, {.threads = 2, .tileSize = 1000}), 1);
}

TEST(TilePoolTests, invalidOptions) {
  const ProbeTracer tracer;
  const CenterSampler sampler;
  const Camera camera = cameraOf(8, 8);
  Image image(8, 8);
  auto render = [&](const RenderOptions& options) {
    return [&, options] { renderImage({camera, tracer, sampler}, image, options); };
  };
  // =============== Boundary Values Tests ==================
  // TC11: threads -1 and MAX_THREADS + 1 are refused, naming the value
  EXPECT_THAT(render({.threads = -1}),
              ThrowsMessage<std::invalid_argument>(HasSubstr("threads is -1")));
  EXPECT_THAT(render({.threads = RenderOptions::MAX_THREADS + 1}),
              ThrowsMessage<std::invalid_argument>(HasSubstr("threads is 1025")));
  // TC12: tile sizes 0 and -5 are refused, naming the value
  EXPECT_THAT(render({.tileSize = 0}),
              ThrowsMessage<std::invalid_argument>(HasSubstr("tileSize is 0")));
  EXPECT_THAT(render({.tileSize = -5}),
              ThrowsMessage<std::invalid_argument>(HasSubstr("tileSize is -5")));
  // TC13: an image that is not the camera's, naming both sizes
  Image other(8, 9);
  EXPECT_THAT(
      [&] {
        renderImage({camera, tracer, sampler}, other);
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr("image is 8x9, camera is 8x8")));
  // TC14: nothing was traced
  EXPECT_EQ(tracer.calls(), 0u);
  // TC15: the largest accepted thread count and tiles of one pixel are accepted
  EXPECT_NO_THROW(render({.threads = RenderOptions::MAX_THREADS, .tileSize = 1})());
}

TEST(TilePoolTests, allocationsDoNotGrowWithTheImage) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: on one thread, the render allocates the same for 8 x 8 and 64 x 64 pixels (its own
  // bookkeeping, once per render): nothing per tile, per row or per ray
  const CenterSampler sampler;
  SceneSetup<LitScene> setup = course::hallOfMirrors();
  const Bvh bvh(setup.scene.geometries);
  const WhittedTracer tracer(setup.scene, &bvh);
  auto allocations = [&](int side) {
    setup.camera.nX = setup.camera.nY = side;
    const Camera camera = setup.camera.builder().build();
    Image image(side, side);
    return testing::allocationsDuring([&] {
      renderImage({camera, tracer, sampler}, image, {.threads = 1, .tileSize = 4});
    });
  };
  EXPECT_EQ(allocations(8), allocations(64));
}

}  // namespace
}  // namespace rt
