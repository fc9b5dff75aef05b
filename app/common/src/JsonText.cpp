#include "common/JsonText.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace rt {

namespace {

using Json = nlohmann::ordered_json;

constexpr std::size_t LINE_WIDTH = 100;

/// A number, string, boolean or null as JSON text.
///
/// Doubles are written by std::to_chars in its general format without a precision: the fewest
/// significant digits that read back to the same double, in printf's %g notation (0.0005 and
/// 1e-05, 1e+23). nlohmann's own writer (Grisu2) also reads back exactly but is not always the
/// shortest (9.999999999999999e+22 for 1e23); plain to_chars (formatNumber, for messages) is,
/// but counts characters, not digits, and writes 5e-04 for 0.0005.
std::string scalarText(const Json& j) {
  if (j.is_number_float()) {
    const double v = j.get<double>();
    if (!std::isfinite(v)) return "null";
    // to_chars writes -0 as "-0", which JSON readers take for the integer 0; "-0.0" is a double.
    if (v == 0 && std::signbit(v)) return "-0.0";
    char buffer[32];
    const auto [end, error] =
        std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general);
    return std::string(buffer, end);
  }
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string keyText(const std::string& key) { return scalarText(Json(key)); }

/// j on one line: {"kA": 0.15, "color": [255, 255, 255]}.
std::string oneLine(const Json& j) {
  if (!j.is_structured()) return scalarText(j);
  std::string out(1, j.is_object() ? '{' : '[');
  std::size_t i = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++i) {
    if (i) out += ", ";
    if (j.is_object()) out += keyText(it.key()) + ": ";
    out += oneLine(it.value());
  }
  out += j.is_object() ? '}' : ']';
  return out;
}

/// Appends j, indented by indent, its first line starting at column; see formatJson.
void write(std::string& out, const Json& j, int indent, std::size_t column, bool document) {
  if (!j.is_structured() || j.empty()) {
    out += oneLine(j);
    return;
  }
  const bool listOfObjects = j.is_array() && j.front().is_object();
  if (!document && !listOfObjects) {
    if (std::string line = oneLine(j); column + line.size() <= LINE_WIDTH) {
      out += line;
      return;
    }
  }
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  out += j.is_object() ? "{\n" : "[\n";
  std::size_t i = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++i) {
    if (i) out += ",\n";
    out += pad;
    if (j.is_object()) out += keyText(it.key()) + ": ";
    write(out, it.value(), indent + 2, out.size() - out.rfind('\n') - 1, false);
  }
  out += '\n';
  out.append(static_cast<std::size_t>(indent), ' ');
  out += j.is_object() ? '}' : ']';
}

}  // namespace

Json jsonNumber(double v) {
  constexpr double EXACT_INTEGERS = 9007199254740992.0;  // 2^53
  if (!std::isfinite(v)) return Json(nullptr);
  if (v == std::trunc(v) && std::abs(v) < EXACT_INTEGERS && !(v == 0 && std::signbit(v)))
    return Json(static_cast<std::int64_t>(v));
  return Json(v);
}

Json jsonTriple(const Double3& v) {
  return Json::array({jsonNumber(v.x), jsonNumber(v.y), jsonNumber(v.z)});
}

std::string formatJson(const Json& j) {
  std::string out;
  write(out, j, 0, 0, true);
  out += '\n';
  return out;
}

}  // namespace rt
