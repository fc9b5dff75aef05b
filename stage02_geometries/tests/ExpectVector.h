#pragma once
// Test helpers for stage 2: component-wise comparison of a vector with hand-computed values, and
// the axis the tube and cylinder tests share.

#include <gtest/gtest.h>

#include "primitives/Point.h"
#include "primitives/Ray.h"
#include "primitives/Vector.h"

namespace rt::test {

/// Expects v == (x,y,z) component-wise within tol.
inline void expectVector(const Vector& v, double x, double y, double z, double tol = 1e-12) {
  EXPECT_NEAR(v.x(), x, tol);
  EXPECT_NEAR(v.y(), y, tol);
  EXPECT_NEAR(v.z(), z, tol);
}

/// The Z axis from the origin: the axis of the tubes and cylinders in the stage's tests.
inline const Ray kZAxis(Point(0, 0, 0), Vector(0, 0, 1));

}  // namespace rt::test
