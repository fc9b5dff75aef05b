#pragma once
/// @file Sphere.h

#include <optional>

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
  /// The same normal for the per-ray path: never throws; nullopt only when p is exactly the
  /// centre.
  std::optional<Vector> tryNormal(const Point& p) const noexcept;

 private:
  Point center_;
  double radius_;
};

}  // namespace rt
