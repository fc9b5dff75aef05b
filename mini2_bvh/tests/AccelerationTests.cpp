// The acceleration structures by name (render.accel, --accel, the benchmark rows).
#include "bvh/Acceleration.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "bvh/Bvh.h"
#include "bvh/Cbr.h"
#include "bvh/WideBvh.h"
#include "geometries/Sphere.h"
#include "grid/Grid.h"

namespace rt {
namespace {

TEST(AccelerationTests, eachNameBuildsItsStructure) {
  Geometries shapes;
  shapes.add(Sphere(Point(0, 0, -5), 1));
  shapes.add(Sphere(Point(3, 0, -5), 1));
  // TC01: the names, in the order the scene format documents them
  EXPECT_EQ(ACCELERATION_NAMES.size(), 5u);
  EXPECT_EQ(ACCELERATION_NAMES[0], "none");
  EXPECT_EQ(ACCELERATION_NAMES[1], "cbr");
  EXPECT_EQ(ACCELERATION_NAMES[2], "bvh");
  EXPECT_EQ(ACCELERATION_NAMES[3], "bvh4");
  EXPECT_EQ(ACCELERATION_NAMES[4], "grid");
  EXPECT_EQ(DEFAULT_ACCELERATION, "bvh4");
  // TC02: "none" is the scene's own list: no structure
  EXPECT_EQ(makeAcceleration("none", shapes), nullptr);
  // TC03: "cbr", "bvh", "bvh4" and "grid" build theirs, which find the same nearest hit as the
  // list
  const auto cbr = makeAcceleration("cbr", shapes);
  const auto bvh = makeAcceleration("bvh", shapes);
  const auto wide = makeAcceleration("bvh4", shapes);
  const auto grid = makeAcceleration("grid", shapes);
  ASSERT_NE(dynamic_cast<const Cbr*>(cbr.get()), nullptr);
  ASSERT_NE(dynamic_cast<const Bvh*>(bvh.get()), nullptr);
  ASSERT_NE(dynamic_cast<const WideBvh*>(wide.get()), nullptr);
  ASSERT_NE(dynamic_cast<const Grid*>(grid.get()), nullptr);
  const Ray ray(Point(3, 0, 0), Vector(0, 0, -1));
  for (const auto* structure : {cbr.get(), bvh.get(), wide.get(), grid.get()}) {
    const auto hit = structure->closestHit(ray);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->geometry, 1u);
    EXPECT_EQ(hit->t, 4.0);
  }
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
                                           std::string(name) +
                                           "' (known: none, cbr, bvh, bvh4, grid)");
    }
  }
  for (std::string_view name : ACCELERATION_NAMES) EXPECT_TRUE(isAccelerationName(name));
}

}  // namespace
}  // namespace rt
