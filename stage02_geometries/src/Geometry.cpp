#include "geometries/Geometry.h"

namespace rt {

Vector normalAt(const Geometry& g, const Point& p) {
  return std::visit([&p](const auto& shape) -> Vector { return shape.normal(p); }, g);
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
