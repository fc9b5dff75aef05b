// Cross-stage: the per-ray path allocates nothing. This executable links the allocation counter
// (support/AllocationCounter.h), which replaces the global operator new with one that counts
// calls, then traces rays through scenes that exercise every shape, triangle meshes flat and
// smooth, every light type, shadows with transparent blockers, reflection, refraction with an
// index of refraction, and the recursion limits — and requires the count not to move.
// AcceleratedNoAllocationTests.cpp adds the same through the BVH and the grid when mini project
// 2 is built.
#include <gtest/gtest.h>

#include "AllocationWhileTracing.h"
#include "MeshScene.h"
#include "camera/Camera.h"
#include "camera/CameraSpec.h"
#include "lighting/LitScene.h"
#include "reflections/CourseScenes.h"
#include "reflections/WhittedTracer.h"
#include "support/AllocationCounter.h"

namespace rt {
namespace {

/// Every shape and light type, a transparent refracting sphere with ior 1.5, a mirror.
LitScene everythingScene() {
  LitScene scene;
  scene.background = Color(5, 5, 5);
  scene.ambientLight = AmbientLight(Color::WHITE, 0.1);
  Material glass;
  glass.kD = Double3(0.1);
  glass.kS = Double3(0.5);
  glass.shininess = 50;
  glass.kT = Double3(0.7);
  glass.kR = Double3(0.2);
  glass.ior = 1.5;
  Material mirror;
  mirror.kR = Double3(0.9);
  Material matte;
  matte.kD = Double3(0.6);
  matte.kS = Double3(0.2);
  matte.shininess = 20;
  matte.kT = Double3(0.3);
  scene.add(Sphere(Point(0, 0, -50), 20), Color(10, 20, 30), glass);
  scene.add(Plane(Point(0, -30, 0), Vector(0, 1, 0)), Color(20, 20, 20), matte);
  scene.add(Triangle(Point(-100, -30, -120), Point(100, -30, -120), Point(0, 100, -120)),
            Color::BLACK, mirror);
  scene.add(
      Polygon({Point(30, -10, -20), Point(50, -10, -20), Point(50, 10, -20), Point(30, 10, -20)}),
      Color(30, 0, 0), matte);
  scene.add(Tube(5, Ray(Point(-40, 0, -60), Vector(0, 1, 0))), Color(0, 30, 0), matte);
  scene.add(Cylinder(8, Ray(Point(40, -30, -70), Vector(0, 1, 0.2)), 30), Color(0, 0, 30), glass);
  scene.addLight(DirectionalLight(Color(100, 100, 100), Vector(1, -1, -1)));
  scene.addLight(PointLight(Color(300, 300, 300), Point(0, 60, 0)).setKl(0.001).setKq(0.0001));
  scene.addLight(SpotLight(Color(300, 200, 100), Point(-50, 50, 20), Vector(1, -1, -1.5))
                     .setKl(0.001)
                     .setNarrowBeam(4));
  return scene;
}

// TC01: every shape and light, Whitted with shadows, reflection and Snell refraction.
TEST(NoAllocation, TC01_whittedTracerOverEveryShapeAndLight) {
  const LitScene scene = everythingScene();
  const WhittedTracer tracer(scene);
  const Camera camera = Camera::builder()
                            .setLocation(Point(0, 0, 100))
                            .setDirection(Point(0, 0, -50))
                            .setVpSize(150, 150)
                            .setVpDistance(100)
                            .setResolution(60, 60)
                            .build();
  EXPECT_EQ(test::allocationsWhileTracing(tracer, camera), 0);
}

// TC02: the course's reflection scenes (mirrors, transparent spheres) at a low resolution.
TEST(NoAllocation, TC02_courseReflectionScenes) {
  for (const CourseScene& entry : reflectionScenes()) {
    SceneSetup<LitScene> setup = entry.make();
    setup.camera.nX = 40;
    setup.camera.nY = 40;
    const WhittedTracer tracer(setup.scene);
    const Camera camera = setup.camera.builder().build();
    EXPECT_EQ(test::allocationsWhileTracing(tracer, camera), 0) << entry.name;
  }
}

// TC03: triangle meshes, smooth (the teapot) and flat (a mirror), among shapes: Whitted with
// shadows through the meshes, reflection and refraction, over the linear Geometries.
TEST(NoAllocation, TC03_whittedTracerOverMeshes) {
  const LitScene scene = test::meshScene();
  const WhittedTracer tracer(scene);
  const Camera camera = test::meshSceneCamera();
  EXPECT_EQ(test::allocationsWhileTracing(tracer, camera), 0);
  // The camera sees both meshes: the teapot (mesh 0) and the mirror (mesh 1)
  int teapot = 0, mirror = 0;
  for (int i = 0; i < camera.nY(); ++i)
    for (int j = 0; j < camera.nX(); ++j)
      if (const auto hit = scene.geometries.closestHit(camera.constructRay(40, 40, j, i));
          hit && !scene.geometries.primitives().isShape(hit->geometry))
        (scene.geometries.primitives().meshTriangle(hit->geometry).mesh == 0 ? teapot : mirror)++;
  EXPECT_GT(teapot, 200);
  EXPECT_GT(mirror, 200);
}

// TC11 (control): the counter does see an allocation on the same path when there is one — the
// course's findGeoIntersections builds a list — so the zeros above are not vacuous.
TEST(NoAllocation, TC11_counterSeesTheCourseListQuery) {
  const LitScene scene = everythingScene();
  std::size_t hits = 0;
  EXPECT_GT(
      testing::allocationsDuring([&] {
        hits =
            scene.geometries.findGeoIntersections(Ray(Point(0, 0, 100), Vector(0, 0, -1))).size();
      }),
      0);
  EXPECT_EQ(hits, 3u);  // the sphere twice, then the mirror triangle
}

}  // namespace
}  // namespace rt
