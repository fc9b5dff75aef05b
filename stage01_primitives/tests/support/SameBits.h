#pragma once
/// @file SameBits.h
/// "Bit for bit" in the tests: the same IEEE bits. Not the course's == of vectors and colours
/// (which accepts 2^-40 per component), nor the doubles' own == (0 and -0 are equal there, and a
/// NaN equals nothing): a result that moved by one rounding step, or changed its sign of zero,
/// is not the same.

#include <bit>
#include <cstdint>

#include "primitives/Color.h"
#include "primitives/Double3.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt::test {

inline bool sameBits(double a, double b) noexcept {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
inline bool sameBits(const Double3& a, const Double3& b) noexcept {
  return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}
inline bool sameBits(const Vector& a, const Vector& b) noexcept {
  return sameBits(a.xyz(), b.xyz());
}
inline bool sameBits(const Point& a, const Point& b) noexcept { return sameBits(a.xyz(), b.xyz()); }
inline bool sameBits(const Color& a, const Color& b) noexcept { return sameBits(a.rgb(), b.rgb()); }

}  // namespace rt::test
