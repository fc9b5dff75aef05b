// mini2: the bounding box of every shape, exact values, and random points of each surface lie
// inside it; planes and tubes have none. A mesh triangle's box is a Triangle's; a primitive's is
// its shape's or its mesh triangle's.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "bvh/BoundingBox.h"
#include "geometries/UtahTeapot.h"
#include "intersections/Geometries.h"

#include "RandomScenes.h"

namespace rt {
namespace {

using test::Random;

/// p is in box, allowing the rounding of p's own computation (1e-12 of its size).
bool holds(const Aabb& box, const Double3& p) {
  const double tol = 1e-12 * (1 + std::sqrt(p.lengthSquared()));
  return box.lo.x - tol <= p.x && p.x <= box.hi.x + tol && box.lo.y - tol <= p.y &&
         p.y <= box.hi.y + tol && box.lo.z - tol <= p.z && p.z <= box.hi.z + tol;
}

/// Two unit vectors orthogonal to a and to each other.
std::pair<Double3, Double3> basisAround(const Double3& a) {
  const Double3 e = std::abs(a.x) < 0.9 ? Double3(1, 0, 0) : Double3(0, 1, 0);
  Double3 u = a.cross(e);
  u = u / std::sqrt(u.lengthSquared());
  return {u, a.cross(u)};
}

TEST(BoundingBoxTests, sphere) {
  // TC01: centre (1,2,3), radius 2: (-1,0,1)..(3,4,5)
  EXPECT_EQ(boundingBox(Sphere(Point(1, 2, 3), 2)), Aabb(Double3(-1, 0, 1), Double3(3, 4, 5)));
  // TC02: random points of the surface lie in the box
  Random random(1);
  const Sphere s(Point(-3, 7, 0.5), 1.25);
  const Aabb box = boundingBox(s);
  for (int i = 0; i < 1000; ++i)
    EXPECT_TRUE(holds(box, s.center().xyz() + random.direction() * s.radius()));
}

TEST(BoundingBoxTests, flatShapes) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the course's triangle (-2,0,0),(2,0,0),(0,4,0): (-2,0,0)..(2,4,0), flat in z
  const Triangle triangle(Point(-2, 0, 0), Point(2, 0, 0), Point(0, 4, 0));
  EXPECT_EQ(boundingBox(triangle), Aabb(Double3(-2, 0, 0), Double3(2, 4, 0)));
  // TC02: a tilted triangle: the minimum and maximum of the vertices on each axis
  const Triangle tilted(Point(1, -1, 2), Point(-3, 4, 0), Point(2, 2, -5));
  EXPECT_EQ(boundingBox(tilted), Aabb(Double3(-3, -1, -5), Double3(2, 4, 2)));
  // TC03: the course's square (0,0,0),(4,0,0),(4,4,0),(0,4,0)
  const Polygon square({Point(0, 0, 0), Point(4, 0, 0), Point(4, 4, 0), Point(0, 4, 0)});
  EXPECT_EQ(boundingBox(square), Aabb(Double3(0, 0, 0), Double3(4, 4, 0)));
  // TC04: a tilted pentagon in the plane x + z = 2
  const Polygon pentagon(
      {Point(0, 0, 2), Point(2, 0, 0), Point(2, 2, 0), Point(1, 3, 1), Point(0, 2, 2)});
  EXPECT_EQ(boundingBox(pentagon), Aabb(Double3(0, 0, 0), Double3(2, 3, 2)));
  // TC05: random points of both surfaces (convex combinations of the vertices) lie in the boxes
  Random random(2);
  for (int i = 0; i < 1000; ++i) {
    double w[5], sum = 0;
    for (double& wi : w) sum += (wi = random.uniform(0, 1));
    Double3 p(0), q(0);
    for (int k = 0; k < 3; ++k) p = p + tilted.vertices()[k].xyz() * (w[k] / sum);
    for (int k = 0; k < 5; ++k) q = q + pentagon.vertices()[k].xyz() * (w[k] / sum);
    EXPECT_TRUE(holds(boundingBox(tilted), p));
    EXPECT_TRUE(holds(boundingBox(pentagon), q));
  }
}

TEST(BoundingBoxTests, cylinder) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: axis +z from (1,2,3), radius 2, height 5: the caps span x, y ± 2; z from 3 to 8
  EXPECT_EQ(boundingBox(Cylinder(2, Ray(Point(1, 2, 3), Vector(0, 0, 1)), 5)),
            Aabb(Double3(-1, 0, 3), Double3(3, 4, 8)));
  // TC02: axis -x from the origin, radius 1, height 3: the caps are discs in x = 0 and x = -3
  EXPECT_EQ(boundingBox(Cylinder(1, Ray(Point(0, 0, 0), Vector(-1, 0, 0)), 3)),
            Aabb(Double3(-3, -1, -1), Double3(0, 1, 1)));
  // TC03: axis (0, 0.6, 0.8), radius 1, height 10 from the origin: the caps span
  // ±√(1 − a_i²) = (±1, ±0.8, ±0.6) around (0,0,0) and (0,6,8)
  const Aabb tilted = boundingBox(Cylinder(1, Ray(Point(0, 0, 0), Vector(0, 3, 4)), 10));
  EXPECT_DOUBLE_EQ(tilted.lo.x, -1);
  EXPECT_DOUBLE_EQ(tilted.lo.y, -0.8);
  EXPECT_DOUBLE_EQ(tilted.lo.z, -0.6);
  EXPECT_DOUBLE_EQ(tilted.hi.x, 1);
  EXPECT_DOUBLE_EQ(tilted.hi.y, 6.8);
  EXPECT_DOUBLE_EQ(tilted.hi.z, 8.6);
  // TC04: random points of the side and of both caps lie in the box, for random cylinders
  Random random(3);
  for (int c = 0; c < 50; ++c) {
    const Double3 a = random.direction();
    const double radius = random.uniform(0.1, 3);
    const Point head(random.direction() * 5);
    const Cylinder cyl(radius, Ray(head, Vector(a)), random.uniform(0.1, 8));
    const Aabb box = boundingBox(cyl);
    const auto [u, v] = basisAround(cyl.axis().direction().xyz());
    for (int i = 0; i < 100; ++i) {
      const double angle = random.uniform(0, 2 * std::numbers::pi);
      const Double3 radial = (u * std::cos(angle) + v * std::sin(angle)) * cyl.radius();
      const Double3& base = cyl.axis().head().xyz();
      const Double3& dir = cyl.axis().direction().xyz();
      const Double3 side = base + dir * random.uniform(0, cyl.height()) + radial;
      const double along = random.chance(0.5) ? 0 : cyl.height();
      const Double3 cap = base + dir * along + radial * std::sqrt(random.uniform(0, 1));
      EXPECT_TRUE(holds(box, side));
      EXPECT_TRUE(holds(box, cap));
    }
  }
  // =============== Boundary Values Tests ==================
  // TC11: the box is tight: the rim touches each of its faces (for the +z cylinder of TC01, the
  // rim point (3, 2, 3) is on the face x = 3)
  EXPECT_EQ(boundingBox(Cylinder(2, Ray(Point(1, 2, 3), Vector(0, 0, 1)), 5)).hi.x, 3);
}

TEST(BoundingBoxTests, unboundedAndVariant) {
  // TC01: a plane and a tube have no box
  EXPECT_FALSE(boundingBox(Plane(Point(0, 0, 0), Vector(0, 0, 1))).has_value());
  EXPECT_FALSE(boundingBox(Tube(1, Ray(Point(0, 0, 0), Vector(1, 0, 0)))).has_value());
  EXPECT_FALSE(boundingBox(Geometry(Plane(Point(0, 0, 0), Vector(0, 0, 1)))).has_value());
  EXPECT_FALSE(boundingBox(Geometry(Tube(1, Ray(Point(0, 0, 0), Vector(1, 0, 0))))).has_value());
  // TC02: through the variant, each bounded shape gets its own box
  const Sphere sphere(Point(1, 2, 3), 2);
  const Triangle triangle(Point(-2, 0, 0), Point(2, 0, 0), Point(0, 4, 0));
  const Cylinder cylinder(2, Ray(Point(1, 2, 3), Vector(0, 0, 1)), 5);
  EXPECT_EQ(boundingBox(Geometry(sphere)), boundingBox(sphere));
  EXPECT_EQ(boundingBox(Geometry(triangle)), boundingBox(triangle));
  EXPECT_EQ(boundingBox(Geometry(cylinder)), boundingBox(cylinder));
}

TEST(BoundingBoxTests, meshTriangles) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a mesh triangle's box is the box of a Triangle of its corners, for every triangle of
  // the teapot (its corners in every order of minimum and maximum)
  const TriangleMesh teapot = utahTeapot(4);
  for (std::size_t t = 0; t < teapot.triangleCount(); ++t) {
    const std::array<Point, 3> c = teapot.corners(t);
    EXPECT_EQ(boundingBox(teapot, t), boundingBox(Triangle(c[0], c[1], c[2]))) << "triangle " << t;
  }
  // TC02: the tilted triangle of flatShapes as triangle 1 of a mesh, its corners shared
  const TriangleMesh mesh({Point(0, 0, 0), Point(1, -1, 2), Point(-3, 4, 0), Point(2, 2, -5)},
                          {{0, 1, 2}, {1, 2, 3}});
  EXPECT_EQ(boundingBox(mesh, 1), Aabb(Double3(-3, -1, -5), Double3(2, 4, 2)));

  // TC03: a primitive's box: a shape's own (none for a plane), a mesh triangle's its triangle's,
  // with shapes added after the mesh numbered first
  Geometries g;
  g.addMesh(std::make_shared<const TriangleMesh>(mesh));
  g.add(Sphere(Point(1, 2, 3), 2), Plane(Point(0, 0, 0), Vector(0, 0, 1)));
  const Primitives p = g.primitives();
  EXPECT_EQ(boundingBox(p, 0), boundingBox(Sphere(Point(1, 2, 3), 2)));
  EXPECT_FALSE(boundingBox(p, 1).has_value());
  EXPECT_EQ(boundingBox(p, 2), Aabb(Double3(-3, -1, 0), Double3(1, 4, 2)));
  EXPECT_EQ(boundingBox(p, 3), boundingBox(mesh, 1));
  // =============== Boundary Values Tests ==================
  // TC11: a triangle flat in an axis has a box of zero thickness on it
  const TriangleMesh flat({Point(0, 0, 1), Point(1, 0, 1), Point(0, 1, 1)}, {{0, 1, 2}});
  EXPECT_EQ(boundingBox(flat, 0), Aabb(Double3(0, 0, 1), Double3(1, 1, 1)));
}

}  // namespace
}  // namespace rt
