// Camera-geometry integration (the Java course's camera stage): a 3x3 view plane of 3x3 pixels at
// distance 1; the intersections of the 9 pixel rays with one shape are counted with
// Geometries::findIntersections and compared with the course's counts.

#include <gtest/gtest.h>

#include <cstddef>

#include "camera/Camera.h"
#include "intersections/Geometries.h"

namespace rt {
namespace {

/// The number of intersections of the 9 rays of a 3x3 camera at location with shape.
std::size_t countIntersections(const Point& location, const Geometry& shape) {
  const Camera camera = Camera::builder()
                            .setLocation(location)
                            .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
                            .setVpSize(3, 3)
                            .setVpDistance(1)
                            .setResolution(3, 3)
                            .build();
  const Geometries geometries{shape};
  std::size_t count = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      count += geometries.findIntersections(camera.constructRay(3, 3, j, i)).size();
  return count;
}

const Point ORIGIN = Point::ZERO;
const Point HALF_FORWARD(0, 0, 0.5);

TEST(CameraIntegrationTests, Sphere) {
  // TC01: small sphere in front, only the centre ray crosses it (twice)
  EXPECT_EQ(countIntersections(ORIGIN, Sphere(Point(0, 0, -3), 1)), 2u);
  // TC02: large sphere in front, every ray crosses it twice
  EXPECT_EQ(countIntersections(HALF_FORWARD, Sphere(Point(0, 0, -2.5), 2.5)), 18u);
  // TC03: medium sphere, the centre and the four side rays cross it twice, corners miss
  EXPECT_EQ(countIntersections(HALF_FORWARD, Sphere(Point(0, 0, -2), 2)), 10u);
  // TC04: the camera is inside the sphere, every ray leaves it once
  EXPECT_EQ(countIntersections(HALF_FORWARD, Sphere(Point(0, 0, -2), 4)), 9u);
  // TC05: the sphere is behind the camera
  EXPECT_EQ(countIntersections(ORIGIN, Sphere(Point(0, 0, 1), 0.5)), 0u);
}

TEST(CameraIntegrationTests, Plane) {
  // TC01: plane parallel to the view plane
  EXPECT_EQ(countIntersections(ORIGIN, Plane(Point(0, 0, -3), Vector(0, 0, 1))), 9u);
  // TC02: plane slightly tilted, still crossed by every ray
  EXPECT_EQ(countIntersections(ORIGIN, Plane(Point(0, 0, -2.5), Vector(0, -0.5, 1))), 9u);
  // TC03: plane steeply tilted, the bottom row's rays are parallel to it
  EXPECT_EQ(countIntersections(ORIGIN, Plane(Point(0, 0, -3), Vector(0, -1, 1))), 6u);
}

TEST(CameraIntegrationTests, Triangle) {
  // TC01: small triangle, only the centre ray
  EXPECT_EQ(
      countIntersections(ORIGIN, Triangle(Point(0, 1, -2), Point(1, -1, -2), Point(-1, -1, -2))),
      1u);
  // TC02: tall triangle, the centre ray and the one above it
  EXPECT_EQ(
      countIntersections(ORIGIN, Triangle(Point(0, 20, -2), Point(1, -1, -2), Point(-1, -1, -2))),
      2u);
}

}  // namespace
}  // namespace rt
