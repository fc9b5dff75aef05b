#include "geometries/Triangle.h"

#include <stdexcept>
#include <string>
#include <string_view>

namespace rt {

namespace {

/// The unit normal of the triangle's plane; Plane's refusal (collinear or coinciding vertices, a
/// normal that overflows) said as the triangle's, which is what the user gave.
Vector normalOf(const Point& p1, const Point& p2, const Point& p3) {
  try {
    return Plane(p1, p2, p3).normal();
  } catch (const std::invalid_argument& e) {
    const std::string_view message = e.what();
    constexpr std::string_view plane = "Plane";
    if (message.substr(0, plane.size()) != plane) throw;
    throw std::invalid_argument("Triangle" + std::string(message.substr(plane.size())));
  }
}

}  // namespace

Triangle::Triangle(const Point& p1, const Point& p2, const Point& p3)
    : vertices_{p1, p2, p3}, normal_(normalOf(p1, p2, p3)) {}

}  // namespace rt
