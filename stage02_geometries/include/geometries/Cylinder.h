#pragma once
/// @file Cylinder.h

#include <optional>

#include "geometries/Tube.h"

namespace rt {

/// A finite, closed cylinder: the tube between the bottom base (through the axis head) and the
/// top base at distance height along the axis, with both caps.
class Cylinder {
 public:
  /// @throws std::invalid_argument when radius or height is not a positive finite number.
  Cylinder(double radius, const Ray& axis, double height);

  double radius() const { return tube_.radius(); }
  const Ray& axis() const { return tube_.axis(); }
  double height() const { return height_; }
  /// The side surface as an infinite tube.
  const Tube& tube() const { return tube_; }

  /// Outward unit normal. On the bottom base (axial coordinate isZero, its centre and rim
  /// included) -axisDir; on the top base (axial coordinate - height isZero) +axisDir; elsewhere
  /// the tube's normal.
  Vector normal(const Point& p) const;
  /// The same normal for the per-ray path: never throws; nullopt only when a side point is
  /// exactly on the axis.
  std::optional<Vector> tryNormal(const Point& p) const noexcept;

 private:
  /// The base's normal when p is on a base (its centre and rim included), else nullopt.
  std::optional<Vector> baseNormal(const Point& p) const noexcept;

  Tube tube_;
  double height_;
};

}  // namespace rt
