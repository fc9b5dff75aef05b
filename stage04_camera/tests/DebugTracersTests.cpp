// Stage 4's debugging views (camera/DebugTracers.h) on hand-computed rays, and the scene they are
// shown on (camera/ShapesScene.h).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "camera/Camera.h"
#include "camera/DebugTracers.h"
#include "camera/RenderBlock.h"
#include "camera/ShapesScene.h"
#include "support/AllocationCounter.h"

namespace rt {
namespace {

const Color BACKGROUND(1, 2, 3);

/// Every channel exactly as given.
void expectColor(const Color& actual, double r, double g, double b) {
  EXPECT_EQ(actual.r(), r);
  EXPECT_EQ(actual.g(), g);
  EXPECT_EQ(actual.b(), b);
}

/// Every channel within 4 ulps (a normalised vector's components are rounded).
void expectNearColor(const Color& actual, double r, double g, double b) {
  EXPECT_DOUBLE_EQ(actual.r(), r);
  EXPECT_DOUBLE_EQ(actual.g(), g);
  EXPECT_DOUBLE_EQ(actual.b(), b);
}

Scene sceneOf(std::initializer_list<Geometry> shapes) {
  Scene scene;
  scene.background = BACKGROUND;
  for (const Geometry& g : shapes) scene.geometries.add(g);
  return scene;
}

const Ray ALONG_MINUS_Z(Point::ZERO, Vector(0, 0, -1));

// ---------------------------------------------------------------------------------------------
// directionColor and the rays tracer

TEST(DirectionColorTests, normalMapEncoding) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: +Z is (0.5, 0.5, 1)·255
  expectColor(directionColor(Vector(0, 0, 1)), 127.5, 127.5, 255);
  // TC02: -X is (0, 0.5, 0.5)·255
  expectColor(directionColor(Vector(-1, 0, 0)), 0, 127.5, 127.5);
  // TC03: a diagonal, (1/√2·0.5 + 0.5)·255 in two channels
  const double c = (std::sqrt(0.5) * 0.5 + 0.5) * 255;
  expectNearColor(directionColor(Vector(1, 1, 0).normalized()), c, c, 127.5);
  // =============== Boundary Values Tests ==================
  // TC11: a component a rounding below -1 gives 0, never a negative channel
  expectColor(directionColor(Vector::unchecked(Double3(-1.0000000000000002, 0, 0))), 0, 127.5,
              127.5);
}

TEST(RaysTracerTests, theRaysDirection) {
  const Scene scene = sceneOf({Sphere(Point(0, 0, -10), 1)});
  const RaysTracer tracer(scene);
  // ============ Equivalence Partitions Tests ==============
  // TC01: along -Z, through a sphere: the direction, not the sphere
  expectColor(tracer.traceRay(ALONG_MINUS_Z), 127.5, 127.5, 0);
  // TC02: along +X, hitting nothing: the direction, not the background
  expectColor(tracer.traceRay(Ray(Point(1, 2, 3), Vector(1, 0, 0))), 255, 127.5, 127.5);
  // TC03: the direction is the ray's unit one (-3·Y stored as -Y)
  expectColor(tracer.traceRay(Ray(Point::ZERO, Vector(0, -3, 0))), 127.5, 0, 127.5);
  // TC04: a camera's central ray is its vTo; the top-left pixel's leans left (less red) and up
  // (more green)
  const Camera camera = Camera::builder()
                            .setLocation(Point::ZERO)
                            .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
                            .setVpSize(3, 3)
                            .setVpDistance(1)
                            .setResolution(3, 3)
                            .build();
  expectColor(tracer.traceRay(camera.constructRay(3, 3, 1, 1)), 127.5, 127.5, 0);
  const double s = 1 / std::sqrt(3.0);  // the direction (-1, 1, -1)/√3
  expectNearColor(tracer.traceRay(camera.constructRay(3, 3, 0, 0)), (0.5 - s * 0.5) * 255,
                  (s * 0.5 + 0.5) * 255, (0.5 - s * 0.5) * 255);
}

// ---------------------------------------------------------------------------------------------
// The normals tracer

TEST(NormalsTracerTests, theNearestHitsOutwardNormal) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a sphere hit head-on at (0,0,-9): normal (0,0,1)
  const Scene sphere = sceneOf({Sphere(Point(0, 0, -10), 1)});
  expectColor(NormalsTracer(sphere).traceRay(ALONG_MINUS_Z), 127.5, 127.5, 255);
  // TC02: a sphere of radius 5 hit off-centre at (3,0,-6): normal (3,0,4)/5 = (0.6, 0, 0.8)
  const Scene sphere5 = sceneOf({Sphere(Point(0, 0, -10), 5)});
  expectNearColor(NormalsTracer(sphere5).traceRay(Ray(Point(3, 0, 0), Vector(0, 0, -1))), 0.8 * 255,
                  127.5, 0.9 * 255);
  // TC03: a floor (normal +Y) seen from above: one colour, the same at every point
  const Scene floor = sceneOf({Plane(Point(0, -5, 0), Vector(0, 1, 0))});
  const NormalsTracer floorTracer(floor);
  expectColor(floorTracer.traceRay(Ray(Point::ZERO, Vector(0, -1, -1))), 127.5, 255, 127.5);
  expectColor(floorTracer.traceRay(Ray(Point(7, 3, 1), Vector(2, -1, 5))), 127.5, 255, 127.5);
  // TC04: a flat shape shows its winding's normal, also facing away from the camera
  const Scene away = sceneOf({Plane(Point(0, 0, -5), Vector(0, 0, -1))});
  expectColor(NormalsTracer(away).traceRay(ALONG_MINUS_Z), 127.5, 127.5, 0);
  // TC05: the nearest hit wins: the sphere in front of that plane, the plane beside it
  const Scene both =
      sceneOf({Plane(Point(0, 0, -20), Vector(0, 0, -1)), Sphere(Point(0, 0, -10), 1)});
  const NormalsTracer bothTracer(both);
  expectColor(bothTracer.traceRay(ALONG_MINUS_Z), 127.5, 127.5, 255);
  expectColor(bothTracer.traceRay(Ray(Point(0, 5, 0), Vector(0, 0, -1))), 127.5, 127.5, 0);
  // TC06: a tube's side hit from -X at (-1,0,-5): normal (-1,0,0)
  const Scene tube = sceneOf({Tube(1, Ray(Point(0, 0, -5), Vector(0, 1, 0)))});
  expectColor(NormalsTracer(tube).traceRay(Ray(Point(-10, 0, -5), Vector(1, 0, 0))), 0, 127.5,
              127.5);
  // TC07: a cylinder's top cap (axis +Y from y = -10, height 2) hit from above: normal +Y
  const Scene cylinder = sceneOf({Cylinder(1, Ray(Point(0, -10, -5), Vector(0, 1, 0)), 2)});
  expectColor(NormalsTracer(cylinder).traceRay(Ray(Point(0, 0, -5), Vector(0, -1, 0))), 127.5, 255,
              127.5);
  // =============== Boundary Values Tests ==================
  // TC11: a miss, and a shape behind the ray: the background
  expectColor(NormalsTracer(sphere).traceRay(Ray(Point::ZERO, Vector(0, 1, 0))), 1, 2, 3);
  expectColor(NormalsTracer(sphere).traceRay(Ray(Point::ZERO, Vector(0, 0, 1))), 1, 2, 3);
  // TC12: a tangent ray (grazing the sphere at (0,1,-10)) is no hit
  expectColor(NormalsTracer(sphere).traceRay(Ray(Point(0, 1, 0), Vector(0, 0, -1))), 1, 2, 3);
  // TC13: an empty scene
  const Scene empty = sceneOf({});
  expectColor(NormalsTracer(empty).traceRay(ALONG_MINUS_Z), 1, 2, 3);
}

// ---------------------------------------------------------------------------------------------
// The hits tracer

TEST(HitsTracerTests, paletteOfCounts) {
  const Scene scene = sceneOf({});
  const HitsTracer tracer(scene);
  // TC01: 1, 2, 3 hits: blue, green, yellow
  EXPECT_EQ(tracer.colorOf(1), Color(40, 90, 230));
  EXPECT_EQ(tracer.colorOf(2), Color(40, 190, 70));
  EXPECT_EQ(tracer.colorOf(3), Color(250, 210, 40));
  // TC11: none: the background; 4 and more: red
  EXPECT_EQ(tracer.colorOf(0), BACKGROUND);
  EXPECT_EQ(tracer.colorOf(4), Color(230, 40, 40));
  EXPECT_EQ(tracer.colorOf(1000), Color(230, 40, 40));
  // TC12: the four colours differ
  std::set<std::array<std::uint8_t, 3>> distinct;
  for (const Color& c : HitsTracer::PALETTE) distinct.insert(c.toRgb8());
  EXPECT_EQ(distinct.size(), 4u);
}

TEST(HitsTracerTests, everyCrossingCounts) {
  const auto hits = [](std::initializer_list<Geometry> shapes, const Ray& ray) {
    const Scene scene = sceneOf(shapes);
    return HitsTracer(scene).traceRay(ray);
  };
  const Color& one = HitsTracer::PALETTE[0];
  const Color& two = HitsTracer::PALETTE[1];
  const Color& three = HitsTracer::PALETTE[2];
  const Color& fourOrMore = HitsTracer::PALETTE[3];
  const Sphere sphere(Point(0, 0, -10), 1);
  const Plane behind(Point(0, 0, -20), Vector(0, 0, 1));
  // ============ Equivalence Partitions Tests ==============
  // TC01: a sphere through its centre: its two roots, t = 9 and 11
  EXPECT_EQ(hits({sphere}, ALONG_MINUS_Z), two);
  // TC02: a sphere and a plane behind it: 3
  EXPECT_EQ(hits({sphere, behind}, ALONG_MINUS_Z), three);
  // TC03: a plane, a triangle, a polygon alone: 1 each
  EXPECT_EQ(hits({behind}, ALONG_MINUS_Z), one);
  EXPECT_EQ(hits({Triangle(Point(-1, -1, -5), Point(1, -1, -5), Point(0, 1, -5))}, ALONG_MINUS_Z),
            one);
  EXPECT_EQ(hits({Polygon{Point(-1, -1, -5), Point(1, -1, -5), Point(1, 1, -5), Point(-1, 1, -5)}},
                 ALONG_MINUS_Z),
            one);
  // TC04: a tube crossed across its axis: 2
  EXPECT_EQ(hits({Tube(1, Ray(Point(0, 0, -5), Vector(0, 1, 0)))}, ALONG_MINUS_Z), two);
  // TC05: a cylinder through both caps (along its axis), and in through the top cap at
  // (0.5,0,-8) and out through the side at (1,0,-9): 2
  const Cylinder cylinder(1, Ray(Point(0, 0, -10), Vector(0, 0, 1)), 2);
  EXPECT_EQ(hits({cylinder}, ALONG_MINUS_Z), two);
  EXPECT_EQ(hits({cylinder}, Ray(Point(-3.5, 0, 0), Vector(0.5, 0, -1))), two);
  // TC06: two spheres and the plane in a row: 5, shown as 4 or more
  EXPECT_EQ(hits({sphere, Sphere(Point(0, 0, -15), 1), behind}, ALONG_MINUS_Z), fourOrMore);
  // TC07: a ray starting inside the sphere: only the way out
  EXPECT_EQ(hits({sphere}, Ray(Point(0, 0, -10), Vector(0, 0, -1))), one);
  // =============== Boundary Values Tests ==================
  // TC11: a miss, and a sphere behind the ray: the background
  EXPECT_EQ(hits({sphere}, Ray(Point::ZERO, Vector(0, 1, 0))), BACKGROUND);
  EXPECT_EQ(hits({sphere}, Ray(Point::ZERO, Vector(0, 0, 1))), BACKGROUND);
  // TC12: a tangent ray is no hit
  EXPECT_EQ(hits({sphere}, Ray(Point(0, 1, 0), Vector(0, 0, -1))), BACKGROUND);
  // TC13: a ray starting on the plane does not hit it there
  EXPECT_EQ(hits({behind}, Ray(Point(0, 0, -20), Vector(0, 1, -1))), BACKGROUND);
}

TEST(HitsTracerTests, countsWhatFindIntersectionsReturns) {
  // TC01: on every ray of a 40 x 40 camera over the shapes scene, the colour is that of the
  // course's findGeoIntersections count
  const SceneSetup<Scene> setup = shapesScene();
  const HitsTracer tracer(setup.scene);
  const Camera camera = setup.camera.builder().setResolution(40, 40).build();
  std::set<std::size_t> seen;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const Ray ray = camera.constructRay(40, 40, j, i);
      const std::size_t count = setup.scene.geometries.findGeoIntersections(ray).size();
      seen.insert(count);
      ASSERT_EQ(tracer.traceRay(ray), tracer.colorOf(count)) << "pixel " << j << "," << i;
    }
  // TC02: the scene shows every count, 0 to 4
  EXPECT_EQ(seen, (std::set<std::size_t>{0, 1, 2, 3, 4}));
  // TC03: the query is counted: one test per shape
  RayCounts counts;
  SampleContext ctx(0, 0, 0, 0, counts);
  (void)tracer.traceRay(ALONG_MINUS_Z, ctx);
  EXPECT_EQ(counts.queries.shapeTests, setup.scene.geometries.size());
}

// ---------------------------------------------------------------------------------------------
// No allocation, and the scene

TEST(DebugTracersTests, allocateNothing) {
  // TC01: a 16 x 16 block of the shapes scene (every kind of shape) by each debugging view
  const SceneSetup<Scene> setup = shapesScene();
  const Camera camera = setup.camera.builder().setResolution(16, 16).build();
  const CenterSampler sampler(0);
  const RaysTracer rays(setup.scene);
  const NormalsTracer normals(setup.scene);
  const HitsTracer hits(setup.scene);
  for (const RayTracer* tracer : std::initializer_list<const RayTracer*>{&rays, &normals, &hits}) {
    Image image(16, 16);
    EXPECT_EQ(0, testing::allocationsDuring([&] {
                renderBlock({camera, *tracer, sampler}, {0, 0, 16, 16}, image);
              }));
  }
}

TEST(ShapesSceneTests, oneOfEachShapeClearlyVisible) {
  const SceneSetup<Scene> setup = shapesScene();
  const Geometries& shapes = setup.scene.geometries;
  // TC01: the six shapes of stage 2, one each, in the documented order
  ASSERT_EQ(shapes.size(), 6u);
  const std::vector<std::string> kinds{"plane",    "sphere",  "cylinder",
                                       "triangle", "polygon", "tube"};
  for (std::uint32_t i = 0; i < 6; ++i) EXPECT_EQ(shapeName(shapes[i]), kinds[i]);
  // TC02: each is the nearest shape on at least 2% of a 100 x 100 image, the background too;
  // the tube is seen on both halves (it crosses the image)
  const int n = 100;
  const Camera camera = setup.camera.builder().setResolution(n, n).build();
  std::array<int, 7> pixels{};  // per shape, then the background
  std::array<int, 2> tubeHalves{};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::optional<Hit> hit = shapes.closestHit(camera.constructRay(n, n, j, i));
      ++pixels[hit ? hit->geometry : 6];
      if (hit && hit->geometry == 5) ++tubeHalves[j < n / 2 ? 0 : 1];
    }
  for (std::size_t k = 0; k < pixels.size(); ++k)
    EXPECT_GE(pixels[k], n * n / 50) << (k < 6 ? kinds[k] : std::string("background"));
  EXPECT_GT(tubeHalves[0], 0);
  EXPECT_GT(tubeHalves[1], 0);
  // TC03: the camera's own image is 500 x 500
  EXPECT_EQ(setup.camera.nX, 500);
  EXPECT_EQ(setup.camera.nY, 500);
}

}  // namespace
}  // namespace rt
