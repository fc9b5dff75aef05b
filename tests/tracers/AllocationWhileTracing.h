#pragma once
// The no-allocation tests' measure: the allocations made while a tracer traces the ray of every
// pixel of a camera once (making the ray included).

#include <gtest/gtest.h>

#include "camera/Camera.h"
#include "support/AllocationCounter.h"

namespace rt::test {

inline long allocationsWhileTracing(const RayTracer& tracer, const Camera& camera) {
  Color sum;
  const long allocations = testing::allocationsDuring([&] {
    for (int i = 0; i < camera.nY(); ++i)
      for (int j = 0; j < camera.nX(); ++j)
        sum += tracer.traceRay(camera.constructRay(camera.nX(), camera.nY(), j, i));
  });
  EXPECT_GT(sum.r() + sum.g() + sum.b(), 0);  // the rays did hit things
  return allocations;
}

}  // namespace rt::test
