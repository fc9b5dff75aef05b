#pragma once
/// @file Values.h
/// Strict parsing of option values: the whole text must be the number, and every error names the
/// option and quotes what was given ("--width: expected an integer from 1 to 32768, got '12x'").

#include <array>
#include <string>
#include <string_view>

#include "primitives/Double3.h"

namespace rt::cli {

/// An integer in [min, max] by the app's one rule for integers (common/Integers.h: 1e3 and
/// 1000.0 are 1000). @throws UsageError "WHAT: " + integerError(text, min, max).
int parseInt(std::string_view text, std::string_view what, int min, int max);

/// "expected an integer from 1 to 32768, got '12x'".
std::string integerError(std::string_view text, int min, int max);

/// A finite number. @throws UsageError.
double parseDouble(std::string_view text, std::string_view what);

/// Exactly n comma-separated finite numbers, "-1,0.5,-2" (no spaces). @throws UsageError.
template <std::size_t N>
std::array<double, N> parseNumbers(std::string_view text, std::string_view what);

/// "X,Y,Z" as a Double3. @throws UsageError.
Double3 parseTriple(std::string_view text, std::string_view what);

/// "X,Y": two integers, X in [0, maxX], Y in [0, maxY]. @throws UsageError.
std::array<int, 2> parseIntPair(std::string_view text, std::string_view what, int maxX, int maxY);

}  // namespace rt::cli
