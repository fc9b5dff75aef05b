#pragma once
/// @file Util.h
/// Numeric helpers with the course's semantics.

#include <cmath>

namespace rt {

/// The course's zero threshold: a double is "zero" when its binary exponent is below -40,
/// that is when |x| < 2^-40 (about 9.09e-13).
inline constexpr double ZERO_THRESHOLD = 0x1p-40;

/// True when |x| is below the course's threshold 2^-40.
inline bool isZero(double x) noexcept { return std::abs(x) < ZERO_THRESHOLD; }

/// Returns 0 for a number that isZero, else the number itself. Used before sign tests so that
/// rounding noise never decides a sign.
inline double alignZero(double x) noexcept { return isZero(x) ? 0.0 : x; }

}  // namespace rt
