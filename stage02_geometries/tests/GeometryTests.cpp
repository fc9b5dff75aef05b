// Stage 2: the closed set of shapes as one value type: normalAt and shapeName visit every kind.
#include <gtest/gtest.h>

#include <string>

#include "geometries/Geometry.h"

#include "ExpectVector.h"

namespace rt {
namespace {

using test::expectVector;
using test::kZAxis;

TEST(GeometryTests, normalAtDispatchesToEveryShape) {
  // TC01: sphere
  expectVector(normalAt(Geometry(Sphere(Point(0, 0, 0), 2)), Point(0, 2, 0)), 0, 1, 0);
  // TC02: plane
  expectVector(normalAt(Geometry(Plane(Point(0, 0, 0), Vector(0, 0, 3))), Point(4, 4, 0)), 0, 0,
               1);
  // TC03: triangle
  expectVector(normalAt(Geometry(Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0))),
                        Point(0.2, 0.2, 0)),
               0, 0, 1);
  // TC04: polygon
  expectVector(
      normalAt(Geometry(Polygon({Point(0, 0, 0), Point(0, 1, 0), Point(1, 1, 0), Point(1, 0, 0)})),
               Point(0.5, 0.5, 0)),
      0, 0, -1);
  // TC05: tube
  expectVector(normalAt(Geometry(Tube(1, kZAxis)), Point(-1, 0, 7)), -1, 0, 0);
  // TC06: cylinder (top base)
  expectVector(normalAt(Geometry(Cylinder(1, kZAxis, 3)), Point(0.1, 0.2, 3)), 0, 0, 1);
}

TEST(GeometryTests, shapeName) {
  // TC01: the course's lower-case name of each kind
  EXPECT_EQ(std::string(shapeName(Geometry(Sphere(Point(0, 0, 0), 1)))), "sphere");
  EXPECT_EQ(std::string(shapeName(Geometry(Plane(Point(0, 0, 0), Vector(0, 0, 1))))), "plane");
  EXPECT_EQ(std::string(shapeName(
                Geometry(Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0))))),
            "triangle");
  EXPECT_EQ(std::string(shapeName(
                Geometry(Polygon({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)})))),
            "polygon");
  EXPECT_EQ(std::string(shapeName(Geometry(Tube(1, kZAxis)))), "tube");
  EXPECT_EQ(std::string(shapeName(Geometry(Cylinder(1, kZAxis, 1)))), "cylinder");
}

}  // namespace
}  // namespace rt
