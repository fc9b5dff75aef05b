#pragma once
// Internal to mini1's tests: "bit for bit" comparisons of colours.

#include <cstring>

#include "primitives/Color.h"

namespace rt::test {

/// True when a and b hold the same bits (unlike ==, 0 and -0 differ).
inline bool sameBits(const Color& a, const Color& b) {
  return std::memcmp(&a.rgb(), &b.rgb(), sizeof(Double3)) == 0;
}

}  // namespace rt::test
