#pragma once
/// @file Optics.h
/// The directions of secondary rays and the Fresnel weight, as free functions of unit vectors.
///
/// Notation: v is the incoming ray's unit direction, n the surface's outward unit normal.
///
///   reflection        r = v − 2(v·n)n
///
///                   n ^
///              v     |     r
///               \    |    /
///                \   |   /
///                 \  |  /
///   ---------------\.|./---------------
///
///   refraction (Snell)   η1·sinθi = η2·sinθt
///
/// Entering (n·v < 0) goes from the outside (index 1) into the material (index ior): η = 1/ior,
/// N = n; leaving (n·v > 0) goes from the material out: η = ior, N = −n. With cosθi = |n·v|:
///
///     sin²θt = η²·(1 − cos²θi)
///     t = η·v + (η·cosθi − cosθt)·N,   cosθt = √(1 − sin²θt)
///
/// and no transmitted ray when sin²θt > 1 (total internal reflection).
///
///   Fresnel (Schlick)   R(θ) = R0 + (1 − R0)(1 − cosθ)^5,   R0 = ((η1 − η2)/(η1 + η2))²
///
/// with θ the angle on the side of the lower index (θi entering, θt leaving), which makes R the
/// same for a ray and its reverse.

#include <optional>

#include "primitives/Vector.h"

namespace rt {

/// The mirror direction r = v − 2(v·n)n (a unit vector for unit v and n).
Vector reflect(const Vector& v, const Vector& n) noexcept;

/// The course's refraction: straight through, the direction v itself.
inline const Vector& refractStraight(const Vector& v) noexcept { return v; }

/// What happens to a ray crossing the surface of a material of index ior (outside: index 1).
struct Refraction {
  /// The transmitted direction (Snell's law); nullopt on total internal reflection.
  std::optional<Vector> direction;
  /// The Fresnel reflectance R in [0, 1] by Schlick's approximation; 1 on total internal
  /// reflection.
  double reflectance;
  /// True when the ray goes into the material (n·v < 0).
  bool entering;
};

/// Snell's law and Schlick's reflectance for the unit direction v meeting the surface of unit
/// outward normal n of a material of index ior (> 0). n·v == 0 counts as entering.
Refraction refract(const Vector& v, const Vector& n, double ior) noexcept;

/// Schlick's approximation R = R0 + (1 − R0)(1 − cosTheta)^5 with R0 = ((n1 − n2)/(n1 + n2))²;
/// cosTheta is the cosine on the side of the lower index.
double schlick(double cosTheta, double n1, double n2) noexcept;

}  // namespace rt
