// Camera transformations (the course's stage-4 bonus): move, rotate around vTo, re-aim at a
// target. Every case checks the resulting frame and location against hand-computed values.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "camera/Camera.h"

namespace rt {
namespace {

constexpr double EPS = 1e-12;

void expectVectorNear(const Vector& actual, double x, double y, double z) {
  EXPECT_NEAR(actual.x(), x, EPS) << actual;
  EXPECT_NEAR(actual.y(), y, EPS) << actual;
  EXPECT_NEAR(actual.z(), z, EPS) << actual;
}

/// At the origin looking along -Z, up +Y, so vRight = +X.
Camera standardCamera() {
  return Camera::builder()
      .setLocation(Point::ZERO)
      .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
      .setVpSize(2, 2)
      .setVpDistance(1)
      .setResolution(2, 2)
      .build();
}

void expectOrthonormalFrame(const Camera& c) {
  EXPECT_NEAR(c.vTo().length(), 1, EPS);
  EXPECT_NEAR(c.vUp().length(), 1, EPS);
  EXPECT_NEAR(c.vRight().length(), 1, EPS);
  EXPECT_NEAR(c.vTo().dot(c.vUp()), 0, EPS);
  EXPECT_NEAR(c.vTo().dot(c.vRight()), 0, EPS);
  EXPECT_NEAR(c.vUp().dot(c.vRight()), 0, EPS);
  // right-handed: vRight = vTo x vUp
  const Vector r = c.vTo().cross(c.vUp());
  expectVectorNear(c.vRight(), r.x(), r.y(), r.z());
}

TEST(CameraTransformTests, Move) {
  Camera camera = standardCamera();
  // ============ Equivalence Partitions Tests ==============
  // TC01: the location moves by the offset, the frame stays
  camera.move(Vector(1, 2, 3));
  EXPECT_EQ(camera.location(), Point(1, 2, 3));
  expectVectorNear(camera.vTo(), 0, 0, -1);
  expectVectorNear(camera.vUp(), 0, 1, 0);
  expectVectorNear(camera.vRight(), 1, 0, 0);
  // the centre ray now starts at the new location, same direction
  const Ray centre = camera.constructRay(3, 3, 1, 1);
  EXPECT_EQ(centre.head(), Point(1, 2, 3));
  expectVectorNear(centre.direction(), 0, 0, -1);
  // TC02: moves add up
  camera.move(Vector(-1, -2, 7));
  EXPECT_EQ(camera.location(), Point(0, 0, 10));
}

TEST(CameraTransformTests, RotateQuarterTurns) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: +90 degrees, counter-clockwise seen from behind: vUp -> old -vRight, vRight -> old vUp
  Camera camera = standardCamera();
  camera.rotate(90);
  expectVectorNear(camera.vTo(), 0, 0, -1);
  expectVectorNear(camera.vUp(), -1, 0, 0);
  expectVectorNear(camera.vRight(), 0, 1, 0);
  expectOrthonormalFrame(camera);
  // the top-left pixel's ray now leans towards the old bottom-left: pixel (0,0) of 2x2 on a
  // 2x2 plane is pC - 0.5·vRight + 0.5·vUp = (0,0,-1) - (0,0.5,0) + (-0.5,0,0)
  const Ray topLeft = camera.constructRay(2, 2, 0, 0);
  const Vector expected = Vector(-0.5, -0.5, -1).normalized();
  expectVectorNear(topLeft.direction(), expected.x(), expected.y(), expected.z());

  // TC02: -90 degrees (clockwise): vUp -> old vRight, vRight -> old -vUp
  Camera clockwise = standardCamera();
  clockwise.rotate(-90);
  expectVectorNear(clockwise.vUp(), 1, 0, 0);
  expectVectorNear(clockwise.vRight(), 0, -1, 0);

  // =============== Boundary Values Tests ==================
  // TC11: 180 degrees turns the picture upside down
  Camera flipped = standardCamera();
  flipped.rotate(180);
  expectVectorNear(flipped.vUp(), 0, -1, 0);
  expectVectorNear(flipped.vRight(), -1, 0, 0);
  // TC12: 0 degrees changes nothing
  Camera same = standardCamera();
  same.rotate(0);
  expectVectorNear(same.vUp(), 0, 1, 0);
  expectVectorNear(same.vRight(), 1, 0, 0);
  // TC13: a full turn (and four quarter turns) gives back the exact frame
  Camera full = standardCamera();
  full.rotate(360);
  EXPECT_EQ(full.vUp().xyz().y, 1.0);
  full.rotate(90).rotate(90).rotate(90).rotate(90);
  EXPECT_EQ(full.vUp().xyz().x, 0.0);
  EXPECT_EQ(full.vUp().xyz().y, 1.0);
  EXPECT_EQ(full.vRight().xyz().x, 1.0);
  // TC14: -270 is the same as +90
  Camera minus270 = standardCamera();
  minus270.rotate(-270);
  expectVectorNear(minus270.vUp(), -1, 0, 0);
  expectVectorNear(minus270.vRight(), 0, 1, 0);
}

TEST(CameraTransformTests, RotateArbitraryAngle) {
  // TC03: 30 degrees: vUp' = cos30·vUp - sin30·vRight = (-1/2, √3/2, 0),
  //                   vRight' = cos30·vRight + sin30·vUp = (√3/2, 1/2, 0)
  Camera camera = standardCamera();
  camera.rotate(30);
  expectVectorNear(camera.vTo(), 0, 0, -1);
  expectVectorNear(camera.vUp(), -0.5, std::sqrt(3.0) / 2, 0);
  expectVectorNear(camera.vRight(), std::sqrt(3.0) / 2, 0.5, 0);
  expectOrthonormalFrame(camera);
  // TC04: rotations add up: 30 + 60 = 90
  camera.rotate(60);
  expectVectorNear(camera.vUp(), -1, 0, 0);
  expectVectorNear(camera.vRight(), 0, 1, 0);
  // TC05: a tilted frame (looking at (1,1,-1) from the origin): vTo is the axis, unchanged
  Camera tilted = standardCamera();
  tilted.lookAt(Point(1, 1, -1)).rotate(45);
  const Vector to = Vector(1, 1, -1).normalized();
  expectVectorNear(tilted.vTo(), to.x(), to.y(), to.z());
  expectOrthonormalFrame(tilted);
  // TC11: a non-finite angle
  EXPECT_THROW(standardCamera().rotate(std::nan("")), std::invalid_argument);
  // TC12: the centre ray is the rotation axis: unchanged
  Camera centre = standardCamera();
  centre.rotate(37);
  expectVectorNear(centre.constructRay(3, 3, 1, 1).direction(), 0, 0, -1);
}

TEST(CameraTransformTests, LookAt) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: turn to look along +X: vTo = X, vRight = X x Y = Z, vUp = Z x X = Y
  Camera camera = standardCamera();
  camera.lookAt(Point(10, 0, 0));
  expectVectorNear(camera.vTo(), 1, 0, 0);
  expectVectorNear(camera.vRight(), 0, 0, 1);
  expectVectorNear(camera.vUp(), 0, 1, 0);
  // TC02: look up at 45 degrees: vTo = (0,1,-1)/√2, vRight = X, vUp = (0,1,1)/√2
  Camera up = standardCamera();
  up.lookAt(Point(0, 10, -10));
  const double h = std::sqrt(0.5);
  expectVectorNear(up.vTo(), 0, h, -h);
  expectVectorNear(up.vRight(), 1, 0, 0);
  expectVectorNear(up.vUp(), 0, h, h);
  expectOrthonormalFrame(up);
  // TC03: turn to +X (vUp stays Y), move, then re-aim at the origin from (0,0,10): back to the
  // standard frame
  Camera moved = standardCamera();
  moved.lookAt(Point(10, 0, 0)).move(Vector(0, 0, 10)).lookAt(Point::ZERO);
  EXPECT_EQ(moved.location(), Point(0, 0, 10));
  expectVectorNear(moved.vTo(), 0, 0, -1);
  expectVectorNear(moved.vUp(), 0, 1, 0);
  expectVectorNear(moved.vRight(), 1, 0, 0);
  // TC05: each re-aim keeps the previous vUp, not +Y. Looking at (5,5,5) from the origin:
  // vTo = (1,1,1)/√3, vRight = norm(vTo x Y) = (-1,0,1)/√2, vUp = vRight x vTo = (-1,2,-1)/√6.
  // Then from (0,0,10) at the origin: vTo = -Z, vRight = norm(-Z x (-1,2,-1)) = (2,1,0)/√5,
  // vUp = vRight x vTo = (-1,2,0)/√5: the camera is rolled, as close to the old up as it gets.
  Camera diagonal = standardCamera();
  diagonal.lookAt(Point(5, 5, 5));
  const double s3 = std::sqrt(3.0), s2 = std::sqrt(2.0), s6 = std::sqrt(6.0), s5 = std::sqrt(5.0);
  expectVectorNear(diagonal.vTo(), 1 / s3, 1 / s3, 1 / s3);
  expectVectorNear(diagonal.vRight(), -1 / s2, 0, 1 / s2);
  expectVectorNear(diagonal.vUp(), -1 / s6, 2 / s6, -1 / s6);
  diagonal.move(Vector(0, 0, 10)).lookAt(Point::ZERO);
  expectVectorNear(diagonal.vTo(), 0, 0, -1);
  expectVectorNear(diagonal.vRight(), 2 / s5, 1 / s5, 0);
  expectVectorNear(diagonal.vUp(), -1 / s5, 2 / s5, 0);
  // TC04: the up of a rolled camera is kept as close as possible: after rotate(90) vUp = -X;
  // looking at (0,10,-10) now keeps up in the x-z plane: vRight = vTo x (-X)
  Camera rolled = standardCamera();
  rolled.rotate(90).lookAt(Point(0, 10, -10));
  expectVectorNear(rolled.vTo(), 0, h, -h);
  expectVectorNear(rolled.vUp(), -1, 0, 0);
  expectVectorNear(rolled.vRight(), 0, h, h);

  // =============== Boundary Values Tests ==================
  // TC11: the target is the location
  EXPECT_THROW(standardCamera().lookAt(Point::ZERO), std::invalid_argument);
  // TC12: the target lies along the current vUp (no right vector)
  EXPECT_THROW(standardCamera().lookAt(Point(0, 7, 0)), std::invalid_argument);
  // TC13: ... or along -vUp
  EXPECT_THROW(standardCamera().lookAt(Point(0, -7, 0)), std::invalid_argument);
  // TC14: a failed lookAt leaves the camera unchanged
  Camera kept = standardCamera();
  EXPECT_THROW(kept.lookAt(Point(0, 7, 0)), std::invalid_argument);
  expectVectorNear(kept.vTo(), 0, 0, -1);
  expectVectorNear(kept.vUp(), 0, 1, 0);
  // TC15: looking straight back (target behind) is allowed: vTo = +Z, vRight = -X
  Camera back = standardCamera();
  back.lookAt(Point(0, 0, 5));
  expectVectorNear(back.vTo(), 0, 0, 1);
  expectVectorNear(back.vUp(), 0, 1, 0);
  expectVectorNear(back.vRight(), -1, 0, 0);
}

}  // namespace
}  // namespace rt
