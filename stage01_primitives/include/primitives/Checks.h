#pragma once
/// @file Checks.h
/// Argument checks for constructors and setters, shared by every stage, so that a rule ("a
/// radius is a positive finite number") is written once and its message reads the same
/// everywhere: "<operation>: <argument> must be ..., got <value>".
///
/// These run when a scene is built, never on the per-ray path (see stage05's README, "Nothing
/// throws per ray").

#include <string_view>

#include "primitives/Double3.h"

namespace rt {

/// @returns value when it is a finite number > 0.
/// @throws std::invalid_argument "<operation>: <argument> must be a positive finite number,
///         got <value>" otherwise (NaN, infinity, zero and negative numbers).
double requirePositive(double value, std::string_view operation, std::string_view argument);

/// @returns value when it is a finite number >= 0.
/// @throws std::invalid_argument "<operation>: <argument> must be a non-negative finite number,
///         got <value>" otherwise (NaN, infinity and negative numbers).
double requireNonNegative(double value, std::string_view operation, std::string_view argument);

/// @returns value when lo <= value <= hi (a count, a grid size, a depth).
/// @throws std::invalid_argument "<operation>: <argument> must be between <lo> and <hi>, got
///         <value>" otherwise.
long requireBetween(long value, long lo, long hi, std::string_view operation,
                    std::string_view argument);

/// @returns value when all three components are finite.
/// @throws std::invalid_argument "<operation>: <argument> must be finite, got (x,y,z)" for a
///         component that is infinite or NaN (including one that overflowed while the value was
///         derived).
const Double3& requireFinite(const Double3& value, std::string_view operation,
                             std::string_view argument);

}  // namespace rt
