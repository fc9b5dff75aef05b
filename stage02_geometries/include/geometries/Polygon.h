#pragma once
/// @file Polygon.h

#include <initializer_list>
#include <vector>

#include "geometries/Plane.h"
#include "primitives/Point.h"

namespace rt {

/// A planar, convex polygon given by its vertices in order (either winding).
///
/// The constructor rejects, each with its own message naming the offending vertex:
/// fewer than 3 vertices; two consecutive vertices that coincide (including last == first);
/// a vertex not in the plane of the first three; a vertex on the line of its neighbours;
/// vertices out of order (the boundary crosses itself); a concave polygon.
class Polygon {
 public:
  /// @throws std::invalid_argument on any of the violations listed above.
  explicit Polygon(std::vector<Point> vertices);
  Polygon(std::initializer_list<Point> vertices) : Polygon(std::vector<Point>(vertices)) {}

  const std::vector<Point>& vertices() const { return vertices_; }
  const Plane& plane() const { return plane_; }
  /// The plane's normal, oriented by the vertices' winding (right-hand rule).
  const Vector& normal(const Point&) const { return plane_.normal(); }

 private:
  std::vector<Point> vertices_;
  Plane plane_;
};

}  // namespace rt
