#pragma once
// Internal to mini1_glossy's scenes (the galaxy, the demonstration scenes).

#include "lighting/Material.h"

namespace rt {

/// A material from the course's setters: kD, kS, nSh, kT, kR (all channels equal).
inline Material material(double kD, double kS, int shininess, double kT = 0, double kR = 0) {
  return {.kD = Double3(kD),
          .kS = Double3(kS),
          .kT = Double3(kT),
          .kR = Double3(kR),
          .shininess = shininess,
          .ior = 1,
          .reflectedBeam = {},
          .refractedBeam = {}};
}

}  // namespace rt
