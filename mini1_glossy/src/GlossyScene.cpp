#include "glossy/GlossyScene.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

namespace rt {

void validate(const LightSize& size, const char* what) {
  if (!(std::isfinite(size.radius) && size.radius >= 0)) {
    throw std::invalid_argument(std::string(what) +
                                ": radius must be a non-negative finite number, got " +
                                formatNumber(size.radius));
  }
  if (size.samples < 1 || size.samples > LightSize::MAX_SAMPLES) {
    throw std::invalid_argument(std::string(what) + ": samples must be between 1 and " +
                                std::to_string(LightSize::MAX_SAMPLES) + ", got " +
                                std::to_string(size.samples));
  }
}

std::uint32_t GlossyScene::addAppearance(const Color& emission, const Material& material,
                                         const Blur& rowBlur) {
  rowBlur.reflected.validate("Blur reflected");
  rowBlur.refracted.validate("Blur refracted");
  const std::uint32_t row = LitScene::addAppearance(emission, material);
  if (rowBlur != Blur{}) {
    blur.resize(appearances.size());
    blur[row] = rowBlur;
  }
  return row;
}

GlossyScene& GlossyScene::addLight(LightSource light, const LightSize& size) {
  rt::validate(size, "LightSize");
  if (size.radius > 0 && std::holds_alternative<DirectionalLight>(light))
    throw std::invalid_argument("LightSize: a directional light has no position, so no radius");
  LitScene::addLight(std::move(light));
  if (size != LightSize{}) {
    lightSizes.resize(lights.size());
    lightSizes.back() = size;
  }
  return *this;
}

void GlossyScene::validate() const {
  LitScene::validate();
  if (blur.size() > appearances.size()) {
    throw std::logic_error("GlossyScene: " + std::to_string(blur.size()) + " blurs for " +
                           std::to_string(appearances.size()) + " appearance rows");
  }
  if (lightSizes.size() > lights.size()) {
    throw std::logic_error("GlossyScene: " + std::to_string(lightSizes.size()) +
                           " light sizes for " + std::to_string(lights.size()) + " lights");
  }
  for (std::size_t i = 0; i < blur.size(); ++i) {
    const std::string what = "GlossyScene: blur[" + std::to_string(i) + "]";
    blur[i].reflected.validate((what + ".reflected").c_str());
    blur[i].refracted.validate((what + ".refracted").c_str());
  }
  for (std::size_t i = 0; i < lightSizes.size(); ++i) {
    const std::string what = "GlossyScene: lightSizes[" + std::to_string(i) + "]";
    rt::validate(lightSizes[i], what.c_str());
    if (lightSizes[i].radius > 0 && std::holds_alternative<DirectionalLight>(lights[i]))
      throw std::invalid_argument(what + ": a directional light has no position, so no radius");
  }
}

}  // namespace rt
