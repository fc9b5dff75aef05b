// The per-ray path allocates nothing: this test binary counts every call of the global operator
// new, and a Whitted render of the all-features scene (shadow rays, reflection, refraction,
// with and without an index of refraction) must not add to the count between the first and the
// last traceRay.

#include <gtest/gtest.h>

#include "camera/Camera.h"
#include "reflections/CourseScenes.h"
#include "reflections/WhittedTracer.h"
#include "shadows/ShadowTracer.h"
#include "support/AllocationCounter.h"

namespace rt {
namespace {

/// Traces a grid of n x n rays of the scene's camera and returns how many allocations happened.
long allocationsWhileTracing(const SceneSetup<LitScene>& s, const RayTracer& tracer, int n) {
  CameraSpec spec = s.camera;
  spec.nX = n;
  spec.nY = n;
  const Camera camera = spec.builder().build();
  double sink = 0;
  const long allocations = testing::allocationsDuring([&] {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) sink += tracer.traceRay(camera.constructRay(n, n, j, i)).r();
  });
  EXPECT_GT(sink, 0);
  return allocations;
}

TEST(NoAllocationTests, whittedTracer) {
  // TC01: the counter works: one call counts one (a direct call cannot be elided, unlike a
  // new-expression)
  EXPECT_EQ(1, testing::allocationsDuring([] { ::operator delete(::operator new(40)); }));
  // TC02: the all-features scene from both viewpoints, rendered block by block (sampler,
  // context, tracer, counts): no allocation per ray
  for (auto make : {&course::allFeaturesBelow, &course::allFeaturesAbove}) {
    const SceneSetup<LitScene> s = make();
    const WhittedTracer tracer(s.scene);
    EXPECT_EQ(0, allocationsWhileTracing(s, tracer, 60));
    CameraSpec spec = s.camera;
    spec.nX = spec.nY = 60;
    const Camera camera = spec.builder().build();
    Image image(60, 60);
    const CenterSampler sampler;
    RayCounts counts;
    EXPECT_EQ(0, testing::allocationsDuring([&] {
                counts = renderBlock({camera, tracer, sampler}, {0, 0, 60, 60}, image);
              }));
    EXPECT_GT(counts.secondary, 1000u);
  }
  // TC03: with an index of refraction (Snell, Fresnel): still none
  SceneSetup<LitScene> glass = course::twoSpheres();
  glass.scene.appearances[0].material.ior = 1.5;
  EXPECT_EQ(0, allocationsWhileTracing(glass, WhittedTracer(glass.scene), 60));
  // TC04: the shadow tracer alone
  EXPECT_EQ(0, allocationsWhileTracing(glass, ShadowTracer(glass.scene), 60));
}

}  // namespace
}  // namespace rt
