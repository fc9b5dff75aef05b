#pragma once
/// @file Point.h
/// A location in space. Points and vectors are distinct types: a point plus a vector is a
/// point, a point minus a point is a vector (and throws when the two points are equal, since
/// that vector would be zero).

#include <iosfwd>

#include "primitives/Double3.h"
#include "primitives/Vector.h"

namespace rt {

class Point {
 public:
  constexpr Point(double x, double y, double z) : xyz_(x, y, z) {}
  constexpr explicit Point(const Double3& xyz) : xyz_(xyz) {}

  double x() const { return xyz_.x; }
  double y() const { return xyz_.y; }
  double z() const { return xyz_.z; }
  const Double3& xyz() const { return xyz_; }

  Point operator+(const Vector& v) const { return Point(xyz_ + v.xyz()); }
  Point operator-(const Vector& v) const { return Point(xyz_ - v.xyz()); }
  /// The vector from o to this point; @throws std::invalid_argument when the points are equal.
  Vector operator-(const Point& o) const;

  double distanceSquared(const Point& o) const { return (xyz_ - o.xyz_).lengthSquared(); }
  double distance(const Point& o) const;

  /// Course equality: every component of the difference isZero.
  bool operator==(const Point& o) const { return xyz_ == o.xyz_; }

  static const Point ZERO;

 private:
  Double3 xyz_;
};

std::ostream& operator<<(std::ostream& os, const Point& p);

}  // namespace rt
