#include "primitives/Vector.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>

namespace rt {

namespace {
[[noreturn]] void throwZero(const std::string& what) {
  throw std::invalid_argument(what + " is the zero vector, which cannot exist");
}
}  // namespace

const Vector Vector::AXIS_X{1, 0, 0};
const Vector Vector::AXIS_Y{0, 1, 0};
const Vector Vector::AXIS_Z{0, 0, 1};

Vector::Vector(double x, double y, double z) : Vector(Double3(x, y, z)) {}

Vector::Vector(const Double3& xyz) : xyz_(xyz) {
  // BEGIN SOLUTION: todo: Vector(xyz): throw std::invalid_argument when every component isZero
  if (xyz_.isZero()) throwZero("Vector constructor: " + xyz.str());
  // END SOLUTION
}

Vector Vector::operator+(const Vector& o) const {
  // BEGIN SOLUTION: hint: Vector + Vector; a zero sum (v + (-v)) throws std::invalid_argument
  const Double3 r = xyz_ + o.xyz_;
  if (r.isZero()) throwZero("Vector addition: " + xyz_.str() + " + " + o.xyz_.str());
  return Vector(r, Unchecked{});
  // END SOLUTION
}

Vector Vector::operator-(const Vector& o) const {
  // BEGIN SOLUTION: hint: Vector - Vector; a zero difference (v - v) throws std::invalid_argument
  const Double3 r = xyz_ - o.xyz_;
  if (r.isZero()) throwZero("Vector subtraction: " + xyz_.str() + " - " + o.xyz_.str());
  return Vector(r, Unchecked{});
  // END SOLUTION
}

Vector Vector::operator*(double s) const {
  // BEGIN SOLUTION: hint: Vector * number; a factor that isZero throws std::invalid_argument
  const Double3 r = xyz_ * s;
  if (r.isZero()) throwZero("Vector scaling: " + xyz_.str() + " * " + formatNumber(s));
  return Vector(r, Unchecked{});
  // END SOLUTION
}

Vector Vector::cross(const Vector& o) const {
  // BEGIN SOLUTION: hint: Vector::cross (right-handed); parallel operands throw
  const Double3 r = xyz_.cross(o.xyz_);
  if (r.isZero()) throwZero("Vector cross product: " + xyz_.str() + " x " + o.xyz_.str());
  return Vector(r, Unchecked{});
  // END SOLUTION
}

double Vector::length() const {
  // BEGIN SOLUTION: hint: Vector::length, the square root of lengthSquared()
  return std::sqrt(lengthSquared());
  // END SOLUTION
}

Vector Vector::normalized() const noexcept {
  // BEGIN SOLUTION: hint: Vector::normalized; mind |v|^2 overflowing or underflowing
  const double l2 = lengthSquared();
  if (l2 >= std::numeric_limits<double>::min() && l2 < std::numeric_limits<double>::infinity())
    return Vector(xyz_ / std::sqrt(l2), Unchecked{});
  // |v|² overflowed (components beyond ~1e154) or underflowed (below ~1e-154, reachable through
  // Vector::unchecked, say the normal of a sphere of radius 1e-170): scale by the largest
  // component first, or the division by an infinite (or zero) length would make the zero vector
  // (or NaN).
  const Double3 scaled = xyz_ / std::max({std::abs(xyz_.x), std::abs(xyz_.y), std::abs(xyz_.z)});
  return Vector(scaled / std::sqrt(scaled.lengthSquared()), Unchecked{});
  // END SOLUTION
}

std::ostream& operator<<(std::ostream& os, const Vector& v) { return os << v.xyz(); }

}  // namespace rt
