#include "lighting/LitScene.h"

#include <stdexcept>
#include <string>

namespace rt {

LitScene::LitScene(const Scene& base)
    : Scene(base),
      appearances(base.geometries.primitiveCount() == 0 ? 0 : 1),
      appearanceIndex(base.geometries.size(), 0),
      meshAppearance(base.geometries.meshes().size(), 0) {}

std::uint32_t LitScene::addAppearance(const Color& emission, const Material& material) {
  material.validate();
  appearances.push_back({emission, material});
  return static_cast<std::uint32_t>(appearances.size() - 1);
}

std::uint32_t LitScene::add(Geometry shape, std::uint32_t appearance) {
  if (appearance >= appearances.size()) {
    throw std::out_of_range("LitScene::add: appearance " + std::to_string(appearance) +
                            " does not exist (the table has " + std::to_string(appearances.size()) +
                            " rows)");
  }
  appearanceIndex.push_back(appearance);
  return geometries.add(std::move(shape));
}

std::uint32_t LitScene::add(Geometry shape, const Color& emission, const Material& material) {
  return add(std::move(shape), addAppearance(emission, material));
}

std::uint32_t LitScene::addMesh(std::shared_ptr<const TriangleMesh> mesh,
                                std::uint32_t appearance) {
  if (appearance >= appearances.size()) {
    throw std::out_of_range("LitScene::addMesh: appearance " + std::to_string(appearance) +
                            " does not exist (the table has " + std::to_string(appearances.size()) +
                            " rows)");
  }
  const std::uint32_t index = geometries.addMesh(std::move(mesh));
  meshAppearance.push_back(appearance);
  return index;
}

LitScene& LitScene::addLight(LightSource light) {
  rt::validate(light);
  lights.push_back(std::move(light));
  return *this;
}

void LitScene::validate() const {
  if (appearanceIndex.size() != geometries.size()) {
    throw std::logic_error("LitScene: " + std::to_string(geometries.size()) + " geometries but " +
                           std::to_string(appearanceIndex.size()) +
                           " appearance indices; every shape needs one (use LitScene::add)");
  }
  for (std::size_t i = 0; i < appearanceIndex.size(); ++i) {
    if (appearanceIndex[i] >= appearances.size()) {
      throw std::logic_error("LitScene: geometry " + std::to_string(i) + " uses appearance " +
                             std::to_string(appearanceIndex[i]) + " but the table has " +
                             std::to_string(appearances.size()) + " rows");
    }
  }
  if (meshAppearance.size() != geometries.meshes().size()) {
    throw std::logic_error(
        "LitScene: " + std::to_string(geometries.meshes().size()) + " meshes but " +
        std::to_string(meshAppearance.size()) +
        " mesh appearance indices; every mesh needs one (use LitScene::addMesh)");
  }
  for (std::size_t m = 0; m < meshAppearance.size(); ++m) {
    if (meshAppearance[m] >= appearances.size()) {
      throw std::logic_error("LitScene: mesh " + std::to_string(m) + " uses appearance " +
                             std::to_string(meshAppearance[m]) + " but the table has " +
                             std::to_string(appearances.size()) + " rows");
    }
  }
  for (std::size_t i = 0; i < appearances.size(); ++i) {
    try {
      appearances[i].material.validate();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("LitScene: appearances[" + std::to_string(i) + "]: " + e.what());
    }
  }
  for (std::size_t i = 0; i < lights.size(); ++i) {
    try {
      rt::validate(lights[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("LitScene: lights[" + std::to_string(i) + "]: " + e.what());
    }
  }
}

}  // namespace rt
