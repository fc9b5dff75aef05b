#pragma once
/// @file Vector.h
/// A direction in space. The course's central rule: a zero vector can never exist. Every
/// operation whose result would be zero (constructing (0,0,0), adding opposite vectors,
/// subtracting a vector from itself, scaling by 0, crossing parallel vectors) throws
/// std::invalid_argument naming the operation and its operands.

#include <iosfwd>

#include "primitives/Double3.h"

namespace rt {

class Vector {
 public:
  /// @throws std::invalid_argument when every component isZero.
  Vector(double x, double y, double z);
  /// @throws std::invalid_argument when every component isZero.
  explicit Vector(const Double3& xyz);

  /// A vector from a triple the caller knows is not zero, without the check: for the per-ray
  /// path, which must never throw (a reflected direction has length 1, a light's direction
  /// points from a position that was checked to differ from the point). Everywhere else use
  /// the constructor.
  static Vector unchecked(const Double3& nonZero) noexcept { return Vector(nonZero, Unchecked{}); }

  double x() const { return xyz_.x; }
  double y() const { return xyz_.y; }
  double z() const { return xyz_.z; }
  const Double3& xyz() const { return xyz_; }

  /// @throws std::invalid_argument when the sum is the zero vector (v + (-v)).
  Vector operator+(const Vector& o) const;
  /// @throws std::invalid_argument when the difference is the zero vector (v - v).
  Vector operator-(const Vector& o) const;
  Vector operator-() const { return Vector(-xyz_, Unchecked{}); }
  /// Scaling; @throws std::invalid_argument for a factor that isZero.
  Vector operator*(double s) const;

  double dot(const Vector& o) const { return xyz_.dot(o.xyz_); }
  /// Right-handed cross product; @throws std::invalid_argument for parallel operands.
  Vector cross(const Vector& o) const;

  double lengthSquared() const { return xyz_.lengthSquared(); }
  double length() const;
  /// The unit vector in the same direction (never throws: a Vector is never zero).
  Vector normalized() const noexcept;

  /// Course equality: every component of the difference isZero.
  bool operator==(const Vector& o) const { return xyz_ == o.xyz_; }

  static const Vector AXIS_X;
  static const Vector AXIS_Y;
  static const Vector AXIS_Z;

 private:
  friend class Point;
  struct Unchecked {};
  /// For results that cannot be zero by construction (negation, normalisation).
  Vector(const Double3& xyz, Unchecked) noexcept : xyz_(xyz) {}
  Double3 xyz_;
};

inline Vector operator*(double s, const Vector& v) { return v * s; }
std::ostream& operator<<(std::ostream& os, const Vector& v);

}  // namespace rt
