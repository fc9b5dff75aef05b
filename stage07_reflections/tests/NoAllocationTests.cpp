// The per-ray path allocates nothing: this test binary counts every call of the global operator
// new, and a Whitted render of the all-features scene (shadow rays, reflection, refraction,
// with and without an index of refraction) must not add to the count between the first and the
// last traceRay.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "camera/Camera.h"
#include "reflections/CourseScenes.h"
#include "reflections/TraceStats.h"
#include "reflections/WhittedTracer.h"
#include "shadows/ShadowTracer.h"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// GCC takes free() in a replacement operator delete for a mismatch with operator new; here the
// pair is malloc/free by construction.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

void* operator new(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return ::operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { ::operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { ::operator delete(p); }

namespace rt {
namespace {

/// Traces a grid of n x n rays of the scene's camera and returns how many allocations happened.
long allocationsWhileTracing(const SceneSetup<LitScene>& s, const RayTracer& tracer, int n) {
  CameraSpec spec = s.camera;
  spec.nX = n;
  spec.nY = n;
  const Camera camera = spec.builder().build();
  double sink = 0;
  const long before = allocations.load();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) sink += tracer.traceRay(camera.constructRay(n, n, j, i)).r();
  const long after = allocations.load();
  EXPECT_GT(sink, 0);
  return after - before;
}

TEST(NoAllocationTests, whittedTracer) {
  // TC01: the counter works: one call counts one (a direct call cannot be elided, unlike a
  // new-expression)
  const long before = allocations.load();
  ::operator delete(::operator new(40));
  EXPECT_EQ(1, allocations.load() - before);
  // TC02: the all-features scene from both viewpoints: no allocation per ray
  for (auto make : {&course::allFeaturesBelow, &course::allFeaturesAbove}) {
    const SceneSetup<LitScene> s = make();
    WhittedTracer tracer(s.scene);
    TraceStats stats;
    tracer.setStats(&stats);
    EXPECT_EQ(0, allocationsWhileTracing(s, tracer, 60));
    EXPECT_GT(stats.secondaryRays.load(), 1000u);
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
