#pragma once
/// @file Material.h

#include "primitives/Double3.h"

namespace rt {

/// How one kind of secondary ray of a material spreads into a beam of rays: plain data here,
/// used by the first mini project's beams tracer (glossy reflection, diffused glass; see
/// mini1_glossy/README.md). The default is no beam: the course's one ray.
struct BeamSettings {
  /// The largest grid accepted: 64 x 64 cells (3228 rays per beam).
  static constexpr int MAX_GRID = 64;

  double distance = 1;  ///< from the ray's origin to the target circle's centre, > 0
  double radius = 0;    ///< of the target circle, >= 0; 0: no beam
  int grid = 1;         ///< N of the N x N grid of cells, 1..MAX_GRID; 1: no beam

  /// True when the settings make a beam of more than one ray.
  bool isBeam() const noexcept { return grid > 1 && radius > 0; }
  bool operator==(const BeamSettings&) const = default;
};

/// Surface coefficients of the Phong model and of the recursive tracer, per RGB channel.
/// kD, kS and shininess are used from stage 5; kT (transparency) from stage 6 (shadows) and
/// stage 7 (refraction); kR (reflection) and ior from stage 7; the beams from mini project 1.
/// They live here as plain data so a scene is described once for every tracer.
struct Material {
  Double3 kD;         ///< diffuse, default 0
  Double3 kS;         ///< specular, default 0
  Double3 kT;         ///< transparency, default 0
  Double3 kR;         ///< reflection, default 0
  int shininess = 0;  ///< Phong exponent nSh, default 0
  double ior = 1;     ///< index of refraction; 1 keeps the course's straight-through refraction
  BeamSettings reflectedBeam;  ///< glossy reflection (mini project 1); default: none
  BeamSettings refractedBeam;  ///< diffused glass (mini project 1); default: none

  /// @throws std::invalid_argument for a negative or non-finite coefficient, a negative
  ///         shininess, an ior that is not positive, or a beam whose distance is not a positive
  ///         finite number, whose radius is negative or not finite, or whose grid is outside
  ///         1..BeamSettings::MAX_GRID; the message names the field.
  void validate() const;

  /// A material as the course's setters make it: kD, kS, nSh, kT, kR, each the same on every
  /// channel; ior 1 and no beams.
  static Material course(double kD, double kS, int shininess, double kT = 0, double kR = 0) {
    Material m;
    m.kD = Double3(kD);
    m.kS = Double3(kS);
    m.kT = Double3(kT);
    m.kR = Double3(kR);
    m.shininess = shininess;
    return m;
  }
};

}  // namespace rt
