// Stage 4: the render loop apart from the camera: Camera::ray at any image point, the sample
// context each ray is traced with, the course's centre sampler and renderBlock's counts.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "camera/Camera.h"
#include "camera/RenderBlock.h"
#include "camera/Scene.h"
#include "support/AllocationCounter.h"

namespace rt {
namespace {

/// A camera at the origin looking along -Z, up +Y, an nX x nY view plane (one unit per pixel)
/// at distance 10.
Camera::Builder view(int nX, int nY) {
  return Camera::builder()
      .setLocation(Point::ZERO)
      .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
      .setVpSize(nX, nY)
      .setVpDistance(10)
      .setResolution(nX, nY);
}

void expectSameRay(const Ray& expected, const Ray& actual) {
  EXPECT_EQ(expected.head().x(), actual.head().x());
  EXPECT_EQ(expected.head().y(), actual.head().y());
  EXPECT_EQ(expected.head().z(), actual.head().z());
  EXPECT_EQ(expected.direction().x(), actual.direction().x());
  EXPECT_EQ(expected.direction().y(), actual.direction().y());
  EXPECT_EQ(expected.direction().z(), actual.direction().z());
}

/// Remembers what it was asked (the ray and the context's pixel, sample and first number),
/// counts one secondary ray per call, and returns the pixel's column as red.
class RecordingTracer final : public RayTracer {
 public:
  struct Call {
    Ray ray;
    int x, y;
    std::uint32_t sample;
    double firstNumber;
  };
  explicit RecordingTracer(const Scene& scene) : RayTracer(scene) {}
  using RayTracer::traceRay;
  Color traceRay(const Ray& ray, SampleContext& ctx) const override {
    calls.push_back({ray, ctx.x, ctx.y, ctx.sample, ctx.random.uniform(0)});
    ++ctx.counts.secondary;
    return Color(ctx.x, ctx.y, 0);
  }
  mutable std::vector<Call> calls;
};

TEST(CameraRayTests, pixelCentreIsConstructRay) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: (j + 0.5, i + 0.5) gives constructRay(nX, nY, j, i) bit for bit, for every pixel of an
  // odd and of an even grid, on a tilted camera with rectangular pixels
  for (const auto& [nX, nY] : {std::pair{5, 3}, std::pair{4, 6}}) {
    const Camera camera = Camera::builder()
                              .setLocation(Point(1, 2, 3))
                              .setDirection(Point(-4, 0.5, -7), Vector(0.1, 1, 0))
                              .setVpSize(3.7, 2.9)
                              .setVpDistance(4.1)
                              .setResolution(nX, nY)
                              .build();
    for (int i = 0; i < nY; ++i)
      for (int j = 0; j < nX; ++j)
        expectSameRay(camera.constructRay(nX, nY, j, i), camera.ray(j + 0.5, i + 0.5));
  }
  // =============== Boundary Values Tests ==================
  // TC11: the image's top-left corner (0, 0) is the view plane's corner (-w/2, h/2)
  const Camera camera = view(4, 2).build();
  const Ray corner = camera.ray(0, 0);
  EXPECT_EQ(Point::ZERO, corner.head());
  EXPECT_EQ(Vector(-2, 1, -10).normalized(), corner.direction());
  // TC12: the bottom-right corner (nX, nY) is (w/2, -h/2)
  EXPECT_EQ(Vector(2, -1, -10).normalized(), camera.ray(4, 2).direction());
  // TC13: the image's centre (nX/2, nY/2) is the view plane's centre
  EXPECT_EQ(Vector(0, 0, -1), camera.ray(2, 1).direction());
}

TEST(CameraRayTests, thinLens) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: with an aperture, the ray leaves the lens point location + a·(u·vRight + v·vUp) and
  // passes through the pinhole ray's point at the focal distance
  const Camera lens = view(4, 4).setAperture(2).setFocalDistance(20).build();
  const Ray r = lens.ray(3, 1, Sample2{0.5, -0.25});
  EXPECT_EQ(Point(1, -0.5, 0), r.head());
  // the pinhole ray through (3, 1) aims at (1, 1, -10): at focal distance 20 it is (2, 2, -20)
  EXPECT_EQ((Point(2, 2, -20) - Point(1, -0.5, 0)).normalized(), r.direction());
  // TC02: the lens's centre gives the pinhole ray
  expectSameRay(view(4, 4).build().ray(3, 1), lens.ray(3, 1, Sample2{0, 0}));
  // =============== Boundary Values Tests ==================
  // TC11: without an aperture the lens sample is ignored
  expectSameRay(view(4, 4).build().ray(3, 1), view(4, 4).build().ray(3, 1, Sample2{0.5, 0.5}));
  // TC12: focal distance 0 focuses on the view plane: rays through (3, 1) from any lens point
  // meet at the view-plane point (1, 1, -10)
  const Camera onPlane = view(4, 4).setAperture(1).build();
  EXPECT_EQ(10.0, onPlane.focalDistance());
  const Ray a = onPlane.ray(3, 1, Sample2{1, 0}), b = onPlane.ray(3, 1, Sample2{0, -1});
  const double ta = (-10 - a.head().z()) / a.direction().z();
  const double tb = (-10 - b.head().z()) / b.direction().z();
  EXPECT_EQ(Point(1, 1, -10), a.point(ta));
  EXPECT_EQ(Point(1, 1, -10), b.point(tb));
  // TC13: a negative or non-finite aperture or focal distance is refused, naming it
  EXPECT_THROW(view(4, 4).setAperture(-1), std::invalid_argument);
  EXPECT_THROW(view(4, 4).setFocalDistance(std::nan("")), std::invalid_argument);
  // TC14: a focal plane so close to a far location that it rounds to the location: refused at
  // build (its rays would have no direction)
  const auto far = [] {
    return Camera::builder()
        .setLocation(Point(1e6, 1e6, 1e6))
        .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
        .setVpSize(4, 4)
        .setVpDistance(10)
        .setResolution(4, 4);
  };
  try {
    (void)far().setAperture(1).setFocalDistance(1e-20).build();
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(
        "Camera::Builder: the focal plane at distance 1e-20 from the location (1e+06,1e+06,"
        "1e+06) rounds to the location itself (the distance is too small for coordinates this "
        "large)",
        e.what());
  }
  // TC15: the same focal distance without an aperture is never used: accepted
  EXPECT_NO_THROW((void)far().setFocalDistance(1e-20).build());
}

TEST(CameraRayTests, viewPlaneRoundingToTheLocationIsRefused) {
  // TC11: a view plane at distance 1e-10 from a location at 1e8: p0 + d·vTo == p0 in doubles
  try {
    (void)Camera::builder()
        .setLocation(Point(0, 0, 1e8))
        .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
        .setVpSize(1, 1)
        .setVpDistance(1e-10)
        .setResolution(2, 2)
        .build();
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(
        "Camera::Builder: the view plane at distance 1e-10 from the location (0,0,1e+08) "
        "rounds to the location itself (the distance is too small for coordinates this large)",
        e.what());
  }
  // TC12: a little farther it is representable: accepted
  EXPECT_NO_THROW((void)Camera::builder()
                      .setLocation(Point(0, 0, 1e8))
                      .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
                      .setVpSize(1, 1)
                      .setVpDistance(1e-5)
                      .setResolution(2, 2)
                      .build());
}

TEST(RenderBlockTests, centreSamplerTracesEachPixelOnce) {
  const Scene scene;
  const RecordingTracer tracer(scene);
  const Camera camera = view(4, 3).build();
  Image image(4, 3);
  // ============ Equivalence Partitions Tests ==============
  // TC01: a 2x2 block: one ray per pixel, through its centre, with the pixel's context (sample
  // 0, numbers of RandomStream(seed, x, y, 0)); the pixel gets the tracer's colour
  const CenterSampler sampler(77);
  const RayCounts counts = renderBlock({camera, tracer, sampler}, {1, 1, 3, 3}, image);
  ASSERT_EQ(4u, tracer.calls.size());
  const int expected[4][2] = {{1, 1}, {2, 1}, {1, 2}, {2, 2}};  // row by row
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& c = tracer.calls[k];
    EXPECT_EQ(expected[k][0], c.x);
    EXPECT_EQ(expected[k][1], c.y);
    EXPECT_EQ(0u, c.sample);
    EXPECT_EQ(RandomStream(77, c.x, c.y, 0).uniform(0), c.firstNumber);
    expectSameRay(camera.constructRay(4, 3, c.x, c.y), c.ray);
    EXPECT_EQ(Color(c.x, c.y, 0), image.pixel(c.x, c.y));
  }
  // TC02: the counts: one primary ray per pixel (the sampler's), the tracer's own counts added
  EXPECT_EQ((RayCounts{4, 4, 0, {}}), counts);
  // TC03: pixels outside the block are untouched
  EXPECT_EQ(Color::BLACK, image.pixel(0, 0));
  EXPECT_EQ(Color::BLACK, image.pixel(3, 2));
  EXPECT_EQ(1, sampler.samplesPerPixel());
}

TEST(RenderBlockTests, blocksGiveTheSameImageAsAWholeRender) {
  // TC01: rendering in 2x2 tiles (in any order) or in one block gives the same pixels: each
  // pixel's colour depends on its coordinates only
  const Scene scene;
  const RecordingTracer tracer(scene);
  const Camera camera = view(5, 3).build();
  const CenterSampler sampler(1);
  Image whole(5, 3), tiled(5, 3);
  renderBlock({camera, tracer, sampler}, {0, 0, 5, 3}, whole);
  RayCounts sum;
  for (const PixelBlock& b : {PixelBlock{4, 2, 5, 3}, PixelBlock{0, 2, 4, 3},
                              PixelBlock{2, 0, 5, 2}, PixelBlock{0, 0, 2, 2}})
    sum += renderBlock({camera, tracer, sampler}, b, tiled);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) EXPECT_EQ(whole.pixel(x, y), tiled.pixel(x, y)) << x << "," << y;
  // TC02: the tiles' counts add up to the whole image's
  EXPECT_EQ(15u, sum.primary);
}

TEST(RenderBlockTests, badBlocksAreRefusedBeforeAnyRay) {
  const Scene scene;
  const RecordingTracer tracer(scene);
  const Camera camera = view(4, 4).build();
  const CenterSampler sampler;
  Image image(4, 4);
  // TC11: an empty block
  EXPECT_THROW(renderBlock({camera, tracer, sampler}, {1, 1, 1, 3}, image), std::invalid_argument);
  // TC12: past the right edge, named with the image's size
  try {
    renderBlock({camera, tracer, sampler}, {0, 0, 5, 1}, image);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ("renderBlock: block columns [0,5) rows [0,1) is empty or not inside the 4x4 image",
                 e.what());
  }
  // TC13: a negative start
  EXPECT_THROW(renderBlock({camera, tracer, sampler}, {0, -1, 1, 1}, image), std::invalid_argument);
  // TC14: an image that is not the camera's size
  Image small(3, 4);
  EXPECT_THROW(renderBlock({camera, tracer, sampler}, {0, 0, 1, 1}, small), std::invalid_argument);
  EXPECT_TRUE(tracer.calls.empty());
  // TC15: the whole image is one valid block
  EXPECT_EQ(16u, renderBlock({camera, tracer, sampler}, {0, 0, 4, 4}, image).primary);
}

TEST(RenderBlockTests, allocatesNothing) {
  // TC01: a block rendered by the ambient tracer, with a lens, allocates nothing
  Scene scene;
  scene.geometries.add(Sphere(Point(0, 0, -20), 3));
  const AmbientTracer tracer(scene);
  const Camera camera = view(16, 16).setAperture(0.5).build();
  const CenterSampler sampler(3);
  Image image(16, 16);
  RayCounts counts;
  EXPECT_EQ(0, testing::allocationsDuring([&] {
              counts = renderBlock({camera, tracer, sampler}, {0, 0, 16, 16}, image);
            }));
  EXPECT_EQ(256u, counts.primary);
  // TC02: the intersection tests were counted (one shape per ray)
  EXPECT_EQ(256u, counts.queries.shapeTests);
}

TEST(RenderBlockTests, renderImageCountsItsRays) {
  // TC01: the course's renderImage is renderBlock row by row: its counts are the image's
  Scene scene;
  const auto tracer = std::make_shared<RecordingTracer>(scene);
  Camera camera = view(3, 2).setRayTracer(tracer).build();
  camera.renderImage();
  EXPECT_EQ((RayCounts{6, 6, 0, {}}), camera.rayCounts());
  EXPECT_EQ(Color(2, 1, 0), camera.image().pixel(2, 1));
}

}  // namespace
}  // namespace rt
