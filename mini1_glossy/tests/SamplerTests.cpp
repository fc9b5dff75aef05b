// Mini project 1: the pixel samplers. Jittered anti-aliasing (one sample in each cell of the
// pixel), depth of field (lens samples), adaptive super-sampling (corners, subdivision where they
// differ, reuse), each checked by what it traces and, statistically, by what it renders.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "camera/Camera.h"
#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "geometries/Sphere.h"
#include "glossy/Samplers.h"
#include "lighting/PhongTracer.h"

namespace rt {
namespace {

/// A camera at the origin looking along -Z, an n x n image whose pixels are 1 x 1 on a view plane
/// at distance 1: the ray through image point (px, py) meets the plane z = -1 at
/// (px − n/2, n/2 − py).
Camera::Builder unitView(int n) {
  return Camera::builder()
      .setLocation(Point::ZERO)
      .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
      .setVpSize(n, n)
      .setVpDistance(1)
      .setResolution(n, n);
}

/// Records the image point of every ray it traces (back from the plane z = -1) and returns
/// red = 1 when that point is left of the image's centre line x = edge (in image units).
class PointTracer final : public RayTracer {
 public:
  PointTracer(const Scene& scene, int n, double edge = 1e9)
      : RayTracer(scene), n_(n), edge_(edge) {}
  using RayTracer::traceRay;
  Color traceRay(const Ray& ray, SampleContext& ctx) const override {
    const double t = -1 / ray.direction().z();
    const Point p = ray.point(t);
    const double px = p.x() + n_ / 2.0, py = n_ / 2.0 - p.y();
    points.push_back({px, py});
    samples.push_back(ctx.sample);
    return px < edge_ ? Color(1, 0, 0) : Color::BLACK;
  }
  mutable std::vector<std::pair<double, double>> points;
  mutable std::vector<std::uint32_t> samples;

 private:
  int n_;
  double edge_;
};

TEST(JitteredSamplerTests, oneSampleInEveryCell) {
  const Scene scene;
  const PointTracer tracer(scene, 8);
  const Camera camera = unitView(8).build();
  RayCounts counts;
  // ============ Equivalence Partitions Tests ==============
  // TC01: N = 4 for pixel (3, 5): 16 rays, one in each 1/4 x 1/4 cell of the pixel, sample
  // indices 0..15
  const JitteredSampler four(4, 1, 9);
  four.pixelColor(camera, tracer, 3, 5, counts);
  ASSERT_EQ(16u, tracer.points.size());
  std::set<std::pair<int, int>> cells;
  for (const auto& [px, py] : tracer.points) {
    EXPECT_GE(px, 3.0);
    EXPECT_LT(px, 4.0);
    EXPECT_GE(py, 5.0);
    EXPECT_LT(py, 6.0);
    cells.insert({static_cast<int>((px - 3) * 4), static_cast<int>((py - 5) * 4)});
  }
  EXPECT_EQ(16u, cells.size());
  EXPECT_EQ((std::set<std::uint32_t>(tracer.samples.begin(), tracer.samples.end())).size(), 16u);
  EXPECT_EQ(16u, counts.primary);
  EXPECT_EQ(16, four.samplesPerPixel());
  // =============== Boundary Values Tests ==================
  // TC11: N = 1: the pixel's centre, like the course's sampler
  tracer.points.clear();
  JitteredSampler(1).pixelColor(camera, tracer, 3, 5, counts);
  ASSERT_EQ(1u, tracer.points.size());
  EXPECT_NEAR(3.5, tracer.points[0].first, 1e-12);
  EXPECT_NEAR(5.5, tracer.points[0].second, 1e-12);
  // TC12: out of range
  EXPECT_THROW(JitteredSampler(0), std::invalid_argument);
  EXPECT_THROW(JitteredSampler(JitteredSampler::MAX_GRID + 1), std::invalid_argument);
  EXPECT_THROW(JitteredSampler(2, 0), std::invalid_argument);
}

TEST(JitteredSamplerTests, antiAliasedEdgeStatistics) {
  // An edge at x = 2.3 (image units) through the pixels of column 2: each pixel of that column is
  // covered 30% by the red side. With N = 4 (16 stratified samples), 64 pixels of the column:
  const Scene scene;
  const PointTracer tracer(scene, 64, 2.3);
  const Camera camera = unitView(64).build();
  const JitteredSampler sampler(4, 1, 21);
  RayCounts counts;
  double sum = 0, sumSquares = 0;
  for (int y = 0; y < 64; ++y) {
    const double red = sampler.pixelColor(camera, tracer, 2, y, counts).r();
    sum += red;
    sumSquares += red * red;
  }
  const double mean = sum / 64, variance = sumSquares / 64 - mean * mean;
  // ============ Equivalence Partitions Tests ==============
  // TC01: the mean coverage is 0.3 within 0.02. Only the four cells of the pixel's second
  // column are uncertain: each is red with probability 0.2 (its part left of the edge), so a
  // pixel's value is (4 + B)/16 with B ~ Binomial(4, 0.2): mean (4 + 0.8)/16 = 0.3, standard
  // deviation √(4·0.2·0.8)/16 = 0.05; over 64 pixels, 0.00625, and 0.02 is 3.2 of those.
  EXPECT_NEAR(0.3, mean, 0.02);
  // TC02: the variance is the binomial's, 0.0025, within a factor 2 either way (the sample
  // variance of 64 values is within ±50% of the true one with high probability)
  EXPECT_GT(variance, 0.0025 / 2);
  EXPECT_LT(variance, 0.0025 * 2);
  // =============== Boundary Values Tests ==================
  // TC11: every pixel is one of the five values (4 + B)/16, B = 0..4: the strata hold
  for (int y = 0; y < 8; ++y) {
    const double red = sampler.pixelColor(camera, tracer, 2, y, counts).r();
    EXPECT_NEAR(0, std::fmod(red * 16, 1.0), 1e-12);
    EXPECT_GE(red, 4.0 / 16);
    EXPECT_LE(red, 8.0 / 16);
  }
}

TEST(JitteredSamplerTests, depthOfField) {
  // A sphere of radius 1 at distance 10 and the camera's lens (aperture 0.5) focused at 10 or
  // at 3. A pixel is 0.01 of the view plane at distance 1, so 0.1 on the sphere's plane: the
  // sphere's image is the disk of radius 10 pixels around the image's centre (20, 20).
  LitScene scene;
  scene.add(Sphere(Point(0, 0, -10), 1), Color(100, 0, 0));
  const PhongTracer tracer(scene);
  const int n = 40;
  const auto camera = [&](double focus) {
    return Camera::builder()
        .setLocation(Point::ZERO)
        .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
        .setVpSize(0.4, 0.4)
        .setVpDistance(1)
        .setResolution(n, n)
        .setAperture(0.5)
        .setFocalDistance(focus)
        .build();
  };
  const JitteredSampler lens(1, 64, 2);
  RayCounts counts;
  // ============ Equivalence Partitions Tests ==============
  // TC01: in focus (10): every lens ray of a pixel meets the pinhole ray on the sphere's plane:
  // the pixel in the middle is all sphere, one 15 pixels up all background
  const Camera sharp = camera(10);
  EXPECT_NEAR(100, lens.pixelColor(sharp, tracer, 20, 20, counts).r(), 1e-9);
  EXPECT_NEAR(0, lens.pixelColor(sharp, tracer, 20, 5, counts).r(), 1e-9);
  // TC02: out of focus (3): a pixel just inside the silhouette (row 11, 0.85 from the centre)
  // mixes sphere and background: the blur circle on the sphere's plane has radius
  // a·|10 − 3|/3 ≈ 1.17, larger than the sphere; in focus the same pixel is all sphere
  const Camera blurred = camera(3);
  EXPECT_NEAR(100, lens.pixelColor(sharp, tracer, 20, 11, counts).r(), 1e-9);
  const double edge = lens.pixelColor(blurred, tracer, 20, 11, counts).r();
  EXPECT_GT(edge, 5);
  EXPECT_LT(edge, 95);
  EXPECT_EQ(64, lens.samplesPerPixel());
  // =============== Boundary Values Tests ==================
  // TC11: without an aperture the lens samples collapse to one ray per cell
  counts = {};
  lens.pixelColor(unitView(n).build(), tracer, 20, 20, counts);
  EXPECT_EQ(1u, counts.primary);
}

TEST(AdaptiveSamplerTests, cornersSubdivisionAndReuse) {
  const Scene scene;
  const Camera camera = unitView(16).build();
  RayCounts counts;
  // ============ Equivalence Partitions Tests ==============
  // TC01: a uniform pixel: its four corners agree, nothing is subdivided: 4 rays
  const PointTracer uniform(scene, 16);  // everything red
  const AdaptiveSampler sampler(0.1, 3, 4);
  EXPECT_EQ(Color(1, 0, 0), sampler.pixelColor(camera, uniform, 5, 5, counts));
  EXPECT_EQ(4u, uniform.points.size());
  // TC02: an edge through the pixel (x = 5.3, lattice column 2.4 of 0..8): subdivided where the
  // corners differ, down to the depth limit along the edge only; every traced point is a lattice
  // point of the pixel, traced once (corners reused). By hand: the right half is black (0); in
  // each left quarter (columns 0..4) the squares of side 2 over columns 0..2 are red (1) and those
  // over 2..4 split into squares of side 1, half red over 2..3 (0.5) and black over 3..4, so 0.25;
  // a left quarter is (1 + 1 + 0.25 + 0.25) / 4 = 0.625 and the pixel 0.3125. The points: column
  // 0 at rows 0, 2, .., 8 (5), columns 2, 3 and 4 at every row (27), column 8 at 0, 4, 8 (3): 35
  // of the 9 x 9 lattice.
  const PointTracer edge(scene, 16, 5.3);
  const Color c = sampler.pixelColor(camera, edge, 5, 5, counts);
  std::set<std::pair<double, double>> distinct(edge.points.begin(), edge.points.end());
  EXPECT_EQ(edge.points.size(), distinct.size());
  EXPECT_EQ(35u, edge.points.size());
  for (const auto& [px, py] : edge.points) {
    EXPECT_NEAR(0, std::fmod((px - 5) * 8, 1.0), 1e-9);
    EXPECT_NEAR(0, std::fmod((py - 5) * 8, 1.0), 1e-9);
  }
  EXPECT_EQ(0.3125, c.r());
  EXPECT_EQ(0, c.g());
  // =============== Boundary Values Tests ==================
  // TC11: depth limit 0: the four corners only, whatever they are
  const PointTracer edge0(scene, 16, 5.3);
  AdaptiveSampler(0.1, 0).pixelColor(camera, edge0, 5, 5, counts);
  EXPECT_EQ(4u, edge0.points.size());
  EXPECT_EQ(4, AdaptiveSampler(0.1, 0).samplesPerPixel());
  EXPECT_EQ(81, sampler.samplesPerPixel());
  // TC12: a threshold above the difference (1 > 1 − 0): never subdivided
  const PointTracer edge1(scene, 16, 5.3);
  AdaptiveSampler(1, 3).pixelColor(camera, edge1, 5, 5, counts);
  EXPECT_EQ(4u, edge1.points.size());
  // TC13: out of range
  EXPECT_THROW(AdaptiveSampler(-1, 2), std::invalid_argument);
  EXPECT_THROW(AdaptiveSampler(1, AdaptiveSampler::MAX_DEPTH + 1), std::invalid_argument);
}

TEST(SamplerFactoryTests, settingsChooseTheSampler) {
  // TC01: the defaults: one ray through the centre (the course's sampler)
  EXPECT_EQ(1, makePixelSampler({})->samplesPerPixel());
  // TC02: samples 3, lens samples 2: 18 rays; adaptive: its lattice
  EXPECT_EQ(18, makePixelSampler({.samples = 3, .lensSamples = 2})->samplesPerPixel());
  EXPECT_EQ(25, makePixelSampler({.adaptive = true, .adaptiveDepth = 2})->samplesPerPixel());
  // TC03: the seed is passed on
  EXPECT_EQ(77u, makePixelSampler({.seed = 77})->seed());
}

}  // namespace
}  // namespace rt
