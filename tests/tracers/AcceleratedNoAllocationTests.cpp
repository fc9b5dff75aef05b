// Cross-stage, with mini project 2: the per-ray path through the BVH and the grid allocates
// nothing either, over shapes and triangle meshes (their triangles are the structures'
// primitives): the scenes of NoAllocationTests.cpp, traced by the Whitted tracer through each.
#include <gtest/gtest.h>

#include "AllocationWhileTracing.h"
#include "MeshScene.h"
#include "bvh/Bvh.h"
#include "grid/Grid.h"
#include "reflections/CourseScenes.h"
#include "reflections/WhittedTracer.h"

namespace rt {
namespace {

// TC04: the mesh scene through the BVH and through the grid.
TEST(NoAllocation, TC04_whittedTracerOverMeshesThroughTheBvhAndTheGrid) {
  const LitScene scene = test::meshScene();
  const Bvh bvh(scene.geometries);
  const Grid grid(scene.geometries);
  const Camera camera = test::meshSceneCamera();
  EXPECT_EQ(test::allocationsWhileTracing(WhittedTracer(scene, &bvh), camera), 0);
  EXPECT_EQ(test::allocationsWhileTracing(WhittedTracer(scene, &grid), camera), 0);
}

// TC05: the course's reflection scenes through the BVH and through the grid.
TEST(NoAllocation, TC05_courseReflectionScenesThroughTheBvhAndTheGrid) {
  for (const CourseScene& entry : reflectionScenes()) {
    SceneSetup<LitScene> setup = entry.make();
    setup.camera.nX = 40;
    setup.camera.nY = 40;
    const Bvh bvh(setup.scene.geometries);
    const Grid grid(setup.scene.geometries);
    const Camera camera = setup.camera.builder().build();
    EXPECT_EQ(test::allocationsWhileTracing(WhittedTracer(setup.scene, &bvh), camera), 0)
        << entry.name;
    EXPECT_EQ(test::allocationsWhileTracing(WhittedTracer(setup.scene, &grid), camera), 0)
        << entry.name;
  }
}

}  // namespace
}  // namespace rt
