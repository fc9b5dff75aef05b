#include "bvh/Acceleration.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "bvh/Bvh.h"
#include "bvh/Cbr.h"
#include "bvh/WideBvh.h"
#include "grid/Grid.h"
#include "lightbuffer/LightBuffers.h"

namespace rt {

bool isAccelerationName(std::string_view name) noexcept {
  return std::find(ACCELERATION_NAMES.begin(), ACCELERATION_NAMES.end(), name) !=
         ACCELERATION_NAMES.end();
}

std::unique_ptr<Intersectable> makeAcceleration(std::string_view name, const Geometries& shapes) {
  if (name == "bvh") return std::make_unique<Bvh>(shapes);
  if (name == "bvh4") return std::make_unique<WideBvh>(shapes);
  if (name == "cbr") return std::make_unique<Cbr>(shapes);
  if (name == "grid") return std::make_unique<Grid>(shapes);
  if (name == "none") return nullptr;
  std::string known;
  for (std::string_view n : ACCELERATION_NAMES)
    known += (known.empty() ? "" : ", ") + std::string(n);
  throw std::invalid_argument("makeAcceleration: unknown acceleration '" + std::string(name) +
                              "' (known: " + known + ")");
}

std::unique_ptr<Intersectable> makeAcceleration(std::string_view name, const Geometries& shapes,
                                                std::span<const LightSource> lights,
                                                bool lightBuffers) {
  std::unique_ptr<Intersectable> structure = makeAcceleration(name, shapes);
  if (!lightBuffers || lights.empty()) return structure;
  if (!structure)
    return std::make_unique<LightBuffers>(static_cast<const Intersectable&>(shapes),
                                          shapes.primitives(), lights);
  return std::make_unique<LightBuffers>(std::move(structure), shapes.primitives(), lights);
}

}  // namespace rt
