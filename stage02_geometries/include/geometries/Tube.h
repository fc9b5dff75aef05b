#pragma once
/// @file Tube.h

#include <optional>

#include "primitives/Point.h"
#include "primitives/Ray.h"
#include "primitives/Vector.h"

namespace rt {

/// An infinite circular tube: the points at distance radius from the axis line.
class Tube {
 public:
  /// @throws std::invalid_argument when radius is not a positive finite number.
  Tube(double radius, const Ray& axis);

  double radius() const { return radius_; }
  const Ray& axis() const { return axis_; }

  /// Outward unit normal: with s = axisDir·(p - P0) and O = P0 + s·axisDir, normalize(p - O).
  /// @throws std::invalid_argument when p lies on the axis.
  Vector normal(const Point& p) const;
  /// The same normal for the per-ray path: never throws; nullopt only when p is exactly on the
  /// axis.
  std::optional<Vector> tryNormal(const Point& p) const noexcept;

 private:
  /// p − O, O the axis point level with p (the unnormalised normal).
  Double3 radial(const Point& p) const noexcept;

  double radius_;
  Ray axis_;
};

}  // namespace rt
