#pragma once
/// @file Integers.h
/// The one rule for integers, wherever a user writes one: a scene file's value
/// ("resolution": [1e3, 800]) and an option's value (`rt render x --width 1e3`) alike.
///
/// An integer is an integral number written in any JSON number form: 100, 1e2, 100.0 and
/// 1.0e2 are all 100. Anything else is refused: 100.5, "100", 0x64, +100, 0100 (JSON has no
/// leading zeros, so 0100 is not a number) and numbers outside the range, however written.

#include <climits>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace rt {

/// The value as an int when it is an integral JSON number in [lo, hi]; nullopt otherwise.
std::optional<int> integerIn(const nlohmann::ordered_json& value, int lo, int hi);

/// The text as an int when it is exactly one JSON number (no white space around it) that is
/// integral and in [lo, hi]; nullopt otherwise.
std::optional<int> integerInText(std::string_view text, int lo, int hi);

/// What the messages call an integer in [lo, hi]: "an integer from 1 to 32768", and with
/// hi = INT_MAX "an integer from 0 to 2147483647" (a larger value is refused, so it is said).
std::string integerDescription(int lo, int hi = INT_MAX);

}  // namespace rt
