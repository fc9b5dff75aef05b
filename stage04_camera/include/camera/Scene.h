#pragma once
/// @file Scene.h

#include <string>

#include "camera/AmbientLight.h"
#include "intersections/Geometries.h"
#include "primitives/Color.h"

namespace rt {

/// What the ambient-only renderer needs: a background, an ambient light and the shapes.
/// Stage 5 extends it with lights, emission and materials (LitScene).
struct Scene {
  std::string name;
  Color background = Color::BLACK;
  AmbientLight ambientLight;
  Geometries geometries;

  Scene() = default;
  Scene(const Scene&) = default;
  Scene(Scene&&) = default;
  Scene& operator=(const Scene&) = default;
  Scene& operator=(Scene&&) = default;
  virtual ~Scene() = default;
};

}  // namespace rt
