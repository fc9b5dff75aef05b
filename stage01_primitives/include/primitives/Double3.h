#pragma once
/// @file Double3.h
/// A plain triple of doubles: the storage of Point, Vector and Color, and the type of the
/// per-channel coefficients (kD, kS, kT, kR). It has no invariant of its own.

#include <iosfwd>
#include <string>

#include "primitives/Util.h"

namespace rt {

struct Double3 {
  double x = 0, y = 0, z = 0;

  constexpr Double3() = default;
  constexpr Double3(double a, double b, double c) : x(a), y(b), z(c) {}
  /// The same value in all three components.
  constexpr explicit Double3(double v) : x(v), y(v), z(v) {}

  constexpr Double3 operator+(const Double3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Double3 operator-(const Double3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Double3 operator-() const { return {-x, -y, -z}; }
  /// Component-wise product.
  constexpr Double3 operator*(const Double3& o) const { return {x * o.x, y * o.y, z * o.z}; }
  constexpr Double3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Double3 operator/(double s) const { return {x / s, y / s, z / s}; }
  constexpr double dot(const Double3& o) const { return x * o.x + y * o.y + z * o.z; }
  constexpr Double3 cross(const Double3& o) const {
    return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x};
  }
  constexpr double lengthSquared() const { return dot(*this); }

  /// Course semantics: true only when all three components are below k.
  constexpr bool lowerThan(double k) const { return x < k && y < k && z < k; }
  /// True when every component isZero (inline: the sphere test asks it of every ray).
  bool isZero() const noexcept { return rt::isZero(x) && rt::isZero(y) && rt::isZero(z); }
  /// True when every component is exactly 0 (or −0): the test for "nothing passes" (a zero
  /// coefficient, a zero weight, a zero direction), where isZero's threshold would be wrong.
  constexpr bool isExactlyZero() const noexcept { return x == 0 && y == 0 && z == 0; }
  /// True when all three components are finite numbers.
  bool isFinite() const;

  /// Course equality: every component of the difference isZero.
  bool operator==(const Double3& o) const;

  /// "(x,y,z)" with the shortest round-trip form of each number.
  std::string str() const;

  static const Double3 ZERO;
  static const Double3 ONE;
};

constexpr Double3 operator*(double s, const Double3& v) { return v * s; }
std::ostream& operator<<(std::ostream& os, const Double3& v);

/// Formats a double in its shortest form that reads back to the same value ("0.1", "-2", "1e-05").
std::string formatNumber(double v);

}  // namespace rt
