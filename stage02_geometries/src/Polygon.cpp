#include "geometries/Polygon.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "primitives/Util.h"

namespace rt {

namespace {

std::string vertexName(std::size_t i, const std::vector<Point>& v) {
  return "vertices[" + std::to_string(i) + "] " + v[i].xyz().str();
}

[[noreturn]] void reject(const std::string& why) { throw std::invalid_argument("Polygon: " + why); }

/// Checks the count and that no two consecutive vertices coincide (the last and the first
/// included), then returns the plane of the first three vertices.
Plane planeOf(const std::vector<Point>& v) {
  const std::size_t n = v.size();
  if (n < 3) reject("needs at least 3 vertices, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t next = (i + 1) % n;
    if (v[i] == v[next]) {
      reject(vertexName(i, v) + " and " + vertexName(next, v) +
             " coincide (consecutive vertices must differ)");
    }
  }
  const Double3 normal = (v[1].xyz() - v[0].xyz()).cross(v[2].xyz() - v[0].xyz());
  if (normal.isZero()) reject(vertexName(1, v) + " lies on the line through its neighbours");
  return Plane(v[0], Vector(normal));
}

}  // namespace

Polygon::Polygon(std::vector<Point> vertices)
    : vertices_(std::move(vertices)), plane_(planeOf(vertices_)) {
  const std::vector<Point>& v = vertices_;
  const std::size_t n = v.size();
  const Double3& normal = plane_.normal().xyz();

  // A vertex's distance from the plane of the first three must be within the course's zero,
  // scaled by the vertices' largest coordinate when that is above 1: rounding a coordinate c to
  // a double moves it by up to 2^-53·|c|, which far from the origin (10^6: 10^-10) is above the
  // zero itself, so a flat polygon given there would be refused for its rounding.
  double size = 1;
  for (const Point& p : v)
    size = std::max({size, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
  for (std::size_t i = 3; i < n; ++i) {
    if (!(std::abs(normal.dot(v[i].xyz() - v[0].xyz())) < ZERO_THRESHOLD * size))
      reject(vertexName(i, v) + " is not in the plane of the first three vertices");
  }

  // Walk the boundary. At each vertex the turn from the incoming to the outgoing edge has a sign
  // relative to the normal: a convex polygon turns the same way at every vertex. The angles of
  // the turns add up to ±2π for a simple polygon; any other total means the edges cross.
  auto turnAt = [&](std::size_t i) {
    const Double3 in = v[i].xyz() - v[(i + n - 1) % n].xyz();
    const Double3 out = v[(i + 1) % n].xyz() - v[i].xyz();
    const double turn = normal.dot(in.cross(out));
    // (sine of the turn angle, the signed angle itself)
    return std::pair{turn / std::sqrt(in.lengthSquared() * out.lengthSquared()),
                     std::atan2(turn, in.dot(out))};
  };
  double totalTurn = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [sine, angle] = turnAt(i);
    if (isZero(sine)) reject(vertexName(i, v) + " lies on the line through its neighbours");
    totalTurn += angle;
  }
  if (std::abs(std::abs(totalTurn) - 2 * std::numbers::pi) > 1e-6)
    reject("the vertices are out of order (the edges cross each other)");
  // A simple polygon turns mostly the way of its total; a vertex turning the other way is reflex.
  for (std::size_t i = 0; i < n; ++i) {
    if ((turnAt(i).first > 0) != (totalTurn > 0))
      reject("the polygon is concave at " + vertexName(i, v));
  }
}

}  // namespace rt
