#pragma once
/// @file Lighting.h
/// The fields of the stage-5 part's objects, for the parts above it that add keys to them
/// (mini 1: a light's radius and shadow samples).

#include <optional>

#include "primitives/Color.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt::scenefile {

struct LightFields {
  std::optional<Color> intensity;
  std::optional<Point> position;
  std::optional<Vector> direction;
  double kC = 1, kL = 0, kQ = 0, narrowBeam = 1;
  double radius = 0;      ///< mini 1's key (soft shadows): PointLight::radius
  int shadowSamples = 1;  ///< mini 1's key: PointLight::shadowSamples
};

}  // namespace rt::scenefile
