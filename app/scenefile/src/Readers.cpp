#include "Readers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "common/Integers.h"
#include "common/NearestName.h"

namespace rt::scenefile {

namespace {

bool isArrayOf(const Node& n, std::size_t size) {
  return n.json().is_array() && n.json().size() == size;
}

/// Names listed in a message: at most this many, then "and N more".
constexpr std::size_t LISTED_NAMES = 12;

/// The N elements of n, an array of exactly N, each read by readOne, in order; otherwise
/// "expected WHAT".
template <typename T, std::size_t N, typename Read>
std::array<T, N> readArray(const Node& n, std::string_view what, Read readOne) {
  if (!isArrayOf(n, N)) n.expected(what);
  std::array<T, N> values{};
  std::size_t i = 0;
  n.forEachElement([&](const Node& e) { values[i++] = readOne(e); });
  return values;
}

}  // namespace

double readNumber(const Node& n) {
  if (!n.json().is_number()) n.expected("a number");
  const double v = n.json().get<double>();
  if (!std::isfinite(v)) n.expected("a finite number");
  return v;
}

double readPositive(const Node& n) {
  if (!n.json().is_number()) n.expected("a positive number");
  const double v = readNumber(n);
  if (!(v > 0)) n.expected("a positive number");
  return v;
}

double readNonNegative(const Node& n) {
  if (!n.json().is_number()) n.expected("a non-negative number");
  const double v = readNumber(n);
  if (!(v >= 0)) n.expected("a non-negative number");
  return v;
}

double readNumberIn(const Node& n, double lo, double hi) {
  const std::string what = "a number from " + formatNumber(lo) + " to " + formatNumber(hi);
  if (!n.json().is_number()) n.expected(what);
  const double v = readNumber(n);
  if (!(v >= lo && v <= hi)) n.expected(what);
  return v;
}

double readCoordinate(const Node& n) {
  static const std::string what =
      "a coordinate from -" + formatNumber(MAX_COORDINATE) + " to " + formatNumber(MAX_COORDINATE);
  const double v = readNumber(n);
  if (!(std::abs(v) <= MAX_COORDINATE)) n.expected(what);
  return v;
}

double readLength(const Node& n) {
  const double v = readPositive(n);
  if (!(v <= MAX_COORDINATE)) n.expected("a length up to " + formatNumber(MAX_COORDINATE));
  return v;
}

double readConstantAttenuation(const Node& n) {
  const std::string what = "a number of at least 2^-40 (the course's zero)";
  if (!n.json().is_number()) n.expected(what);
  const double v = readNumber(n);
  if (!(v >= MIN_KC)) n.expected(what);
  return v;
}

int readInteger(const Node& n, int lo, int hi) {
  const std::optional<int> v = integerIn(n.json(), lo, hi);
  if (!v) n.expected(integerDescription(lo, hi));
  return *v;
}

std::string readString(const Node& n) {
  if (!n.json().is_string()) n.expected("a string");
  return n.json().get<std::string>();
}

bool readBoolean(const Node& n) {
  if (!n.json().is_boolean()) n.expected("true or false");
  return n.json().get<bool>();
}

Point readPoint(const Node& n) {
  const auto xyz = readArray<double, 3>(n, "a point [x,y,z]", readCoordinate);
  return Point(xyz[0], xyz[1], xyz[2]);
}

Vector readDirection(const Node& n) {
  const auto xyz = readArray<double, 3>(n, "a vector [x,y,z]", readNumber);
  const Double3 d(xyz[0], xyz[1], xyz[2]);
  // The course's rule: a vector whose components are all zero (below 2^-40) cannot exist.
  if (d.isZero()) n.expected("a non-zero vector [x,y,z]");
  // Its normalisation must exist too: |d|^2 overflows for components beyond about 1e154.
  if (!std::isfinite(d.lengthSquared()) || !(d.lengthSquared() > 0))
    n.expected("a vector [x,y,z] of finite length");
  return Vector(d);
}

namespace {
double readColorValue(const Node& n) { return readNumberIn(n, 0, MAX_COLOR_VALUE); }
}  // namespace

Color readColor(const Node& n) {
  const auto rgb = readArray<double, 3>(n, "a colour [r,g,b]", readColorValue);
  return Color(rgb[0], rgb[1], rgb[2]);
}

Double3 readCoefficient(const Node& n) {
  if (n.json().is_number()) return Double3(readColorValue(n));
  const auto k = readArray<double, 3>(n, "a coefficient (a number or [r,g,b])", readColorValue);
  return Double3(k[0], k[1], k[2]);
}

std::vector<Point> readPoints(const Node& n, std::size_t minCount, std::size_t maxCount) {
  const bool sizeOk =
      n.json().is_array() && n.json().size() >= minCount && n.json().size() <= maxCount;
  if (!sizeOk) {
    if (minCount == maxCount)
      n.expected("an array of " + std::to_string(minCount) + " points [x,y,z]");
    n.expected("an array of at least " + std::to_string(minCount) + " points [x,y,z]");
  }
  std::vector<Point> points;
  points.reserve(n.json().size());
  n.forEachElement([&](const Node& e) { points.push_back(readPoint(e)); });
  return points;
}

std::array<double, 2> readPositivePair(const Node& n) {
  return readArray<double, 2>(n, "two positive numbers [width,height]", readPositive);
}

std::array<int, 2> readIntegerPair(const Node& n, int lo, int hi) {
  return readArray<int, 2>(n, "two integers [nX,nY]",
                           [lo, hi](const Node& e) { return readInteger(e, lo, hi); });
}

std::string readChoice(const Node& n, std::string_view what,
                       std::span<const std::string_view> choices) {
  const std::string expected = std::string(what) + " (" + joinNames(choices) + ")";
  if (!n.json().is_string()) n.expected(expected);
  const std::string value = n.json().get<std::string>();
  if (std::find(choices.begin(), choices.end(), value) != choices.end()) return value;
  n.fail("expected " + expected + ", got " + n.describe() + didYouMean(value, choices));
}

std::string joinNames(std::span<const std::string_view> names) {
  return rt::joinNames(names, ", ", LISTED_NAMES);
}

}  // namespace rt::scenefile
