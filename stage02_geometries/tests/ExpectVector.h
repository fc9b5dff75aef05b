#pragma once
// Test helper for stage 2: component-wise comparison of a vector with hand-computed values.

#include <gtest/gtest.h>

#include "primitives/Vector.h"

namespace rt::test {

/// Expects v == (x,y,z) component-wise within tol.
inline void expectVector(const Vector& v, double x, double y, double z, double tol = 1e-12) {
  EXPECT_NEAR(v.x(), x, tol);
  EXPECT_NEAR(v.y(), y, tol);
  EXPECT_NEAR(v.z(), z, tol);
}

}  // namespace rt::test
