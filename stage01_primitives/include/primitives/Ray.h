#pragma once
/// @file Ray.h
/// A half-line: a head point and a unit direction. The constructor normalises the direction.

#include <iosfwd>

#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {

class Ray {
 public:
  /// @param direction any non-zero vector; it is stored normalised.
  Ray(const Point& head, const Vector& direction)
      : head_(head), direction_(direction.normalized()) {}

  /// A ray whose direction the caller knows is already unit (a reflected, refracted or shadow
  /// ray's, computed from unit vectors): stored as it is, without a second normalisation (a
  /// square root and three divisions per secondary ray, saved).
  static Ray withUnitDirection(const Point& head, const Vector& unitDirection) noexcept {
    return Ray(head, unitDirection, Unit{});
  }

  const Point& head() const { return head_; }
  const Vector& direction() const { return direction_; }

  /// The point head + t·direction; t = 0 gives the head itself.
  Point point(double t) const { return Point(head_.xyz() + direction_.xyz() * t); }

  bool operator==(const Ray& o) const { return head_ == o.head_ && direction_ == o.direction_; }

 private:
  struct Unit {};
  Ray(const Point& head, const Vector& unitDirection, Unit) noexcept
      : head_(head), direction_(unitDirection) {}

  Point head_;
  Vector direction_;
};

std::ostream& operator<<(std::ostream& os, const Ray& r);

}  // namespace rt
