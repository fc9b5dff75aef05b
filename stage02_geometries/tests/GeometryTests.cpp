// Stage 2: the closed set of shapes as one value type: normalAt and shapeName visit every kind.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

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
  expectVector(normalAt(Geometry(Plane(Point(0, 0, 0), Vector(0, 0, 3))), Point(4, 4, 0)), 0, 0, 1);
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

TEST(GeometryTests, hitNormalIsNormalAtWithoutThrowing) {
  const Vector fallback(0, 0, -1);
  // ============ Equivalence Partitions Tests ==============
  // TC01: on the surface of every kind, the same vector as normalAt, bit for bit
  const std::pair<Geometry, Point> onSurface[] = {
      {Sphere(Point(1, 2, 3), 2), Point(1 + 2 / std::sqrt(3.0), 2 + 2 / std::sqrt(3.0), 3)},
      {Plane(Point(0, 0, 0), Vector(0, 1, 3)), Point(0, 0, 0)},
      {Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)), Point(0.2, 0.2, 0)},
      {Polygon({Point(0, 0, 0), Point(0, 1, 0), Point(1, 1, 0), Point(1, 0, 0)}),
       Point(0.5, 0.5, 0)},
      {Tube(1, kZAxis), Point(0.6, 0.8, 7)},
      {Cylinder(1, kZAxis, 3), Point(0.6, -0.8, 1)},
      {Cylinder(1, kZAxis, 3), Point(0.1, 0.2, 0)}};
  for (const auto& [shape, p] : onSurface) {
    const Vector expected = normalAt(shape, p);
    const Vector got = hitNormal(shape, p, fallback);
    EXPECT_EQ(expected.x(), got.x()) << shapeName(shape);
    EXPECT_EQ(expected.y(), got.y()) << shapeName(shape);
    EXPECT_EQ(expected.z(), got.z()) << shapeName(shape);
  }
  // =============== Boundary Values Tests ==================
  // TC11: at a sphere's centre normalAt throws; hitNormal gives the fallback
  const Geometry sphere = Sphere(Point(1, 2, 3), 2);
  EXPECT_THROW(normalAt(sphere, Point(1, 2, 3)), std::invalid_argument);
  expectVector(hitNormal(sphere, Point(1, 2, 3), fallback), 0, 0, -1);
  // TC12: on a tube's axis, and on a cylinder's axis between its bases: the fallback
  expectVector(hitNormal(Geometry(Tube(1, kZAxis)), Point(0, 0, 5), fallback), 0, 0, -1);
  expectVector(hitNormal(Geometry(Cylinder(1, kZAxis, 3)), Point(0, 0, 1), fallback), 0, 0, -1);
  // TC13: a sphere far below the course's 2^-40 scale: normalAt throws (its p - centre is the
  // course's zero), hitNormal still gives the true normal
  const Geometry tiny = Sphere(Point(0, 0, 0), 1e-14);
  EXPECT_THROW(normalAt(tiny, Point(1e-14, 0, 0)), std::invalid_argument);
  expectVector(hitNormal(tiny, Point(1e-14, 0, 0), fallback), 1, 0, 0);
  // TC14: a sphere so small (1e-170) that p - centre's squared length underflows: still the unit
  // normal, not NaN
  const Geometry tinier = Sphere(Point(0, 0, 0), 1e-170);
  expectVector(hitNormal(tinier, Point(0, -1e-170, 0), fallback), 0, -1, 0);
}

TEST(GeometryTests, shapeName) {
  // TC01: the course's lower-case name of each kind
  EXPECT_EQ(std::string(shapeName(Geometry(Sphere(Point(0, 0, 0), 1)))), "sphere");
  EXPECT_EQ(std::string(shapeName(Geometry(Plane(Point(0, 0, 0), Vector(0, 0, 1))))), "plane");
  EXPECT_EQ(
      std::string(shapeName(Geometry(Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0))))),
      "triangle");
  EXPECT_EQ(
      std::string(shapeName(Geometry(Polygon({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)})))),
      "polygon");
  EXPECT_EQ(std::string(shapeName(Geometry(Tube(1, kZAxis)))), "tube");
  EXPECT_EQ(std::string(shapeName(Geometry(Cylinder(1, kZAxis, 1)))), "cylinder");
}

}  // namespace
}  // namespace rt
