#include "primitives/Point.h"

#include <cmath>
#include <ostream>
#include <stdexcept>

namespace rt {

const Point Point::ZERO{0, 0, 0};

Vector Point::operator-(const Point& o) const {
  // BEGIN SOLUTION: hint: Point - Point, from o to this point; equal points throw
  const Double3 r = xyz_ - o.xyz_;
  if (r.isZero()) {
    throw std::invalid_argument("Point subtraction: " + xyz_.str() + " - " + o.xyz_.str() +
                                " is the zero vector, which cannot exist");
  }
  return Vector(r, Vector::Unchecked{});
  // END SOLUTION
}

double Point::distance(const Point& o) const {
  // BEGIN SOLUTION: hint: Point::distance, the square root of distanceSquared
  return std::sqrt(distanceSquared(o));
  // END SOLUTION
}

std::ostream& operator<<(std::ostream& os, const Point& p) { return os << p.xyz(); }

}  // namespace rt
