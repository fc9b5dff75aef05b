#include "geometries/Geometry.h"

namespace rt {

Vector normalAt(const Geometry& g, const Point& p) {
  return std::visit([&p](const auto& shape) -> Vector { return shape.normal(p); }, g);
}

Vector hitNormal(const Geometry& g, const Point& p, const Vector& fallback) noexcept {
  struct Normal {
    const Point& p;
    const Vector& fallback;
    Vector operator()(const Sphere& s) const noexcept { return s.tryNormal(p).value_or(fallback); }
    Vector operator()(const Tube& t) const noexcept { return t.tryNormal(p).value_or(fallback); }
    Vector operator()(const Cylinder& c) const noexcept {
      return c.tryNormal(p).value_or(fallback);
    }
    // Flat shapes: one stored normal, never undefined.
    Vector operator()(const Plane& s) const noexcept { return s.normal(); }
    Vector operator()(const Triangle& s) const noexcept { return s.normal(); }
    Vector operator()(const Polygon& s) const noexcept { return s.plane().normal(); }
  };
  return std::visit(Normal{p, fallback}, g);
}

const char* shapeName(const Geometry& g) {
  struct Name {
    const char* operator()(const Sphere&) const { return "sphere"; }
    const char* operator()(const Plane&) const { return "plane"; }
    const char* operator()(const Triangle&) const { return "triangle"; }
    const char* operator()(const Polygon&) const { return "polygon"; }
    const char* operator()(const Tube&) const { return "tube"; }
    const char* operator()(const Cylinder&) const { return "cylinder"; }
  };
  return std::visit(Name{}, g);
}

}  // namespace rt
