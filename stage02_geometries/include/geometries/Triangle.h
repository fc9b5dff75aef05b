#pragma once
/// @file Triangle.h

#include <array>

#include "geometries/Plane.h"
#include "primitives/Point.h"

namespace rt {

/// A triangle: the course's Polygon with exactly three vertices. It is a type of its own here so
/// that it needs no heap storage; it shares the polygon's inside test (stage 3).
class Triangle {
 public:
  /// @throws std::invalid_argument when two vertices coincide or the three are collinear.
  Triangle(const Point& p1, const Point& p2, const Point& p3);

  const std::array<Point, 3>& vertices() const { return vertices_; }
  const Plane& plane() const { return plane_; }
  const Vector& normal(const Point&) const { return plane_.normal(); }

 private:
  std::array<Point, 3> vertices_;
  Plane plane_;
};

}  // namespace rt
