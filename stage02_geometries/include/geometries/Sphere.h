#pragma once
/// @file Sphere.h

#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {

/// The set of points at distance radius from center.
class Sphere {
 public:
  /// @throws std::invalid_argument when radius is not a positive finite number.
  Sphere(const Point& center, double radius);

  const Point& center() const { return center_; }
  double radius() const { return radius_; }

  /// Outward unit normal at a point of the surface: normalize(p - center).
  /// @throws std::invalid_argument when p is the centre (the normal is undefined there).
  Vector normal(const Point& p) const;

 private:
  Point center_;
  double radius_;
};

}  // namespace rt
