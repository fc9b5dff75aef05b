// The acceleration structures by name (render.accel, --accel, the benchmark rows).
#include "bvh/Acceleration.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "bvh/Bvh.h"
#include "bvh/Cbr.h"
#include "geometries/Sphere.h"
#include "grid/Grid.h"

namespace rt {
namespace {

TEST(AccelerationTests, eachNameBuildsItsStructure) {
  Geometries shapes;
  shapes.add(Sphere(Point(0, 0, -5), 1));
  shapes.add(Sphere(Point(3, 0, -5), 1));
  // TC01: the names, in the order the scene format documents them
  EXPECT_EQ(ACCELERATION_NAMES.size(), 4u);
  EXPECT_EQ(ACCELERATION_NAMES[0], "none");
  EXPECT_EQ(ACCELERATION_NAMES[1], "cbr");
  EXPECT_EQ(ACCELERATION_NAMES[2], "bvh");
  EXPECT_EQ(ACCELERATION_NAMES[3], "grid");
  // TC02: "none" is the scene's own list: no structure
  EXPECT_EQ(makeAcceleration("none", shapes), nullptr);
  // TC03: "cbr", "bvh" and "grid" build theirs, which find the same nearest hit as the list
  const auto cbr = makeAcceleration("cbr", shapes);
  const auto bvh = makeAcceleration("bvh", shapes);
  const auto grid = makeAcceleration("grid", shapes);
  ASSERT_NE(dynamic_cast<const Cbr*>(cbr.get()), nullptr);
  ASSERT_NE(dynamic_cast<const Bvh*>(bvh.get()), nullptr);
  ASSERT_NE(dynamic_cast<const Grid*>(grid.get()), nullptr);
  const Ray ray(Point(3, 0, 0), Vector(0, 0, -1));
  const auto viaCbr = cbr->closestHit(ray);
  const auto viaBvh = bvh->closestHit(ray);
  const auto viaGrid = grid->closestHit(ray);
  ASSERT_TRUE(viaCbr && viaBvh && viaGrid);
  EXPECT_EQ(viaCbr->geometry, 1u);
  EXPECT_EQ(viaBvh->geometry, 1u);
  EXPECT_EQ(viaGrid->geometry, 1u);
  EXPECT_EQ(viaCbr->t, 4.0);
  EXPECT_EQ(viaBvh->t, 4.0);
  EXPECT_EQ(viaGrid->t, 4.0);
}

TEST(AccelerationTests, unknownNamesAreRefusedByName) {
  const Geometries shapes;
  // TC01: a name that is not one: refused, with the known ones; case matters ("BVH" is not one)
  for (const char* name : {"octree", "BVH", ""}) {
    EXPECT_FALSE(isAccelerationName(name)) << name;
    try {
      (void)makeAcceleration(name, shapes);
      ADD_FAILURE() << "accepted '" << name << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "makeAcceleration: unknown acceleration '" +
                                           std::string(name) + "' (known: none, cbr, bvh, grid)");
    }
  }
  for (std::string_view name : ACCELERATION_NAMES) EXPECT_TRUE(isAccelerationName(name));
}

}  // namespace
}  // namespace rt
