#include "primitives/Checks.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rt {

namespace {
[[noreturn]] void reject(std::string_view operation, std::string_view argument,
                         std::string_view requirement, const std::string& value) {
  std::string message(operation);
  message.append(": ").append(argument).append(" must be ").append(requirement);
  message.append(", got ").append(value);
  throw std::invalid_argument(message);
}
}  // namespace

double requirePositive(double value, std::string_view operation, std::string_view argument) {
  if (!(std::isfinite(value) && value > 0))
    reject(operation, argument, "a positive finite number", formatNumber(value));
  return value;
}

double requireNonNegative(double value, std::string_view operation, std::string_view argument) {
  if (!(std::isfinite(value) && value >= 0))
    reject(operation, argument, "a non-negative finite number", formatNumber(value));
  return value;
}

long requireBetween(long value, long lo, long hi, std::string_view operation,
                    std::string_view argument) {
  if (value < lo || value > hi) {
    reject(operation, argument, "between " + std::to_string(lo) + " and " + std::to_string(hi),
           std::to_string(value));
  }
  return value;
}

const Double3& requireFinite(const Double3& value, std::string_view operation,
                             std::string_view argument) {
  if (!value.isFinite()) reject(operation, argument, "finite", value.str());
  return value;
}

}  // namespace rt
