#include "geometries/Triangle.h"

namespace rt {

Triangle::Triangle(const Point& p1, const Point& p2, const Point& p3)
    : vertices_{p1, p2, p3}, normal_(Plane(p1, p2, p3).normal()) {}

}  // namespace rt
