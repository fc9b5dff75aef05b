#include "cli/Values.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>

#include "cli/CommandLine.h"
#include "common/Integers.h"

namespace rt::cli {

namespace {

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

}  // namespace

std::string integerError(std::string_view text, int min, int max) {
  return "expected " + integerDescription(min, max) + ", got " + quoted(text);
}

int parseInt(std::string_view text, std::string_view what, int min, int max) {
  if (const std::optional<int> value = integerInText(text, min, max)) return *value;
  throw UsageError(std::string(what) + ": " + integerError(text, min, max));
}

double parseDouble(std::string_view text, std::string_view what) {
  double value = 0;
  const char* end = text.data() + text.size();
  // from_chars accepts no leading '+', and neither do we; it does accept "inf" and "nan",
  // which the finiteness check then refuses.
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc{} || ptr != end || !std::isfinite(value))
    throw UsageError(std::string(what) + ": expected a finite number, got " + quoted(text));
  return value;
}

template <std::size_t N>
std::array<double, N> parseNumbers(std::string_view text, std::string_view what) {
  std::array<double, N> out{};
  std::string_view rest = text;
  for (std::size_t k = 0; k < N; ++k) {
    const std::size_t comma = rest.find(',');
    const bool last = k + 1 == N;
    if (last != (comma == std::string_view::npos))
      throw UsageError(std::string(what) + ": expected " + std::to_string(N) +
                       " comma-separated numbers, got " + quoted(text));
    const std::string_view item = last ? rest : rest.substr(0, comma);
    try {
      out[k] = parseDouble(item, what);
    } catch (const UsageError&) {
      throw UsageError(std::string(what) + ": expected " + std::to_string(N) +
                       " comma-separated finite numbers, got " + quoted(text) + " (" +
                       quoted(item) + " is not one)");
    }
    if (!last) rest = rest.substr(comma + 1);
  }
  return out;
}

template std::array<double, 2> parseNumbers<2>(std::string_view, std::string_view);
template std::array<double, 3> parseNumbers<3>(std::string_view, std::string_view);

Double3 parseTriple(std::string_view text, std::string_view what) {
  const auto v = parseNumbers<3>(text, what);
  return {v[0], v[1], v[2]};
}

std::array<int, 2> parseIntPair(std::string_view text, std::string_view what, int maxX, int maxY) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos)
    throw UsageError(std::string(what) + ": expected X,Y, got " + quoted(text));
  return {parseInt(text.substr(0, comma), std::string(what) + " X", 0, maxX),
          parseInt(text.substr(comma + 1), std::string(what) + " Y", 0, maxY)};
}

}  // namespace rt::cli
