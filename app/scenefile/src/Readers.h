#pragma once
/// @file Readers.h
/// Readers of the format's value types. Each checks its node and returns the value, or throws
/// a SceneError at the node: "expected WHAT, got VALUE".

#include <array>
#include <climits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "Node.h"
#include "primitives/Color.h"
#include "primitives/Double3.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"
#include "scenefile/SceneFile.h"

namespace rt::scenefile {

/// Any finite number. (The first pass already rejects 1e999; this guards defaults and DOMs.)
double readNumber(const Node& n);
/// A finite number > 0.
double readPositive(const Node& n);
/// A finite number >= 0.
double readNonNegative(const Node& n);
/// A finite number in [lo, hi].
double readNumberIn(const Node& n, double lo, double hi);
/// The largest colour component and coefficient a file may give: far beyond any light (the
/// course's scale is 0-255), and low enough that the render's products and sums of them stay
/// finite (10^12 · 2^40, an intensity over the smallest kC, times a coefficient, about 10^36 a
/// light) where a value near 1e308 overflowed, and an infinite colour that met a zero turned into
/// NaN and the pixel into a wrong colour. Not a proof for every scene: kR and kT above 1 multiply
/// a path's weight at every level, so at a large maxLevel they can still overflow it.
inline constexpr double MAX_COLOR_VALUE = 1e12;
/// The smallest constant attenuation kC: the course's zero, 2^-40 (below it kC is 0, and the
/// intensity at the light infinite).
inline constexpr double MIN_KC = 0x1p-40;
/// kC, at least MIN_KC.
double readConstantAttenuation(const Node& n);
/// An integral number in [lo, hi] (1e2 and 100.0 count as 100): the app's one rule for
/// integers, common/Integers.h.
int readInteger(const Node& n, int lo, int hi = INT_MAX);
std::string readString(const Node& n);
/// true or false.
bool readBoolean(const Node& n);
/// A finite number in [-MAX_COORDINATE, MAX_COORDINATE] (scenefile/SceneFile.h).
double readCoordinate(const Node& n);
/// A finite number in (0, MAX_COORDINATE]: a radius or a height ("a positive number" below).
double readLength(const Node& n);
/// [x,y,z] of coordinates (readCoordinate).
Point readPoint(const Node& n);
/// [x,y,z] of finite numbers, not the zero vector, of finite length.
Vector readDirection(const Node& n);
/// [r,g,b] of non-negative numbers (the course's 0-255 scale; brighter than 255 allowed).
Color readColor(const Node& n);
/// A coefficient: a non-negative number (the same for r, g and b) or [r,g,b].
Double3 readCoefficient(const Node& n);
/// An array of points, with at least minCount and at most maxCount of them.
std::vector<Point> readPoints(const Node& n, std::size_t minCount, std::size_t maxCount);
/// [a,b] of positive numbers.
std::array<double, 2> readPositivePair(const Node& n);
/// [a,b] of integers in [lo, hi].
std::array<int, 2> readIntegerPair(const Node& n, int lo, int hi);
/// One of the strings in choices; otherwise "expected WHAT (a, b, c), got "x"; did you mean
/// 'y'?".
std::string readChoice(const Node& n, std::string_view what,
                       std::span<const std::string_view> choices);

/// "a, b, c"; after 12 names, "and N more".
std::string joinNames(std::span<const std::string_view> names);

}  // namespace rt::scenefile
