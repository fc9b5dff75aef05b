#pragma once
/// @file Triangle.h

#include <array>

#include "geometries/Plane.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {

/// A triangle: the course's Polygon with exactly three vertices. It is a type of its own here so
/// that it needs no heap storage; it shares the polygon's inside test (stage 3).
///
/// It keeps its vertices and its plane's unit normal (96 bytes), not a whole Plane: the plane's
/// point would repeat the first vertex, and a Triangle is the largest alternative of the shapes'
/// variant, so its size is every shape's (a sphere of a 10^6-star galaxy included).
class Triangle {
 public:
  /// @throws std::invalid_argument when two vertices coincide or the three are collinear.
  Triangle(const Point& p1, const Point& p2, const Point& p3);

  const std::array<Point, 3>& vertices() const { return vertices_; }
  /// The plane of the vertices: through the first, normal normalize((p2 − p1) × (p3 − p1)).
  Plane plane() const { return Plane::ofUnitNormal(vertices_[0], normal_); }
  /// The plane's unit normal, oriented by the vertices' winding (right-hand rule).
  const Vector& normal() const { return normal_; }
  const Vector& normal(const Point&) const { return normal_; }

 private:
  std::array<Point, 3> vertices_;
  Vector normal_;
};

}  // namespace rt
