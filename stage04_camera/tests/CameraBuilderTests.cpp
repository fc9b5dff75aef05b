// Camera::Builder validation: every setter rejects bad values with a message naming the
// argument and the value; build() names the first missing field. Also CameraSpec::builder.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "camera/Camera.h"
#include "camera/CameraSpec.h"
#include "camera/Image.h"

namespace rt {
namespace {

/// Runs f, expects exception E, and checks that its message contains every given fragment.
template <typename E, typename F>
void expectThrowWith(F&& f, std::initializer_list<const char*> fragments) {
  try {
    f();
    ADD_FAILURE() << "no exception thrown";
  } catch (const E& e) {
    const std::string what = e.what();
    for (const char* fragment : fragments)
      EXPECT_NE(what.find(fragment), std::string::npos)
          << "message \"" << what << "\" lacks \"" << fragment << "\"";
  }
}

Camera::Builder complete() {
  return Camera::builder()
      .setLocation(Point::ZERO)
      .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
      .setVpSize(3, 2)
      .setVpDistance(1)
      .setResolution(30, 20);
}

TEST(CameraBuilderTests, CompleteBuilderBuilds) {
  // TC01: every field set -> a camera with these values and an image of the resolution
  const Camera camera = complete().build();
  EXPECT_EQ(camera.location(), Point::ZERO);
  EXPECT_DOUBLE_EQ(camera.vpWidth(), 3);
  EXPECT_DOUBLE_EQ(camera.vpHeight(), 2);
  EXPECT_DOUBLE_EQ(camera.vpDistance(), 1);
  EXPECT_EQ(camera.nX(), 30);
  EXPECT_EQ(camera.nY(), 20);
  EXPECT_EQ(camera.image().nX(), 30);
  EXPECT_EQ(camera.image().nY(), 20);
  EXPECT_EQ(camera.vRight(), Vector(1, 0, 0));
}

TEST(CameraBuilderTests, DirectionIsNormalised) {
  // TC02: vTo (0,0,-5) and vUp (0,2,0) are stored as unit vectors
  const Camera camera = complete().setDirection(Vector(0, 0, -5), Vector(0, 2, 0)).build();
  EXPECT_EQ(camera.vTo(), Vector(0, 0, -1));
  EXPECT_EQ(camera.vUp(), Vector(0, 1, 0));
  EXPECT_EQ(camera.vRight(), Vector(1, 0, 0));
}

TEST(CameraBuilderTests, DirectionMustBeOrthogonal) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: clearly not orthogonal (45 degrees)
  expectThrowWith<std::invalid_argument>(
      [] { Camera::builder().setDirection(Vector(0, 0, -1), Vector(0, 1, 1)); },
      {"vTo (0,0,-1)", "vUp (0,1,1)", "orthogonal"});
  // =============== Boundary Values Tests ==================
  // TC11: parallel
  EXPECT_THROW(Camera::builder().setDirection(Vector(0, 0, -1), Vector(0, 0, 2)),
               std::invalid_argument);
  // TC12: off by 1e-9 in the dot product: not zero for isZero (threshold 2^-40)
  EXPECT_THROW(Camera::builder().setDirection(Vector(0, 0, -1), Vector(0, 1, 1e-9)),
               std::invalid_argument);
  // TC13: off by 1e-14: zero for isZero -> accepted
  EXPECT_NO_THROW(Camera::builder().setDirection(Vector(0, 0, -1), Vector(0, 1, 1e-14)));
}

TEST(CameraBuilderTests, VpSizeMustBePositive) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: negative width
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setVpSize(-2, 1); },
                                         {"width", "-2"});
  // TC02: negative height
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setVpSize(1, -3); },
                                         {"height", "-3"});
  // =============== Boundary Values Tests ==================
  // TC11: zero width
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setVpSize(0, 1); },
                                         {"width", "got 0"});
  // TC12: zero height
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setVpSize(1, 0); },
                                         {"height", "got 0"});
  // TC13: a width that alignZero makes zero
  EXPECT_THROW(Camera::builder().setVpSize(1e-13, 1), std::invalid_argument);
  // TC14: infinite and NaN sizes
  EXPECT_THROW(Camera::builder().setVpSize(std::numeric_limits<double>::infinity(), 1),
               std::invalid_argument);
  EXPECT_THROW(Camera::builder().setVpSize(1, std::nan("")), std::invalid_argument);
  // TC15: the smallest accepted size, just above the zero threshold
  EXPECT_NO_THROW(Camera::builder().setVpSize(1e-12, 1e-12));
}

TEST(CameraBuilderTests, VpDistanceMustBePositive) {
  // TC01: negative distance
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setVpDistance(-1); },
                                         {"distance", "-1"});
  // TC11: zero distance
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setVpDistance(0); },
                                         {"distance", "got 0"});
}

TEST(CameraBuilderTests, ResolutionBounds) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: negative nX
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setResolution(-4, 3); },
                                         {"nX", "-4"});
  // =============== Boundary Values Tests ==================
  // TC11: nX = 0
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setResolution(0, 3); },
                                         {"nX", "got 0"});
  // TC12: nY = 0
  expectThrowWith<std::invalid_argument>([] { Camera::builder().setResolution(3, 0); },
                                         {"nY", "got 0"});
  // TC13: 1x1 is the smallest image
  EXPECT_NO_THROW(Camera::builder().setResolution(1, 1));
  // TC14: one above the largest side
  expectThrowWith<std::invalid_argument>(
      [] { Camera::builder().setResolution(Image::MAX_SIDE + 1, 1); }, {"nX", "32769"});
  // TC15: the largest side is accepted by the setter (not allocated until build)
  EXPECT_NO_THROW(Camera::builder().setResolution(1, Image::MAX_SIDE));
}

TEST(CameraBuilderTests, MissingFieldIsNamed) {
  // TC01: nothing set -> the first field, location
  expectThrowWith<std::logic_error>([] { (void)Camera::builder().build(); },
                                    {"missing rendering data 'location'"});
  // TC02: only the direction missing
  expectThrowWith<std::logic_error>(
      [] {
        (void)Camera::builder()
            .setLocation(Point::ZERO)
            .setVpSize(1, 1)
            .setVpDistance(1)
            .setResolution(1, 1)
            .build();
      },
      {"'direction'"});
  // TC03: only the view-plane size missing
  expectThrowWith<std::logic_error>(
      [] {
        (void)Camera::builder()
            .setLocation(Point::ZERO)
            .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
            .setVpDistance(1)
            .setResolution(1, 1)
            .build();
      },
      {"'vpSize'"});
  // TC04: only the view-plane distance missing
  expectThrowWith<std::logic_error>(
      [] {
        (void)Camera::builder()
            .setLocation(Point::ZERO)
            .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
            .setVpSize(1, 1)
            .setResolution(1, 1)
            .build();
      },
      {"'vpDistance'"});
  // TC05: only the resolution missing
  expectThrowWith<std::logic_error>(
      [] {
        (void)Camera::builder()
            .setLocation(Point::ZERO)
            .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
            .setVpSize(1, 1)
            .setVpDistance(1)
            .build();
      },
      {"'resolution'"});
  // TC06: only the location missing (the others set): still location
  expectThrowWith<std::logic_error>(
      [] {
        (void)Camera::builder()
            .setDirection(Point(0, 0, -1))
            .setVpSize(1, 1)
            .setVpDistance(1)
            .setResolution(1, 1)
            .build();
      },
      {"'location'"});
}

TEST(CameraBuilderTests, LastDirectionWins) {
  // TC01: a look-at target replaces an earlier (vTo, vUp)
  const Camera aimed = complete().setDirection(Point(5, 0, 0)).build();
  EXPECT_EQ(aimed.vTo(), Vector(1, 0, 0));
  // TC02: (vTo, vUp) replaces an earlier target
  const Camera direct = complete()
                            .setDirection(Point(5, 0, 0))
                            .setDirection(Vector(0, -1, 0), Vector(1, 0, 0))
                            .build();
  EXPECT_EQ(direct.vTo(), Vector(0, -1, 0));
  EXPECT_EQ(direct.vUp(), Vector(1, 0, 0));
  // (0,-1,0) x (1,0,0) = (0,0,1)
  EXPECT_EQ(direct.vRight(), Vector(0, 0, 1));
}

TEST(CameraBuilderTests, MissingTracerAndWriterAreNotBuildErrors) {
  // TC01: they are checked when rendering and writing (see ImageTests), not at build
  EXPECT_NO_THROW((void)complete().build());
}

// ---------------------------------------------------------------------------------------------
// CameraSpec

TEST(CameraSpecTests, SpecWithVToBuildsTheSameCamera) {
  // TC01: location, to, up, view plane and resolution carried over
  CameraSpec spec;
  spec.location = Point(1, 2, 3);
  spec.to = Vector(0, 0, -2);
  spec.up = Vector(0, 1, 0);
  spec.vpWidth = 4;
  spec.vpHeight = 3;
  spec.vpDistance = 7;
  spec.nX = 40;
  spec.nY = 30;
  const Camera camera = spec.builder().build();
  EXPECT_EQ(camera.location(), Point(1, 2, 3));
  EXPECT_EQ(camera.vTo(), Vector(0, 0, -1));
  EXPECT_EQ(camera.vUp(), Vector(0, 1, 0));
  EXPECT_DOUBLE_EQ(camera.vpWidth(), 4);
  EXPECT_DOUBLE_EQ(camera.vpHeight(), 3);
  EXPECT_DOUBLE_EQ(camera.vpDistance(), 7);
  EXPECT_EQ(camera.nX(), 40);
  EXPECT_EQ(camera.nY(), 30);
}

TEST(CameraSpecTests, SpecWithTargetLooksAtIt) {
  // TC02: a target wins over to; up defaults to Y
  CameraSpec spec;
  spec.location = Point(0, 0, 10);
  spec.target = Point(0, 0, 0);
  spec.to = Vector(1, 0, 0);
  spec.vpWidth = spec.vpHeight = spec.vpDistance = 1;
  spec.nX = spec.nY = 1;
  const Camera camera = spec.builder().build();
  EXPECT_EQ(camera.vTo(), Vector(0, 0, -1));
  EXPECT_EQ(camera.vUp(), Vector(0, 1, 0));
}

TEST(CameraSpecTests, SpecWithoutDirectionIsMissingIt) {
  // TC11: neither target nor to -> build names the direction
  CameraSpec spec;
  spec.vpWidth = spec.vpHeight = spec.vpDistance = 1;
  spec.nX = spec.nY = 1;
  expectThrowWith<std::logic_error>([&] { (void)spec.builder().build(); }, {"'direction'"});
  // TC12: the default (zero) view plane is rejected by the builder's own check
  expectThrowWith<std::invalid_argument>([] { (void)CameraSpec{}.builder(); }, {"width"});
}

/// The fields both forms of CameraSpec::squareView set alike: location, up +Y, the square view
/// plane and the square image.
void expectSquareView(const CameraSpec& spec, const Point& location, double vpSize,
                      double vpDistance, int pixels) {
  EXPECT_EQ(spec.location, location);
  EXPECT_EQ(spec.up, Vector::AXIS_Y);
  EXPECT_EQ(spec.vpWidth, vpSize);
  EXPECT_EQ(spec.vpHeight, vpSize);
  EXPECT_EQ(spec.vpDistance, vpDistance);
  EXPECT_EQ(spec.nX, pixels);
  EXPECT_EQ(spec.nY, pixels);
}

TEST(CameraSpecTests, SquareView) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: looking along `to`: `to` set, no target
  const CameraSpec along = CameraSpec::squareView(Point(1, 2, 3), Vector(0, 0, -2), 4, 7, 40);
  expectSquareView(along, Point(1, 2, 3), 4, 7, 40);
  ASSERT_TRUE(along.to.has_value());
  EXPECT_EQ(*along.to, Vector(0, 0, -2));
  EXPECT_FALSE(along.target.has_value());
  // TC02: looking at a target: the target set, no `to`; the camera looks at it
  const CameraSpec at = CameraSpec::squareView(Point(0, 0, 10), Point(0, 0, 0), 2, 5, 3);
  expectSquareView(at, Point(0, 0, 10), 2, 5, 3);
  ASSERT_TRUE(at.target.has_value());
  EXPECT_EQ(*at.target, Point(0, 0, 0));
  EXPECT_FALSE(at.to.has_value());
  EXPECT_EQ(at.builder().build().vTo(), Vector(0, 0, -1));
}

}  // namespace
}  // namespace rt
