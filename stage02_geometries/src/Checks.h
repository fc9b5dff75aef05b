#pragma once
// Argument checks shared by the shapes' constructors (private to stage 2).

#include <cmath>
#include <stdexcept>
#include <string>

#include "primitives/Double3.h"

namespace rt::detail {

/// @throws std::invalid_argument "<what>: <name> must be a positive number, got <value>".
inline double requirePositive(double value, const char* what, const char* name) {
  if (!(std::isfinite(value) && value > 0)) {
    throw std::invalid_argument(std::string(what) + ": " + name +
                                " must be a positive number, got " + formatNumber(value));
  }
  return value;
}

/// @throws std::invalid_argument "<what>: <name> must be finite, got <value>" for a component
/// that is infinite or NaN (including one that overflowed while the shape was derived).
inline const Double3& requireFinite(const Double3& value, const char* what, const char* name) {
  if (!value.isFinite()) {
    throw std::invalid_argument(std::string(what) + ": " + name + " must be finite, got " +
                                value.str());
  }
  return value;
}

}  // namespace rt::detail
