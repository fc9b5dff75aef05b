#include "lighting/Material.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rt {

namespace {
void requireCoefficient(const char* field, const Double3& k) {
  const bool ok = k.isFinite() && k.x >= 0 && k.y >= 0 && k.z >= 0;
  if (!ok) {
    throw std::invalid_argument(std::string("Material: ") + field +
                                " must be finite and non-negative in every channel, got " +
                                k.str());
  }
}
}  // namespace

void Material::validate() const {
  requireCoefficient("kD", kD);
  requireCoefficient("kS", kS);
  requireCoefficient("kT", kT);
  requireCoefficient("kR", kR);
  if (shininess < 0) {
    throw std::invalid_argument("Material: shininess must be non-negative, got " +
                                std::to_string(shininess));
  }
  if (!(std::isfinite(ior) && ior > 0)) {
    throw std::invalid_argument("Material: ior must be a positive finite number, got " +
                                formatNumber(ior));
  }
}

}  // namespace rt
