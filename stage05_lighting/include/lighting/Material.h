#pragma once
/// @file Material.h

#include "primitives/Double3.h"

namespace rt {

/// Surface coefficients of the Phong model and of the recursive tracer, per RGB channel.
/// kD, kS and shininess are used from stage 5; kT (transparency) from stage 6 (shadows) and
/// stage 7 (refraction); kR (reflection) and ior from stage 7. They live here as plain data so a
/// scene is described once for every tracer.
struct Material {
  Double3 kD;         ///< diffuse, default 0
  Double3 kS;         ///< specular, default 0
  Double3 kT;         ///< transparency, default 0
  Double3 kR;         ///< reflection, default 0
  int shininess = 0;  ///< Phong exponent nSh, default 0
  double ior = 1;     ///< index of refraction; 1 keeps the course's straight-through refraction

  /// @throws std::invalid_argument for a negative or non-finite coefficient, a negative
  ///         shininess or an ior that is not positive; the message names the field.
  void validate() const;
};

}  // namespace rt
