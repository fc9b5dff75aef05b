#include "shadows/RayOffset.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "primitives/Double3.h"

namespace rt {

namespace {

void requirePositive(const char* function, const char* argument, double value) {
  if (!(std::isfinite(value) && value > 0)) {
    throw std::invalid_argument(std::string("RayOffset::") + function + ": " + argument +
                                " must be a positive finite number, got " + formatNumber(value));
  }
}

}  // namespace

RayOffset RayOffset::scaled(double relative) {
  requirePositive("scaled", "relative", relative);
  return RayOffset(true, relative);
}

RayOffset RayOffset::fixed(double delta) {
  requirePositive("fixed", "delta", delta);
  return RayOffset(false, delta);
}

}  // namespace rt
