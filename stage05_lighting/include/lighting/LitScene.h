#pragma once
/// @file LitScene.h

#include <cstdint>
#include <vector>

#include "camera/Scene.h"
#include "lighting/LightSource.h"
#include "lighting/Material.h"
#include "primitives/Color.h"

namespace rt {

/// How a shape looks: what it emits and what it is made of.
struct Appearance {
  Color emission = Color::BLACK;
  Material material;
};

/// A scene with light sources, and an Appearance for every shape. appearances[i] belongs to
/// geometries[i]; add() keeps the two lists aligned, and every tracer checks it once when it is
/// constructed (std::logic_error otherwise).
struct LitScene : Scene {
  std::vector<Appearance> appearances;
  std::vector<LightSource> lights;

  LitScene() = default;
  /// An unlit scene (stage 4) as a lit one: every shape gets the default Appearance.
  explicit LitScene(const Scene& base) : Scene(base), appearances(base.geometries.size()) {}

  /// Adds a shape with its appearance and returns its index.
  std::uint32_t add(Geometry shape, const Color& emission = Color::BLACK,
                    const Material& material = {}) {
    material.validate();
    appearances.push_back({emission, material});
    return geometries.add(std::move(shape));
  }
  LitScene& addLight(LightSource light) {
    validate(light);
    lights.push_back(std::move(light));
    return *this;
  }
};

}  // namespace rt
