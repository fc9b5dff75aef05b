#include "common/Integers.h"

#include <cctype>
#include <cmath>
#include <cstdint>

namespace rt {

std::optional<int> integerIn(const nlohmann::ordered_json& j, int lo, int hi) {
  // nlohmann keeps 100 as an unsigned, -5 as a signed integer and 1e2 or 100.0 as a double; a
  // literal too large for 64 bits becomes a double too.
  if (j.is_number_unsigned()) {
    const std::uint64_t v = j.get<std::uint64_t>();
    if (hi < 0 || v > static_cast<std::uint64_t>(hi) || static_cast<std::int64_t>(v) < lo)
      return std::nullopt;
    return static_cast<int>(v);
  }
  if (j.is_number_integer()) {
    const std::int64_t v = j.get<std::int64_t>();
    if (v < lo || v > hi) return std::nullopt;
    return static_cast<int>(v);
  }
  if (j.is_number_float()) {
    const double v = j.get<double>();
    // false for NaN and the infinities
    if (!(v == std::floor(v) && v >= lo && v <= hi)) return std::nullopt;
    return static_cast<int>(v);
  }
  return std::nullopt;
}

std::optional<int> integerInText(std::string_view text, int lo, int hi) {
  // The JSON parser is the definition of "any JSON number form"; it would skip white space
  // around the number, which a value given on its own must not have.
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) ||
      std::isspace(static_cast<unsigned char>(text.back())))
    return std::nullopt;
  const nlohmann::ordered_json j =
      nlohmann::ordered_json::parse(text, /*cb=*/nullptr, /*allow_exceptions=*/false);
  return integerIn(j, lo, hi);
}

std::string integerDescription(int lo, int hi) {
  // The upper end said too when it is int's own (2147483647): "a non-negative integer" was
  // untrue of 2147483648, which is refused.
  return "an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
}

}  // namespace rt
