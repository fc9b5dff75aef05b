// Ambient-only rendering: the AmbientTracer, and the course's "base render test"
// (RenderTests.renderTwoColorTest) with its pixel colours checked in every quadrant.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "camera/AmbientLight.h"
#include "camera/Camera.h"
#include "camera/CourseScenes.h"
#include "camera/ImageWriter.h"
#include "camera/RayTracer.h"
#include "camera/Scene.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

const Color PINK(255, 191, 191);
const Color GREEN(75, 127, 90);

// ---------------------------------------------------------------------------------------------
// AmbientLight and AmbientTracer

TEST(AmbientLightTests, Intensity) {
  // TC01: Ia·kA with a scalar kA
  EXPECT_EQ(AmbientLight(Color(200, 100, 50), 0.5).intensity(), Color(100, 50, 25));
  // TC02: per-channel kA
  EXPECT_EQ(AmbientLight(Color(200, 100, 50), Double3(1, 0, 0.2)).intensity(), Color(200, 0, 10));
  // TC11: NONE is black
  EXPECT_EQ(AmbientLight::NONE.intensity(), Color::BLACK);
  // TC12: a negative kA is rejected
  EXPECT_THROW(AmbientLight(Color::WHITE, -0.1), std::invalid_argument);
}

TEST(AmbientTracerTests, HitAndMiss) {
  Scene scene;
  scene.background = Color(1, 2, 3);
  scene.ambientLight = AmbientLight(Color(100, 200, 40), 0.5);
  scene.geometries.add(Sphere(Point(0, 0, -10), 1));
  const AmbientTracer tracer(scene);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the ray hits the sphere -> Ia·kA
  EXPECT_EQ(tracer.traceRay(Ray(Point::ZERO, Vector(0, 0, -1))), Color(50, 100, 20));
  // TC02: the ray misses -> background
  EXPECT_EQ(tracer.traceRay(Ray(Point::ZERO, Vector(0, 1, 0))), Color(1, 2, 3));
  // =============== Boundary Values Tests ==================
  // TC11: the sphere is behind the ray -> background
  EXPECT_EQ(tracer.traceRay(Ray(Point::ZERO, Vector(0, 0, 1))), Color(1, 2, 3));
  // TC12: an empty scene -> background
  const Scene empty;
  EXPECT_EQ(AmbientTracer(empty).traceRay(Ray(Point::ZERO, Vector(0, 0, -1))), Color::BLACK);
  // TC13: a tangent ray (grazing the sphere at (0,1,-10)) counts as no hit
  EXPECT_EQ(tracer.traceRay(Ray(Point(0, 1, 0), Vector(0, 0, -1))), Color(1, 2, 3));
}

TEST(AmbientTracerTests, AcceleratorIsUsedInsteadOfTheSceneGeometries) {
  // TC03: the tracer intersects what it is given (a stand-in for a BVH)
  Scene scene;
  scene.background = Color::BLUE;
  scene.ambientLight = AmbientLight(Color::RED, 1);
  Geometries other;
  other.add(Plane(Point(0, 0, -5), Vector(0, 0, 1)));
  const AmbientTracer tracer(scene, &other);
  EXPECT_EQ(tracer.traceRay(Ray(Point::ZERO, Vector(0, 0, -1))), Color::RED);
}

// ---------------------------------------------------------------------------------------------
// The base render test

TEST(RenderTests, TwoColorSceneData) {
  // TC01: the course's data
  const SceneSetup<Scene> setup = twoColorScene();
  EXPECT_EQ(setup.scene.background, GREEN);
  EXPECT_EQ(setup.scene.ambientLight.intensity(), PINK);
  EXPECT_EQ(setup.scene.geometries.size(), 4u);
  const Camera camera = setup.camera.builder().build();
  EXPECT_EQ(camera.location(), Point::ZERO);
  EXPECT_EQ(camera.vTo(), Vector(0, 0, -1));
  EXPECT_EQ(camera.vUp(), Vector(0, 1, 0));
  EXPECT_DOUBLE_EQ(camera.vpDistance(), 100);
  EXPECT_DOUBLE_EQ(camera.vpWidth(), 500);
  EXPECT_DOUBLE_EQ(camera.vpHeight(), 500);
  EXPECT_EQ(camera.nX(), 1000);
  EXPECT_EQ(camera.nY(), 1000);
}

/// Renders the two-colour scene at 500x500 (the course's view plane, half its resolution), so
/// that one pixel is one unit of the view plane: pixel (j, i) looks through the point
/// (j - 249.5, 249.5 - i, -100), which is also the plane of all four shapes.
class BaseRenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    setup_.camera.nX = 500;
    setup_.camera.nY = 500;
    camera_ =
        std::make_unique<Camera>(setup_.camera.builder()
                                     .setRayTracer(std::make_shared<AmbientTracer>(setup_.scene))
                                     .setImageWriter(std::make_shared<PngImageWriter>())
                                     .build());
    camera_->renderImage();
  }
  const Color& at(int j, int i) const { return camera_->image().pixel(j, i); }

  SceneSetup<Scene> setup_ = twoColorScene();
  std::unique_ptr<Camera> camera_;
};

TEST_F(BaseRenderTest, ShapesArePinkOnGreen) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the sphere's centre, pixel (260,260) -> (10.5,-10.5)
  EXPECT_EQ(at(260, 260), PINK);
  // TC02: up-left triangle (-100,0),(0,100),(-100,100): (-79.5,79.5)
  EXPECT_EQ(at(170, 170), PINK);
  // TC03: down-left triangle (-100,0),(0,-100),(-100,-100): (-79.5,-80.5)
  EXPECT_EQ(at(170, 330), PINK);
  // TC04: down-right triangle (100,0),(0,-100),(100,-100): (80.5,-80.5)
  EXPECT_EQ(at(330, 330), PINK);
  // TC05: the empty up-right quadrant: (80.5,79.5)
  EXPECT_EQ(at(330, 170), GREEN);
  // TC06: between shapes: above the sphere (0.5,129.5), left of it beyond the triangles
  // (-149.5,0.5), and the image corner (-249.5,249.5)
  EXPECT_EQ(at(250, 120), GREEN);
  EXPECT_EQ(at(100, 249), GREEN);
  EXPECT_EQ(at(0, 0), GREEN);
  // TC07: below the up-left triangle's hypotenuse y = x + 100 (outside the triangle):
  // (-30.5,30.5) is 43.1 from the axis, inside the sphere's silhouette (57.7) -> pink;
  // (-60.5,20.5) is 63.9 from the axis, outside it -> green
  EXPECT_EQ(at(219, 219), PINK);
  EXPECT_EQ(at(189, 229), GREEN);

  // =============== Boundary Values Tests ==================
  // TC11: the sphere's silhouette (angular radius 30 degrees, radius 100·tan30 = 57.74 in the
  // view plane): along +x, (57.5,-0.5) is inside and (58.5,-0.5) outside
  EXPECT_EQ(at(307, 250), PINK);
  EXPECT_EQ(at(308, 250), GREEN);
  // TC12: the triangles' outer corners: (-99.5,99.5) inside, (-100.5,99.5) outside
  EXPECT_EQ(at(150, 150), PINK);
  EXPECT_EQ(at(149, 150), GREEN);
  // TC13: every pixel is one of the two colours
  int other = 0;
  for (int i = 0; i < 500; ++i)
    for (int j = 0; j < 500; ++j)
      if (!(at(j, i) == PINK) && !(at(j, i) == GREEN)) ++other;
  EXPECT_EQ(other, 0);
}

TEST_F(BaseRenderTest, GridAndFileOnTop) {
  // TC08: the course's grid every 100 pixels at 1000x1000 is every 50 pixels here
  camera_->printGrid(50, Color::YELLOW);
  const fs::path dir = fs::path("test-images") / "stage04";
  fs::create_directories(dir);
  const std::string path = (dir / "base render test.png").string();
  camera_->writeToImage(path);

  const Rgb8Image back = readPng(path);
  ASSERT_EQ(back.width, 500);
  ASSERT_EQ(back.height, 500);
  using Rgb = std::array<unsigned char, 3>;
  const Rgb pink{255, 191, 191}, green{75, 127, 90}, yellow{255, 255, 0};
  // grid lines over the background, the sphere and a triangle
  EXPECT_EQ(back.at(0, 0), yellow);
  EXPECT_EQ(back.at(450, 333), yellow);
  EXPECT_EQ(back.at(250, 260), yellow);  // column 250 through the sphere
  EXPECT_EQ(back.at(170, 150), yellow);  // row 150 through the up-left triangle
  // off the lines the render shows through
  EXPECT_EQ(back.at(260, 260), pink);
  EXPECT_EQ(back.at(170, 170), pink);
  EXPECT_EQ(back.at(170, 330), pink);
  EXPECT_EQ(back.at(330, 330), pink);
  EXPECT_EQ(back.at(330, 170), green);
  EXPECT_EQ(back.at(499, 499), green);
}

}  // namespace
}  // namespace rt
