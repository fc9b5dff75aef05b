// Stage 1 (point(t) is the course's stage-3 getPoint): Ray normalises its direction.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "primitives/Ray.h"

namespace rt {
namespace {

TEST(RayTests, directionIsNormalised) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a non-unit direction is stored as the unit vector (3,4,0)/5
  const Ray ray(Point(1, 2, 3), Vector(3, 4, 0));
  EXPECT_NEAR(ray.direction().x(), 0.6, 1e-15);
  EXPECT_NEAR(ray.direction().y(), 0.8, 1e-15);
  EXPECT_EQ(ray.direction().z(), 0.0);
  EXPECT_NEAR(ray.direction().length(), 1.0, 1e-15);
  EXPECT_EQ(ray.head(), Point(1, 2, 3));
  // TC02: a general direction: unit length, same direction as given
  const Ray ray2(Point(0, 0, 0), Vector(-1, 2, -3));
  EXPECT_NEAR(ray2.direction().length(), 1.0, 1e-15);
  EXPECT_NEAR(ray2.direction().dot(Vector(-1, 2, -3)), std::sqrt(14.0), 1e-12);
  // =============== Boundary Values Tests ==================
  // TC11: an already-unit direction is unchanged
  EXPECT_EQ(Ray(Point(0, 0, 0), Vector(0, 0, 1)).direction(), Vector(0, 0, 1));
  // TC12: a tiny (but non-zero) direction is normalised too
  EXPECT_NEAR(Ray(Point(0, 0, 0), Vector(1e-9, 1e-9, 0)).direction().length(), 1.0, 1e-12);
}

TEST(RayTests, point) {
  const Ray ray(Point(0, 0, 0), Vector(1, 0, 0));
  // ============ Equivalence Partitions Tests ==============
  // TC01: positive parameter
  EXPECT_EQ(ray.point(1), Point(1, 0, 0));
  // TC02: negative parameter (behind the head)
  EXPECT_EQ(ray.point(-1), Point(-1, 0, 0));
  // TC03: a non-unit given direction: t is the distance along the normalised direction
  const Ray diagonal(Point(1, 1, 1), Vector(0, 3, 4));
  EXPECT_EQ(diagonal.point(5), Point(1, 4, 5));
  // =============== Boundary Values Tests ==================
  // TC11: t = 0 is the head itself
  EXPECT_EQ(ray.point(0), ray.head());
  EXPECT_EQ(diagonal.point(0), Point(1, 1, 1));
}

TEST(RayTests, equality) {
  // TC01: same head and same direction after normalisation are equal
  EXPECT_TRUE(Ray(Point(1, 2, 3), Vector(0, 0, 2)) == Ray(Point(1, 2, 3), Vector(0, 0, 5)));
  // TC02: different head, or opposite direction, are different rays
  EXPECT_FALSE(Ray(Point(1, 2, 3), Vector(0, 0, 1)) == Ray(Point(1, 2, 4), Vector(0, 0, 1)));
  EXPECT_FALSE(Ray(Point(1, 2, 3), Vector(0, 0, 1)) == Ray(Point(1, 2, 3), Vector(0, 0, -1)));
}

TEST(RayTests, printing) {
  // TC01: the printed form names the head and the (normalised) direction
  std::ostringstream os;
  os << Ray(Point(1, 2, 3), Vector(0, 0, 2));
  EXPECT_NE(os.str().find("(1,2,3)"), std::string::npos) << os.str();
  EXPECT_NE(os.str().find("(0,0,1)"), std::string::npos) << os.str();
}

}  // namespace
}  // namespace rt
