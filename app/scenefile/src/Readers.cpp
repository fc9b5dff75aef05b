#include "Readers.h"

#include <algorithm>
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
  if (!isArrayOf(n, 3)) n.expected("a point [x,y,z]");
  double xyz[3];
  std::size_t i = 0;
  n.forEachElement([&](const Node& e) { xyz[i++] = readNumber(e); });
  return Point(xyz[0], xyz[1], xyz[2]);
}

Vector readDirection(const Node& n) {
  if (!isArrayOf(n, 3)) n.expected("a vector [x,y,z]");
  double xyz[3];
  std::size_t i = 0;
  n.forEachElement([&](const Node& e) { xyz[i++] = readNumber(e); });
  const Double3 d(xyz[0], xyz[1], xyz[2]);
  // The course's rule: a vector whose components are all zero (below 2^-40) cannot exist.
  if (d.isZero()) n.expected("a non-zero vector [x,y,z]");
  // Its normalisation must exist too: |d|^2 overflows for components beyond about 1e154.
  if (!std::isfinite(d.lengthSquared()) || !(d.lengthSquared() > 0))
    n.expected("a vector [x,y,z] of finite length");
  return Vector(d);
}

Color readColor(const Node& n) {
  if (!isArrayOf(n, 3)) n.expected("a colour [r,g,b]");
  double rgb[3];
  std::size_t i = 0;
  n.forEachElement([&](const Node& e) { rgb[i++] = readNonNegative(e); });
  return Color(rgb[0], rgb[1], rgb[2]);
}

Double3 readCoefficient(const Node& n) {
  if (n.json().is_number()) return Double3(readNonNegative(n));
  if (!isArrayOf(n, 3)) n.expected("a coefficient (a number or [r,g,b])");
  double k[3];
  std::size_t i = 0;
  n.forEachElement([&](const Node& e) { k[i++] = readNonNegative(e); });
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
  if (!isArrayOf(n, 2)) n.expected("two positive numbers [width,height]");
  std::array<double, 2> pair{};
  std::size_t i = 0;
  n.forEachElement([&](const Node& e) { pair[i++] = readPositive(e); });
  return pair;
}

std::array<int, 2> readIntegerPair(const Node& n, int lo, int hi) {
  if (!isArrayOf(n, 2)) n.expected("two integers [nX,nY]");
  std::array<int, 2> pair{};
  std::size_t i = 0;
  n.forEachElement([&](const Node& e) { pair[i++] = readInteger(e, lo, hi); });
  return pair;
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
