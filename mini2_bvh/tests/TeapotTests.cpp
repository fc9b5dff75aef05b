// mini2: the course's TeapotTest as a scene (scenes/Teapot.h). The teapot's triangles, its box
// and the course's own points after the placement; the camera, the light and the look; the
// bubbles in their cone, the same for the same seed; and the images through the BVH and the grid
// the same bits as through the scene's own list.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <variant>

#include "bvh/Bvh.h"
#include "camera/Camera.h"
#include "geometries/Sphere.h"
#include "grid/Grid.h"
#include "parallel/TilePool.h"
#include "reflections/WhittedTracer.h"
#include "scenes/Teapot.h"

namespace rt {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// The placement's scale (Teapot.h): the box's extremes below are Newell's, times it, moved.
constexpr double S = 28.42544;

struct Box {
  Double3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity()};
  Double3 hi = lo * -1;
};

Box boxOf(const TriangleMesh& m) {
  Box b;
  for (const Point& p : m.vertices()) {
    const Double3& q = p.xyz();
    b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y), std::min(b.lo.z, q.z)};
    b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y), std::max(b.hi.z, q.z)};
  }
  return b;
}

TEST(TeapotTests, theMeshHasTheCoursesTriangles) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: detail 4 is the course's 992 triangles, over 32 patches of 5 x 5 vertices, flat
  const auto flat = teapotMesh();
  EXPECT_EQ(flat->triangleCount(), 992u);
  EXPECT_EQ(flat->vertexCount(), 800u);
  EXPECT_FALSE(flat->hasNormals());
  // TC02: smooth: the same vertices and triangles, with a normal per vertex
  const auto smooth = teapotMesh({.detail = 4, .smooth = true});
  EXPECT_EQ(smooth->triangles(), flat->triangles());
  EXPECT_EQ(smooth->vertices(), flat->vertices());
  EXPECT_EQ(smooth->normals().size(), 800u);
  // TC03: a finer teapot, 64·d² - 8·d triangles (d = 13: about 10^4)
  EXPECT_EQ(teapotMesh({.detail = 13})->triangleCount(), 10712u);
  // =============== Boundary Values Tests ==================
  // TC11: the coarsest, detail 1 (52: the spout's tip patches vanish)
  EXPECT_EQ(teapotMesh({.detail = 1})->triangleCount(), 52u);
  // TC12: detail 0 and 257 are refused, naming the detail
  for (const int detail : {0, 257})
    EXPECT_THAT([detail] { teapotMesh({.detail = detail}); },
                ThrowsMessage<std::invalid_argument>(HasSubstr("got " + std::to_string(detail))));
}

TEST(TeapotTests, theMeshIsPlacedAsTheCourses) {
  const auto mesh = teapotMesh();
  const Box b = boxOf(*mesh);
  // TC01: the box's extremes are Newell's (the handle at x = -3, the spout's tip at 3.428125
  // (a quad's corner at u = 1/2), the body's widest circle of radius 2, the bottom at z = 0,
  // the knob's top at 3.15) turned y up, scaled and moved, exactly
  EXPECT_EQ(b.lo.x, -3 * S + 0.831025);
  EXPECT_EQ(b.hi.x, 3.428125 * S + 0.831025);
  EXPECT_EQ(b.lo.y, -39.8754);
  EXPECT_EQ(b.hi.y, 3.15 * S - 39.8754);
  EXPECT_EQ(b.lo.z, -2 * S - 1.10804);
  EXPECT_EQ(b.hi.z, 2 * S - 1.10804);
  // TC02: so it fills the course's view as the course's does: x from -84.4 to 98.3, y from
  // -39.9 to 49.7, inside the view plane's -100..100
  EXPECT_NEAR(b.lo.x, -84.4453, 1e-3);
  EXPECT_NEAR(b.hi.x, 98.2770, 1e-3);
  EXPECT_NEAR(b.hi.y, 49.6647, 1e-3);
  // TC03: points of the course's file (its rim, handle, spout, knob, bottom, body, printed to 6
  // digits) are vertices of ours to within 1e-4
  const Double3 course[] = {
      {40.6266, 28.3457, -1.10804},  {37.5425, 28.3457, 14.5117},   {-84.4453, 11.2904, -1.10804},
      {98.2769, 30.5442, -1.10804},  {0.831025, 49.6647, -1.10804}, {0.831025, -39.8754, -1.10804},
      {57.6819, -14.2925, -1.10804}, {22.7411, -39.5089, 8.21414},  {89.7049, 30.2444, 3.15578}};
  for (const Double3& c : course) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Point& p : mesh->vertices())
      nearest = std::min(nearest, std::sqrt((p.xyz() - c).lengthSquared()));
    EXPECT_LT(nearest, 1e-4) << c.x << "," << c.y << "," << c.z;
  }
  // TC04: the turn is a rotation, not a mirror: the turned normals still agree with every
  // triangle's winding (both outward)
  const auto smooth = teapotMesh({.detail = 4, .smooth = true});
  std::size_t agreeing = 0;
  for (std::size_t t = 0; t < smooth->triangleCount(); ++t) {
    const TriangleMesh::Indices& i = smooth->triangles()[t];
    const Double3 n = smooth->normals()[i[0]].xyz() + smooth->normals()[i[1]].xyz() +
                      smooth->normals()[i[2]].xyz();
    agreeing += n.dot(smooth->flatNormal(t).xyz()) > 0 ? 1 : 0;
  }
  EXPECT_EQ(agreeing, smooth->triangleCount());
}

TEST(TeapotTests, theSceneIsTheCoursesTeapotTest) {
  const SceneSetup<LitScene> t = teapotScene();
  const LitScene& s = t.scene;
  // TC01: one mesh, no other shape, one look: emission (200,0,0), kD 0.5, kS 0.5, shininess 60
  EXPECT_EQ(s.geometries.size(), 0u);
  ASSERT_EQ(s.geometries.meshes().size(), 1u);
  EXPECT_EQ(s.geometries.primitiveCount(), 992u);
  ASSERT_EQ(s.meshAppearance.size(), 1u);
  const Appearance& look = s.appearances[s.meshAppearance[0]];
  EXPECT_EQ(look.emission, Color(200, 0, 0));
  EXPECT_EQ(look.material.kD, Double3(0.5));
  EXPECT_EQ(look.material.kS, Double3(0.5));
  EXPECT_EQ(look.material.shininess, 60);
  EXPECT_EQ(look.material.kT, Double3(0));
  EXPECT_EQ(look.material.kR, Double3(0));
  // TC02: the point light (500,500,500) at (100,0,-100), kQ 1e-6; black, no ambient light
  ASSERT_EQ(s.lights.size(), 1u);
  const PointLight& light = std::get<PointLight>(s.lights[0]);
  EXPECT_EQ(light.intensity, Color(500, 500, 500));
  EXPECT_EQ(light.position, Point(100, 0, -100));
  EXPECT_EQ(light.kC, 1);
  EXPECT_EQ(light.kL, 0);
  EXPECT_EQ(light.kQ, 1e-6);
  EXPECT_EQ(s.background, Color::BLACK);
  EXPECT_EQ(s.ambientLight.intensity(), Color::BLACK);
  // TC03: the camera at (0,0,-1000) along +z, up +y, 200 x 200 at 1000, 800 x 800
  const CameraSpec& c = t.camera;
  EXPECT_EQ(c.location, Point(0, 0, -1000));
  ASSERT_TRUE(c.to.has_value());
  EXPECT_EQ(*c.to, Vector(0, 0, 1));
  EXPECT_EQ(c.up, Vector(0, 1, 0));
  EXPECT_EQ(c.vpWidth, 200);
  EXPECT_EQ(c.vpHeight, 200);
  EXPECT_EQ(c.vpDistance, 1000);
  EXPECT_EQ(c.nX, 800);
  EXPECT_EQ(c.nY, 800);
  // TC04: smooth shading gives the mesh its normals, nothing else changes
  const SceneSetup<LitScene> smooth = teapotScene({.detail = 4, .smooth = true});
  EXPECT_TRUE(smooth.scene.geometries.meshes()[0].mesh->hasNormals());
  EXPECT_FALSE(s.geometries.meshes()[0].mesh->hasNormals());
}

TEST(TeapotTests, bubblesRiseInTheirConeFromTheSpout) {
  const SceneSetup<LitScene> b = bubblesScene();
  const LitScene& s = b.scene;
  // TC01: the teapot and its light, 1000 x 1000, and the course's 400 bubbles
  EXPECT_EQ(s.geometries.meshes().size(), 1u);
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(b.camera.nX, 1000);
  EXPECT_EQ(b.camera.nY, 1000);
  ASSERT_EQ(s.geometries.size(), 400u);
  EXPECT_EQ(s.geometries.primitiveCount(), 1392u);
  // TC02: every bubble in the cone of apex (90,30,0.2), radius 0.3 per unit of height, height
  // below 70; radius in [0.1, 1); black, kD below 0.1 on each channel, kS 0.2, kR 0.1
  double highest = 0;
  for (std::uint32_t i = 0; i < s.geometries.size(); ++i) {
    const Sphere& sphere = std::get<Sphere>(s.geometries[i]);
    const Double3 d = sphere.center().xyz() - Double3(90, 30, 0.2);
    EXPECT_GE(d.y, 0) << i;
    EXPECT_LT(d.y, 70) << i;
    EXPECT_LE(std::hypot(d.x, d.z), 0.3 * d.y + 1e-12) << i;
    EXPECT_GE(sphere.radius(), 0.1) << i;
    EXPECT_LT(sphere.radius(), 1) << i;
    highest = std::max(highest, d.y);
    const Appearance& a = s.appearanceOf(i);
    EXPECT_EQ(a.emission, Color::BLACK) << i;
    for (const double k : {a.material.kD.x, a.material.kD.y, a.material.kD.z}) {
      EXPECT_GE(k, 0) << i;
      EXPECT_LT(k, 0.1) << i;
    }
    EXPECT_EQ(a.material.kS, Double3(0.2)) << i;
    EXPECT_EQ(a.material.kR, Double3(0.1)) << i;
    EXPECT_EQ(a.material.kT, Double3(0)) << i;
  }
  // TC03: they fill the cone's height (400 uniform heights: the highest above 69)
  EXPECT_GT(highest, 69);
  // TC04: the same seed, the same bubbles; another seed, other ones
  const auto centres = [](const LitScene& scene) {
    std::vector<Double3> c;
    for (const Geometry& g : scene.geometries.shapes())
      c.push_back(std::get<Sphere>(g).center().xyz());
    return c;
  };
  EXPECT_EQ(centres(bubblesScene().scene), centres(s));
  EXPECT_EQ(centres(bubblesScene({}, {.count = 400, .seed = 1}).scene), centres(s));
  EXPECT_NE(centres(bubblesScene({}, {.count = 400, .seed = 2}).scene), centres(s));
  // TC05: fewer bubbles are the first ones of the same seed
  const std::vector<Double3> all = centres(s);
  EXPECT_EQ(centres(bubblesScene({}, {.count = 10}).scene),
            std::vector<Double3>(all.begin(), all.begin() + 10));
  // =============== Boundary Values Tests ==================
  // TC11: no bubbles: the teapot alone, 1000 x 1000
  EXPECT_EQ(bubblesScene({}, {.count = 0}).scene.geometries.size(), 0u);
  // TC12: a count beyond the most, and a negative one, refused naming the count
  for (const int count : {-1, BubbleOptions::MAX_COUNT + 1})
    EXPECT_THAT([count] { bubblesScene({}, {.count = count}); },
                ThrowsMessage<std::invalid_argument>(HasSubstr("count")));
}

/// The scene's image at n x n pixels through the scene's own list (accel none), the BVH and the
/// grid, by the Whitted tracer (the course's SimpleRayTracer).
struct ThreeImages {
  Image none, bvh, grid;
};

ThreeImages renderThreeWays(const SceneSetup<LitScene>& setup, int n) {
  CameraSpec spec = setup.camera;
  spec.nX = spec.nY = n;
  const Camera camera = spec.builder().build();
  const CenterSampler sampler;
  const Bvh bvh(setup.scene.geometries);
  const Grid grid(setup.scene.geometries);
  ThreeImages images{Image(n, n), Image(n, n), Image(n, n)};
  const auto render = [&](const Intersectable* accel, Image& image) {
    const WhittedTracer tracer(setup.scene, accel);
    renderImage({camera, tracer, sampler}, image, {.threads = 1});
  };
  render(nullptr, images.none);
  render(&bvh, images.bvh);
  render(&grid, images.grid);
  return images;
}

bool sameBits(const Image& a, const Image& b) {
  for (int y = 0; y < a.nY(); ++y)
    for (int x = 0; x < a.nX(); ++x)
      if (std::memcmp(&a.pixel(x, y), &b.pixel(x, y), sizeof(Color)) != 0) return false;
  return true;
}

TEST(TeapotTests, theBvhAndTheGridRenderTheSameBits) {
  // TC01: the teapot at 32 x 32: the BVH's and the grid's images are the list's, bit for bit
  const ThreeImages t = renderThreeWays(teapotScene(), 32);
  EXPECT_TRUE(sameBits(t.bvh, t.none));
  EXPECT_TRUE(sameBits(t.grid, t.none));
  // TC02: the pixel at the middle sees the teapot's lit body: its emission (200,0,0) plus the
  // white light's diffuse and specular share, the same on every channel
  const Double3& middle = t.none.pixel(16, 16).rgb();
  EXPECT_GT(middle.y, 0);
  EXPECT_EQ(middle.y, middle.z);
  EXPECT_NEAR(middle.x - middle.y, 200, 1e-9);
  // TC03: a corner sees nothing: the black background
  EXPECT_EQ(t.none.pixel(0, 0), Color::BLACK);
  // TC04: smooth shading, and the bubbles (their reflections, their shadows on the teapot)
  const ThreeImages smooth = renderThreeWays(teapotScene({.detail = 4, .smooth = true}), 24);
  EXPECT_TRUE(sameBits(smooth.bvh, smooth.none));
  EXPECT_TRUE(sameBits(smooth.grid, smooth.none));
  const ThreeImages bubbles = renderThreeWays(bubblesScene(), 24);
  EXPECT_TRUE(sameBits(bubbles.bvh, bubbles.none));
  EXPECT_TRUE(sameBits(bubbles.grid, bubbles.none));
  EXPECT_FALSE(sameBits(smooth.none, renderThreeWays(teapotScene(), 24).none));
}

TEST(TeapotTests, aLargeFloorUnderTheTeapot) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: floor 10000: a second mesh of two triangles in the plane of the teapot's bottom,
  // facing up, with a look of its own
  const SceneSetup<LitScene> setup = teapotScene({.floor = 10000});
  const Geometries& g = setup.scene.geometries;
  ASSERT_EQ(g.meshes().size(), 2u);
  EXPECT_EQ(g.triangleCount(), 992u + 2);
  const TriangleMesh& floor = *g.meshes()[1].mesh;
  EXPECT_EQ(floor.corners(0)[0], Point(-10000, -39.8754, -10000));
  EXPECT_EQ(floor.corners(1)[2], Point(10000, -39.8754, -10000));
  EXPECT_EQ(floor.flatNormal(0), Vector(0, 1, 0));
  EXPECT_EQ(floor.flatNormal(1), Vector(0, 1, 0));
  EXPECT_NE(setup.scene.rowOf(0), setup.scene.rowOf(992));  // the teapot's, the floor's
  EXPECT_EQ(setup.scene.rowOf(992), setup.scene.rowOf(993));
  // TC02: the BVH's and the grid's images are the list's; the bottom row sees the floor (its
  // emission (20,20,20) at least), the top row the black background
  const ThreeImages t = renderThreeWays(setup, 24);
  EXPECT_TRUE(sameBits(t.bvh, t.none));
  EXPECT_TRUE(sameBits(t.grid, t.none));
  EXPECT_GE(t.none.pixel(0, 23).rgb().x, 20);
  EXPECT_EQ(t.none.pixel(0, 0), Color::BLACK);
  // =============== Boundary Values Tests ==================
  // TC11: floor 0: no floor, the course's scene
  EXPECT_EQ(teapotScene({.floor = 0}).scene.geometries.meshes().size(), 1u);
  // TC12: a negative floor is refused, naming it
  EXPECT_THAT([] { teapotScene({.floor = -1}); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("floor")));
}

}  // namespace
}  // namespace rt
