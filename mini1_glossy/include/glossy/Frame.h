#pragma once
/// @file Frame.h
/// An orthonormal frame around any unit vector: what a beam's target circle and a light's disk
/// are laid out in.
///
/// The Java course project built it as nX = normalize(dir × Y), nY = dir × nX, with a special case
/// for dir == +Y only: for dir == −Y the cross product is zero and the beam collapses. Duff et al.
/// ("Building an Orthonormal Basis, Revisited", JCGT 2017) give a frame that is continuous and
/// exact for every unit w, without a branch on the direction: with s = sign(w.z) (+1 for 0),
/// a = −1/(s + w.z), b = w.x·w.y·a,
///
///     u = (1 + s·w.x²·a,  s·b,  −s·w.x)
///     v = (b,  s + w.y²·a,  −w.y)
///
/// u, v, w are unit, mutually orthogonal and right-handed (u × v = w).

#include <cmath>

#include "primitives/Double3.h"

namespace rt {

struct Frame {
  Double3 u, v, w;

  /// The frame whose third axis is the unit vector w (not checked: per-ray code).
  static Frame around(const Double3& w) noexcept {
    const double s = std::copysign(1.0, w.z);
    const double a = -1.0 / (s + w.z);
    const double b = w.x * w.y * a;
    return {Double3(1 + s * w.x * w.x * a, s * b, -s * w.x), Double3(b, s + w.y * w.y * a, -w.y),
            w};
  }

  /// The point (x, y) of the frame's plane, as a vector: x·u + y·v.
  Double3 inPlane(double x, double y) const noexcept { return u * x + v * y; }
};

}  // namespace rt
