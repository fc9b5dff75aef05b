#pragma once
// Random scenes and rays with fixed seeds, for the equivalence tests and the benchmark.
//
// Scenes: spheres only; a mix of every bounded shape (spheres, triangles, axis-aligned and tilted
// rectangles on integer coordinates, so that faces are exactly flat and rays can start exactly on
// them, and cylinders); copies of shapes (exact ties between two indices); planes and tubes;
// triangle meshes moved elsewhere, and copies of their triangles as shapes.
// Rays: from outside towards the scene, from inside it, along the axes or parallel to a
// coordinate plane, from the points where earlier rays hit, with infinite or finite tMax.
// The numbers come from support/TestRandom.h, one draw per statement: the same scenes and rays
// on every compiler and standard library.

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "bvh/Aabb.h"
#include "intersections/Geometries.h"
#include "support/TestRandom.h"

namespace rt::test {

/// The tests' portable numbers, points and directions, with boxes as Aabb.
class Random : public TestRandom {
 public:
  using TestRandom::inBox;
  using TestRandom::TestRandom;
  Double3 inBox(const Aabb& box) noexcept { return inBox(box.lo, box.hi); }
  /// A point with integer coordinates in box (whose bounds should be integers): x, y, then z.
  Double3 gridPoint(const Aabb& box) noexcept {
    const double x = integer(int(box.lo.x), int(box.hi.x));
    const double y = integer(int(box.lo.y), int(box.hi.y));
    const double z = integer(int(box.lo.z), int(box.hi.z));
    return Double3(x, y, z);
  }
  /// Three points c + s·direction(), drawn in that order: a triangle's corners around c.
  std::vector<Point> cornersAround(const Double3& c, double s) {
    std::vector<Point> corners;
    for (int k = 0; k < 3; ++k) corners.emplace_back(c + direction() * s);
    return corners;
  }
  /// The triangle of cornersAround(c, s) (@throws std::invalid_argument as Triangle does).
  Triangle triangleAround(const Double3& c, double s) {
    const std::vector<Point> p = cornersAround(c, s);
    return Triangle(p[0], p[1], p[2]);
  }
};

/// n spheres with centres uniform in box and radii uniform in [rMin, rMax].
inline void addSpheres(Geometries& g, Random& random, std::uint32_t n, const Aabb& box, double rMin,
                       double rMax) {
  for (std::uint32_t i = 0; i < n; ++i) {
    const Point c(random.inBox(box));
    g.add(Sphere(c, random.uniform(rMin, rMax)));
  }
}

/// n shapes of every bounded kind, spread over box (whose bounds should be integers).
inline void addMixedShapes(Geometries& g, Random& random, std::uint32_t n, const Aabb& box) {
  for (std::uint32_t i = 0; i < n; ++i) {
    const Double3 c = random.inBox(box);
    switch (i % 5) {
      case 0:
        g.add(Sphere(Point(c), random.uniform(0.2, 3)));
        break;
      case 1:  // a triangle of size up to 6 around c
        g.add(random.triangleAround(c, random.uniform(0.5, 3)));
        break;
      case 2: {  // an axis-aligned rectangle on integer coordinates (exactly flat)
        const Double3 p = random.gridPoint(box);
        const double a = random.integer(1, 4), b = random.integer(1, 4);
        switch (random.integer(0, 2)) {
          case 0:
            g.add(Polygon({Point(p), Point(p + Double3(a, 0, 0)), Point(p + Double3(a, b, 0)),
                           Point(p + Double3(0, b, 0))}));
            break;
          case 1:
            g.add(Polygon({Point(p), Point(p + Double3(0, a, 0)), Point(p + Double3(0, a, b)),
                           Point(p + Double3(0, 0, b))}));
            break;
          default:
            g.add(Polygon({Point(p), Point(p + Double3(0, 0, a)), Point(p + Double3(b, 0, a)),
                           Point(p + Double3(b, 0, 0))}));
        }
        break;
      }
      case 3: {  // a tilted rectangle p, p+u, p+u+v, p+v on integers: u·v = −abk + abk = 0
        const Double3 p = random.gridPoint(box);
        const double a = random.integer(1, 3), b = random.integer(-2, 2);
        const double k = random.integer(-1, 1), h = random.integer(1, 2);
        const Double3 u(a, b, 0), v(-b * k, a * k, h);
        g.add(Polygon({Point(p), Point(p + u), Point(p + u + v), Point(p + v)}));
        break;
      }
      default: {
        const double radius = random.uniform(0.2, 2);
        const Vector axis(random.direction());
        g.add(Cylinder(radius, Ray(Point(c), axis), random.uniform(0.5, 5)));
      }
    }
  }
}

/// n axis-aligned rectangles on few planes (z = −3 … 3 and x = −3 … 3, integers), overlapping:
/// a ray through an overlap meets two rectangles of different boxes at exactly the same t.
inline void addCoplanarRectangles(Geometries& g, Random& random, std::uint32_t n) {
  for (std::uint32_t i = 0; i < n; ++i) {
    const double level = random.integer(-3, 3);
    const double u0 = random.integer(-12, 0), v0 = random.integer(-12, 0);
    const double u1 = u0 + random.integer(4, 12), v1 = v0 + random.integer(4, 12);
    if (i % 2 == 0)
      g.add(Polygon({Point(u0, v0, level), Point(u1, v0, level), Point(u1, v1, level),
                     Point(u0, v1, level)}));
    else
      g.add(Polygon({Point(level, u0, v0), Point(level, u1, v0), Point(level, u1, v1),
                     Point(level, u0, v1)}));
  }
}

/// Copies of `copies` shapes chosen at random, appended: exact ties between two indices.
inline void addCopies(Geometries& g, Random& random, std::uint32_t copies) {
  const std::uint32_t n = g.size();
  for (std::uint32_t i = 0; i < copies && n > 0; ++i)
    g.add(Geometry(g[static_cast<std::uint32_t>(random.integer(0, int(n) - 1))]));
}

/// Two planes and two tubes across box: the unbounded shapes.
inline void addUnbounded(Geometries& g, const Aabb& box) {
  const Double3 c = box.centroid();
  g.add(Plane(Point(box.lo - Double3(1)), Vector(0, 1, 0)));
  g.add(Plane(Point(box.hi + Double3(1)), Vector(1, 1, 1)));
  g.add(Tube(1.5, Ray(Point(c), Vector(0, 0, 1))));
  g.add(Tube(0.75, Ray(Point(c + Double3(3, 0, 0)), Vector(1, 2, 0))));
}

/// The mesh's vertices moved by offset, its triangles and normals kept: a second mesh of the
/// same shape elsewhere.
inline std::shared_ptr<const TriangleMesh> movedMesh(const TriangleMesh& mesh,
                                                     const Double3& offset) {
  std::vector<Point> vertices;
  vertices.reserve(mesh.vertexCount());
  for (const Point& v : mesh.vertices()) vertices.emplace_back(v.xyz() + offset);
  std::vector<Double3> normals;
  for (const Vector& n : mesh.normals()) normals.push_back(n.xyz());
  return std::make_shared<const TriangleMesh>(std::move(vertices), mesh.triangles(),
                                              std::move(normals));
}

/// Copies of `copies` triangles of mesh, chosen at random, as Triangle shapes: exact ties
/// between a shape and a mesh triangle.
inline void addTriangleCopies(Geometries& g, Random& random, const TriangleMesh& mesh,
                              std::uint32_t copies) {
  for (std::uint32_t i = 0; i < copies; ++i) {
    const std::array<Point, 3> c =
        mesh.corners(static_cast<std::size_t>(random.integer(0, int(mesh.triangleCount()) - 1)));
    g.add(Triangle(c[0], c[1], c[2]));
  }
}

/// A query: a ray and its maximum distance.
struct Query {
  Ray ray;
  double tMax;
};

/// n queries around box: a fifth each from outside (towards a point of the box), from inside
/// (any direction), along an axis, parallel to a coordinate plane, and from a grid point (on
/// the rectangles' planes); a third of them with a finite tMax.
inline std::vector<Query> randomQueries(Random& random, std::uint32_t n, const Aabb& box) {
  const double diagonal = std::sqrt(box.extent().lengthSquared());
  const Aabb around(box.lo - Double3(diagonal), box.hi + Double3(diagonal));
  std::vector<Query> queries;
  queries.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    Double3 origin, direction;
    switch (i % 5) {
      case 0: {
        origin = box.centroid() + random.direction() * diagonal;
        direction = random.inBox(box) - origin;
        break;
      }
      case 1:
        origin = random.inBox(box);
        direction = random.direction();
        break;
      case 2: {
        origin = random.inBox(around);
        const int axis = random.integer(0, 2);
        const double sign = random.chance(0.5) ? 1 : -1;
        direction = Double3(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
        break;
      }
      case 3: {
        origin = random.inBox(box);
        direction = random.direction();
        const int axis = random.integer(0, 2);
        (axis == 0 ? direction.x : axis == 1 ? direction.y : direction.z) = 0;
        if (direction.lengthSquared() < 1e-6) direction = Double3(1, 1, 0);
        break;
      }
      default: {
        const Double3 p = random.inBox(box);
        origin = Double3(std::round(p.x), std::round(p.y), std::round(p.z));
        direction = random.direction();
      }
    }
    const double tMax = random.chance(1.0 / 3) ? random.uniform(0, diagonal) : INFINITE_DISTANCE;
    queries.push_back(Query{Ray(Point(origin), Vector(direction)), tMax});
  }
  return queries;
}

}  // namespace rt::test
