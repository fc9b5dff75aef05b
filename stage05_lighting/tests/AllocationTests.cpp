// Stage 5: the per-ray path allocates nothing. The stage-5 test program links the allocation
// counter (stage01's tests/support), which counts every call of the global operator new; the
// tests count the allocations made while the tracer shades every pixel of every built-in scene
// of the stage.
#include <gtest/gtest.h>

#include <vector>

#include "camera/Camera.h"
#include "lighting/CourseScenes.h"
#include "lighting/LightSource.h"
#include "lighting/PhongTracer.h"
#include "support/AllocationCounter.h"

namespace {
std::vector<int>* volatile sink = nullptr;  // keeps the probe allocation from being elided
}  // namespace

namespace rt {
namespace {

TEST(AllocationTests, traceRayAllocatesNothing) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: every pixel of every scene of the stage (41 x 41 through the course view plane):
  // hits and misses, every light type, with and without ambient light
  for (const CourseScene& cs : lightingScenes()) {
    const SceneSetup<LitScene> setup = cs.make();
    CameraSpec spec = setup.camera;
    spec.nX = spec.nY = 41;
    const Camera camera = spec.builder().build();
    const PhongTracer tracer(setup.scene);
    std::vector<Ray> rays;
    rays.reserve(41 * 41);
    for (int i = 0; i < 41; ++i)
      for (int j = 0; j < 41; ++j) rays.push_back(camera.constructRay(41, 41, j, i));

    double sum = 0;  // used, so that the calls cannot be optimised away
    const long during = testing::allocationsDuring([&] {
      for (const Ray& ray : rays) {
        const Color c = tracer.traceRay(ray);
        sum += c.r() + c.g() + c.b();
      }
    });
    EXPECT_EQ(during, 0) << cs.name;
    EXPECT_GT(sum, 0) << cs.name << ": the rays saw something lit (they were traced)";
  }

  // =============== Boundary Values Tests ==================
  // TC11: illuminate at the light's own position (the no-sample case) allocates nothing either
  const LightSource spot = SpotLight(Color::WHITE, Point::ZERO, Vector(0, 0, -1)).setNarrowBeam(3);
  bool none = false, some = false;
  EXPECT_EQ(0, testing::allocationsDuring([&] {
              none = !illuminate(spot, Point::ZERO).has_value();
              some = illuminate(spot, Point(0, 0, -1)).has_value();
            }));
  EXPECT_TRUE(none && some);
}

TEST(AllocationTests, counterWorks) {
  // TC01: the counter sees a heap allocation (otherwise the test above could not fail)
  EXPECT_GE(testing::allocationsDuring([] { sink = new std::vector<int>(100); }), 2);
  delete sink;
}

}  // namespace
}  // namespace rt
