// Cross-stage: the per-ray path allocates nothing. This executable replaces the global
// operator new with one that counts calls, then traces rays through scenes that exercise every
// shape, every light type, shadows with transparent blockers, reflection, refraction with an
// index of refraction, and the recursion limits — and requires the count not to move.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "camera/Camera.h"
#include "camera/CameraSpec.h"
#include "lighting/LitScene.h"
#include "reflections/CourseScenes.h"
#include "reflections/WhittedTracer.h"

namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

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
  scene.add(Polygon({Point(30, -10, -20), Point(50, -10, -20), Point(50, 10, -20),
                     Point(30, 10, -20)}),
            Color(30, 0, 0), matte);
  scene.add(Tube(5, Ray(Point(-40, 0, -60), Vector(0, 1, 0))), Color(0, 30, 0), matte);
  scene.add(Cylinder(8, Ray(Point(40, -30, -70), Vector(0, 1, 0.2)), 30), Color(0, 0, 30),
            glass);
  scene.addLight(DirectionalLight(Color(100, 100, 100), Vector(1, -1, -1)));
  scene.addLight(PointLight(Color(300, 300, 300), Point(0, 60, 0)).setKl(0.001).setKq(0.0001));
  scene.addLight(SpotLight(Color(300, 200, 100), Point(-50, 50, 20), Vector(1, -1, -1.5))
                     .setKl(0.001)
                     .setNarrowBeam(4));
  return scene;
}

long allocationsWhileTracing(const RayTracer& tracer, const Camera& camera) {
  const long before = allocations.load();
  Color sum;
  for (int i = 0; i < camera.nY(); ++i)
    for (int j = 0; j < camera.nX(); ++j)
      sum += tracer.traceRay(camera.constructRay(camera.nX(), camera.nY(), j, i));
  const long after = allocations.load();
  EXPECT_GT(sum.r() + sum.g() + sum.b(), 0);  // the rays did hit things
  return after - before;
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
  EXPECT_EQ(allocationsWhileTracing(tracer, camera), 0);
}

// TC02: the course's reflection scenes (mirrors, transparent spheres) at a low resolution.
TEST(NoAllocation, TC02_courseReflectionScenes) {
  for (const CourseScene& entry : reflectionScenes()) {
    SceneSetup<LitScene> setup = entry.make();
    setup.camera.nX = 40;
    setup.camera.nY = 40;
    const WhittedTracer tracer(setup.scene);
    const Camera camera = setup.camera.builder().build();
    EXPECT_EQ(allocationsWhileTracing(tracer, camera), 0) << entry.name;
  }
}

// TC11 (control): the counter does see an allocation on the same path when there is one — the
// course's findGeoIntersections builds a list — so the zeros above are not vacuous.
TEST(NoAllocation, TC11_counterSeesTheCourseListQuery) {
  const LitScene scene = everythingScene();
  const long before = allocations.load();
  const auto hits = scene.geometries.findGeoIntersections(Ray(Point(0, 0, 100), Vector(0, 0, -1)));
  EXPECT_GT(allocations.load() - before, 0);
  EXPECT_EQ(hits.size(), 3u);  // the sphere twice, then the mirror triangle
}

}  // namespace
}  // namespace rt
