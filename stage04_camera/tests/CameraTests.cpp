// Camera::constructRay: the course's CameraTests (EP01, BV01..BV06) and the look-at cases of the
// course year 5785 (EP01, EP02, BV01).

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "camera/Camera.h"

namespace rt {
namespace {

constexpr double EPS = 1e-12;

void expectVectorNear(const Vector& actual, const Vector& expected) {
  EXPECT_NEAR(actual.x(), expected.x(), EPS) << "actual " << actual << ", expected " << expected;
  EXPECT_NEAR(actual.y(), expected.y(), EPS) << "actual " << actual << ", expected " << expected;
  EXPECT_NEAR(actual.z(), expected.z(), EPS) << "actual " << actual << ", expected " << expected;
}

void expectRay(const Ray& actual, const Point& head, const Vector& direction) {
  EXPECT_EQ(actual.head(), head) << actual;
  expectVectorNear(actual.direction(), direction.normalized());
}

/// The course's camera: at the origin, vTo = (0,0,-1), vUp = (0,-1,0) (so vRight = (-1,0,0)),
/// distance 10. The resolution given to the builder does not matter: constructRay takes nX, nY.
Camera::Builder courseBuilder() {
  return Camera::builder()
      .setLocation(Point::ZERO)
      .setDirection(Vector(0, 0, -1), Vector(0, -1, 0))
      .setVpDistance(10)
      .setResolution(1, 1);
}

TEST(CameraTests, FrameOfTheCourseCamera) {
  // TC01: vRight = vTo x vUp = (0,0,-1) x (0,-1,0) = (-1,0,0)
  const Camera camera = courseBuilder().setVpSize(8, 8).build();
  EXPECT_EQ(camera.vTo(), Vector(0, 0, -1));
  EXPECT_EQ(camera.vUp(), Vector(0, -1, 0));
  EXPECT_EQ(camera.vRight(), Vector(-1, 0, 0));
}

TEST(CameraTests, ConstructRayFourByFour) {
  const Camera camera = courseBuilder().setVpSize(8, 8).build();
  // ============ Equivalence Partitions Tests ==============
  // EP01: 4x4 inside (1,1)
  expectRay(camera.constructRay(4, 4, 1, 1), Point::ZERO, Vector(1, -1, -10));

  // =============== Boundary Values Tests ==================
  // BV01: 4x4 corner (0,0)
  expectRay(camera.constructRay(4, 4, 0, 0), Point::ZERO, Vector(3, -3, -10));
  // BV02: 4x4 side (j=1, i=0)
  expectRay(camera.constructRay(4, 4, 1, 0), Point::ZERO, Vector(1, -3, -10));
}

TEST(CameraTests, ConstructRayThreeByThree) {
  const Camera camera = courseBuilder().setVpSize(6, 6).build();
  // =============== Boundary Values Tests ==================
  // BV03: 3x3 centre (1,1)
  expectRay(camera.constructRay(3, 3, 1, 1), Point::ZERO, Vector(0, 0, -10));
  // BV04: 3x3 centre of the upper side (j=1, i=0)
  expectRay(camera.constructRay(3, 3, 1, 0), Point::ZERO, Vector(0, -2, -10));
  // BV05: 3x3 centre of the left side (j=0, i=1)
  expectRay(camera.constructRay(3, 3, 0, 1), Point::ZERO, Vector(2, 0, -10));
  // BV06: 3x3 corner (0,0)
  expectRay(camera.constructRay(3, 3, 0, 0), Point::ZERO, Vector(2, -2, -10));
}

TEST(CameraTests, ConstructRayFromAMovedLocationAndRectangularPlane) {
  // TC02: the head is the location; pixel sizes differ per axis (w/nX = 2, h/nY = 1)
  const Camera camera = Camera::builder()
                            .setLocation(Point(1, 2, 3))
                            .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
                            .setVpDistance(5)
                            .setVpSize(8, 2)
                            .setResolution(4, 2)
                            .build();
  // vRight = (0,0,-1) x (0,1,0) = (1,0,0); pixel (3,1): xJ = 1.5·2 = 3, yI = -0.5·1 = -0.5
  expectRay(camera.constructRay(4, 2, 3, 1), Point(1, 2, 3), Vector(3, -0.5, -5));
}

TEST(CameraTests, ConstructRayRejectsAnEmptyGrid) {
  const Camera camera = courseBuilder().setVpSize(6, 6).build();
  // TC11: nX = 0
  EXPECT_THROW((void)camera.constructRay(0, 3, 0, 0), std::invalid_argument);
  // TC12: nY = -1
  EXPECT_THROW((void)camera.constructRay(3, -1, 0, 0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Look-at direction (5785 testBuilder): VP 4x4, resolution 2x2, distance 10, location origin.

Camera::Builder lookAtBuilder() {
  return Camera::builder()
      .setLocation(Point::ZERO)
      .setVpSize(4, 4)
      .setVpDistance(10)
      .setResolution(2, 2);
}

TEST(CameraTests, LookAtTarget) {
  // ============ Equivalence Partitions Tests ==============
  // EP01: target (10,-10,0) with the default up Y
  const Camera camera = lookAtBuilder().setDirection(Point(10, -10, 0)).build();
  expectVectorNear(camera.vTo(), Vector(1, -1, 0).normalized());
  expectVectorNear(camera.vRight(), Vector(0, 0, 1));
  expectVectorNear(camera.vUp(), Vector(1, 1, 0).normalized());
  // ray (0,0) passes through the view-plane centre + vUp - vRight
  //   = 10·(1,-1,0)/√2 + (1,1,0)/√2 - (0,0,1) = (11/√2, -9/√2, -1)
  expectRay(camera.constructRay(2, 2, 0, 0), Point::ZERO,
            Vector(11 / std::sqrt(2.0), -9 / std::sqrt(2.0), -1));
}

TEST(CameraTests, LookAtTargetWithUp) {
  // EP02: target (0,5,0) with up (0,1,1), not orthogonal to vTo -> vTo = Y, vRight = X, vUp = Z
  const Camera camera = lookAtBuilder().setDirection(Point(0, 5, 0), Vector(0, 1, 1)).build();
  expectVectorNear(camera.vTo(), Vector(0, 1, 0));
  expectVectorNear(camera.vRight(), Vector(1, 0, 0));
  expectVectorNear(camera.vUp(), Vector(0, 0, 1));
  // ray (0,0) passes through (0,10,0) + Z - X
  expectRay(camera.constructRay(2, 2, 0, 0), Point::ZERO, Vector(-1, 10, 1));
}

TEST(CameraTests, LookAtTargetAlongTheUpAxis) {
  // =============== Boundary Values Tests ==================
  // BV01: target on the Y axis without up: vTo is parallel to the default up
  Camera::Builder builder = lookAtBuilder().setDirection(Point(0, 5, 0));
  EXPECT_THROW((void)builder.build(), std::invalid_argument);
  // BV02: target below, on the -Y axis (antiparallel to up)
  builder.setDirection(Point(0, -3, 0));
  EXPECT_THROW((void)builder.build(), std::invalid_argument);
  // BV03: target is the location itself
  builder.setDirection(Point::ZERO, Vector(0, 0, 1));
  try {
    (void)builder.build();
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("target (0,0,0)"), std::string::npos) << e.what();
  }
}

TEST(CameraTests, LookAtResolvedAtBuildWithTheFinalLocation) {
  // TC03: the location set after the target still counts (resolved at build)
  const Camera camera = Camera::builder()
                            .setDirection(Point(0, 0, -10))
                            .setLocation(Point(0, 0, 10))
                            .setVpSize(4, 4)
                            .setVpDistance(10)
                            .setResolution(2, 2)
                            .build();
  expectVectorNear(camera.vTo(), Vector(0, 0, -1));
  expectVectorNear(camera.vUp(), Vector(0, 1, 0));
  expectVectorNear(camera.vRight(), Vector(1, 0, 0));
}

}  // namespace
}  // namespace rt
