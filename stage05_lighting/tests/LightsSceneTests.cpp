// Stage 5: every LightsTests scene of the course (and the report authors' multi-light scenes),
// rendered by the Phong tracer at 101 x 101 pixels through the course's view plane (the course
// renders 500 x 500; 101 keeps the suite fast and gives a centre pixel whose ray is exactly the
// camera's axis). Each test checks values that a missing or wrong term would change:
//  - the centre pixel against a value worked out by hand below;
//  - pixels where one term is known to be the only one (dark side: emission exactly; outside
//    the spot's cone: the ambient exactly; misses: the background exactly);
//  - the highlight, which exceeds the diffuse-only colour by exactly the specular term;
//  - every pixel against an independent term-by-term oracle (ReferencePhong.h);
//  - a spot light against the point light with the same attenuation: exactly the cone factor.
//
// Hand values at the centre pixel:
//  Sphere scenes: the ray (0,0,-1) from (0,0,1000) hits the sphere (centre (0,0,-50), r 50) at
//  P = (0,0,0): n = (0,0,1), v = (0,0,-1), n·v = -1. The sphere light's direction (1,1,-0.5)
//  normalises to (2/3,2/3,-1/3), and P - (-50,-50,25) = (50,50,-25) = 75·(2/3,2/3,-1/3): every
//  sphere light has l = (2/3,2/3,-1/3) at P, n·l = -1/3, r = l - 2(l·n)n = (2/3,2/3,1/3),
//  -v·r = 1/3; the spot factor there is direction·l = 1. So the colour is
//      (0,0,127.5) + I_L · (0.5·(1/3) + 0.5·(1/3)^301)
//  with I_L = (800,500,0) / attenuation, attenuation 1 + 0.001·75 + kQ·75²:
//  directional 1; point (kQ 0.0002) 2.2; spot (kQ 0.0001) 1.6375; sharp spot (kQ 0.00004) 1.3.
//  Triangles scenes: the ray hits triangle 1 (plane z = -150, normal (0,0,-1)) at
//  P = (0,0,-150): n·v = 1. Directional: l = -(1,1,1)/sqrt(3), n·l = 1/sqrt(3),
//  r = (-1,-1,1)/sqrt(3), -v·r = 1/sqrt(3). Point and spot at (30,10,-100): P - L = (-30,-10,-50),
//  d = sqrt(3500), n·l = 50/sqrt(3500), r = (-30,-10,50)/sqrt(3500), -v·r = 50/sqrt(3500);
//  spot factor direction·l = (30+10+50)/(sqrt(3)·sqrt(3500)) = 90/sqrt(10500).
//  Colour: ambient (38.25,38.25,38.25) + I_L·(kD3·|n·l| + kS3·(-v·r)^301).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <set>
#include <span>
#include <stdexcept>
#include <string>

#include "ReferencePhong.h"
#include "TestSupport.h"
#include "camera/Camera.h"
#include "camera/ImageWriter.h"
#include "geometries/Sphere.h"
#include "lighting/CourseScenes.h"

namespace rt {
namespace {

using test::colorNear;
using test::EPS;
using test::referencePhong;
using test::ReferenceShading;
using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr int N = 101;  // pixels per side in these tests; the centre pixel is (50,50)
const Double3 KD3(0.2, 0.6, 0.4), KS3(0.2, 0.4, 0.3);
const Double3 SPHERE_EMISSION(0, 0, 127.5);
const Double3 TRIANGLES_AMBIENT(38.25, 38.25, 38.25);  // WHITE x 0.15

/// A scene rendered at n x n through its course camera's view plane.
struct Render {
  explicit Render(SceneSetup<LitScene> s, int n = N) : setup(std::move(s)), n_(n) {
    CameraSpec spec = setup.camera;
    spec.nX = spec.nY = n;
    rays = spec.builder().build();
    image = test::renderPhong(setup.scene, setup.camera, n, n).image();
  }
  const Color& pixel(int j, int i) const { return image.pixel(j, i); }
  Ray ray(int j, int i) const { return rays.constructRay(n_, n_, j, i); }
  ReferenceShading reference(int j, int i) const { return referencePhong(setup.scene, ray(j, i)); }
  /// Writes the image to test-images/stage05/<course image name>.png under the build directory.
  void save() const {
    const std::filesystem::path dir = std::filesystem::path("test-images") / "stage05";
    std::filesystem::create_directories(dir);
    PngImageWriter().write(image, (dir / (setup.scene.name + ".png")).string());
  }

  SceneSetup<LitScene> setup;
  Camera rays = Camera::builder()
                    .setLocation(Point::ZERO)
                    .setDirection(Vector(0, 0, -1), Vector::AXIS_Y)
                    .setVpSize(1, 1)
                    .setVpDistance(1)
                    .setResolution(1, 1)
                    .build();
  Image image;

 private:
  int n_;
};

/// Every pixel equals the oracle to 1e-9; returns how many pixels hit a shape.
int expectAllPixelsMatchReference(const Render& r, int n = N) {
  int hits = 0, mismatches = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const ReferenceShading ref = r.reference(j, i);
      hits += ref.hit;
      if (!colorNear(r.pixel(j, i), ref.total())) {
        if (++mismatches <= 5)
          ADD_FAILURE() << "pixel (" << j << "," << i
                        << "): " << colorNear(r.pixel(j, i), ref.total()).message();
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
  return hits;
}

/// The centre colour of a sphere scene: emission + I_L·(kD/3 + kS/3^301).
Double3 sphereCentre(double attenuation) {
  const double terms = 0.5 * (1.0 / 3) + 0.5 * std::pow(1.0 / 3, 301);
  return SPHERE_EMISSION + Double3(800, 500, 0) * (terms / attenuation);
}

/// The centre colour of a triangles scene: ambient + I_L·(kD3·nl + kS3·nl^301), where the
/// cosine nl = |n·l| equals -v·r at that point in every triangles scene.
Double3 trianglesCentre(double intensityScale, double nl) {
  return TRIANGLES_AMBIENT +
         Double3(800, 500, 250) * (KD3 * nl + KS3 * std::pow(nl, 301)) * intensityScale;
}

/// Checks the highlight pixel: it is lit, and its colour is the diffuse-only colour plus the
/// specular term (at least minSpecularRed in red: visibly a highlight).
void expectHighlight(const Render& r, int j, int i, double minSpecularRed) {
  const ReferenceShading ref = r.reference(j, i);
  ASSERT_TRUE(ref.hit);
  ASSERT_GT(ref.specular.x, minSpecularRed);
  const Double3 diffuseOnly = ref.base + ref.diffuse;
  EXPECT_TRUE(colorNear(r.pixel(j, i), diffuseOnly + ref.specular));
  EXPECT_GT(r.pixel(j, i).r() - diffuseOnly.x, minSpecularRed);
}

/// A point light with the spot's position and attenuation (the spot without its cone).
PointLight asPointLight(const SpotLight& spot) {
  return PointLight(spot.intensity, spot.position).setKc(spot.kC).setKl(spot.kL).setKq(spot.kQ);
}

/// Spot scene vs the same scene with the spot replaced by a point light: on every pixel that
/// hits, (spot - base) = (point - base)·max(0, direction·l)^narrowBeam exactly.
void expectSpotIsConedPointLight(const Render& spot) {
  const SpotLight& s = std::get<SpotLight>(spot.setup.scene.lights.at(0));
  SceneSetup<LitScene> pointSetup = spot.setup;
  pointSetup.scene.lights = {asPointLight(s)};
  const Render point(pointSetup);
  int checked = 0, coned = 0;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      const ReferenceShading ref = spot.reference(j, i);
      if (!ref.hit) continue;
      const Double3 l = (Point(ref.point) - s.position).normalized().xyz();
      const double factor = std::pow(std::max(0.0, s.direction.xyz().dot(l)), s.narrowBeam);
      const Double3 expected = ref.base + (point.pixel(j, i).rgb() - ref.base) * factor;
      if (!colorNear(spot.pixel(j, i), expected)) {
        ADD_FAILURE() << "pixel (" << j << "," << i << ")";
        return;
      }
      ++checked;
      coned += factor < 0.99;
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(coned, 100);  // the cone really dims part of the image
}

// ---- the sphere -----------------------------------------------------------------------------

TEST(LightsSceneTests, sphereDirectional) {
  const Render r(course::sphereDirectional());
  r.save();
  // ============ Equivalence Partitions Tests ==============
  // TC01: the centre pixel, by hand: (800/6, 500/6, 127.5) (+ a 3^-301 highlight)
  EXPECT_TRUE(colorNear(r.pixel(50, 50), sphereCentre(1)));
  EXPECT_TRUE(colorNear(r.pixel(50, 50), 800.0 / 6, 500.0 / 6, 127.5));
  // TC02: the dark side (upper right, the light comes from the lower left): the emission exactly
  const ReferenceShading dark = r.reference(70, 30);
  ASSERT_TRUE(dark.hit);
  ASSERT_EQ(dark.litBy, 0);
  EXPECT_TRUE(colorNear(r.pixel(70, 30), SPHERE_EMISSION));
  // TC03: the lit side (lower left): emission + diffuse (+ specular), above the emission
  const ReferenceShading lit = r.reference(30, 70);
  ASSERT_EQ(lit.litBy, 1);
  EXPECT_TRUE(colorNear(r.pixel(30, 70), lit.total()));
  EXPECT_GT(r.pixel(30, 70).r(), 100);
  // TC04: the highlight pixel exceeds the diffuse-only colour by the specular term (> 300 red)
  expectHighlight(r, 37, 63, 300);
  // TC05: every pixel against the oracle
  EXPECT_EQ(expectAllPixelsMatchReference(r), N * N - 6960);

  // =============== Boundary Values Tests ==================
  // TC11: a corner pixel misses the sphere: the black background
  ASSERT_FALSE(r.reference(0, 0).hit);
  EXPECT_TRUE(colorNear(r.pixel(0, 0), 0, 0, 0));
}

TEST(LightsSceneTests, spherePoint) {
  const Render r(course::spherePoint());
  r.save();
  // ============ Equivalence Partitions Tests ==============
  // TC01: centre, attenuation 1 + 0.001·75 + 0.0002·5625 = 2.2
  EXPECT_TRUE(colorNear(r.pixel(50, 50), sphereCentre(2.2)));
  // TC02: the dark side: the emission exactly
  ASSERT_EQ(r.reference(70, 30).litBy, 0);
  EXPECT_TRUE(colorNear(r.pixel(70, 30), SPHERE_EMISSION));
  // TC03: the highlight
  expectHighlight(r, 39, 61, 200);
  // TC04: every pixel against the oracle
  expectAllPixelsMatchReference(r);

  // =============== Boundary Values Tests ==================
  // TC11: a miss: the background
  EXPECT_TRUE(colorNear(r.pixel(100, 0), 0, 0, 0));
}

TEST(LightsSceneTests, sphereSpot) {
  const Render r(course::sphereSpot());
  r.save();
  // ============ Equivalence Partitions Tests ==============
  // TC01: centre, on the spot's axis (factor 1), attenuation 1 + 0.075 + 0.0001·5625 = 1.6375
  EXPECT_TRUE(colorNear(r.pixel(50, 50), sphereCentre(1.6375)));
  // TC02: the dark side: the emission exactly
  ASSERT_EQ(r.reference(70, 30).litBy, 0);
  EXPECT_TRUE(colorNear(r.pixel(70, 30), SPHERE_EMISSION));
  // TC03: the highlight
  expectHighlight(r, 39, 61, 250);
  // TC04: the spot is the point light with the same attenuation times the cone factor
  expectSpotIsConedPointLight(r);
  // TC05: every pixel against the oracle
  expectAllPixelsMatchReference(r);
}

TEST(LightsSceneTests, sphereSpotSharp) {
  const Render r(course::sphereSpotSharp());
  r.save();
  // ============ Equivalence Partitions Tests ==============
  // TC01: centre, factor 1^10, attenuation 1 + 0.075 + 0.00004·5625 = 1.3
  EXPECT_TRUE(colorNear(r.pixel(50, 50), sphereCentre(1.3)));
  // TC02: the dark side: the emission exactly
  ASSERT_EQ(r.reference(70, 30).litBy, 0);
  EXPECT_TRUE(colorNear(r.pixel(70, 30), SPHERE_EMISSION));
  // TC03: the highlight
  expectHighlight(r, 39, 61, 250);
  // TC04: the point light with the same attenuation times the cone factor to the 10th power
  expectSpotIsConedPointLight(r);
  // TC05: every pixel against the oracle
  expectAllPixelsMatchReference(r);
}

// ---- the triangles --------------------------------------------------------------------------

TEST(LightsSceneTests, trianglesDirectional) {
  const Render r(course::trianglesDirectional());
  r.save();
  const double nl = 1 / std::sqrt(3.0);
  // ============ Equivalence Partitions Tests ==============
  // TC01: centre (triangle 1): ambient + (800,500,250)·(kD3/sqrt(3) + kS3·3^-150.5)
  //       = (38.25 + 160/sqrt(3), 38.25 + 300/sqrt(3), 38.25 + 100/sqrt(3))
  EXPECT_TRUE(colorNear(r.pixel(50, 50), trianglesCentre(1, nl)));
  EXPECT_TRUE(colorNear(r.pixel(50, 50), 38.25 + 160 * nl, 38.25 + 300 * nl, 38.25 + 100 * nl));
  // TC02: a pixel of triangle 2 (upper left), lit: the oracle's value, above the ambient
  const ReferenceShading t2 = r.reference(30, 30);
  ASSERT_EQ(t2.geometry, 1u);
  ASSERT_EQ(t2.litBy, 1);
  EXPECT_TRUE(colorNear(r.pixel(30, 30), t2.total()));
  EXPECT_GT(r.pixel(30, 30).g(), 38.25 + 10);
  // TC03: every pixel against the oracle
  EXPECT_EQ(expectAllPixelsMatchReference(r), N * N - 1901);

  // =============== Boundary Values Tests ==================
  // TC11: the upper-left corner misses both triangles: the black background, no ambient
  ASSERT_FALSE(r.reference(0, 0).hit);
  EXPECT_TRUE(colorNear(r.pixel(0, 0), 0, 0, 0));
}

TEST(LightsSceneTests, trianglesPoint) {
  const Render r(course::trianglesPoint());
  r.save();
  const double d = std::sqrt(3500.0), nl = 50 / d;
  // ============ Equivalence Partitions Tests ==============
  // TC01: centre, attenuation 1 + 0.001·sqrt(3500) + 0.0002·3500 = 1.7 + 0.001·sqrt(3500)
  EXPECT_TRUE(colorNear(r.pixel(50, 50), trianglesCentre(1 / (1.7 + 0.001 * d), nl)));
  // TC02: the highlight: the specular term, visible (> 90 red), on top of the diffuse colour
  expectHighlight(r, 63, 46, 90);
  // TC03: every pixel against the oracle
  expectAllPixelsMatchReference(r);
}

TEST(LightsSceneTests, trianglesSpot) {
  const Render r(course::trianglesSpot());
  r.save();
  const double d = std::sqrt(3500.0), nl = 50 / d;
  const double factor = 90 / std::sqrt(10500.0);
  // ============ Equivalence Partitions Tests ==============
  // TC01: centre, attenuation 1.35 + 0.001·sqrt(3500), cone factor 90/sqrt(10500)
  EXPECT_TRUE(colorNear(r.pixel(50, 50), trianglesCentre(factor / (1.35 + 0.001 * d), nl)));
  // TC02: the spot is the point light with the same attenuation times the cone factor
  expectSpotIsConedPointLight(r);
  // TC03: every pixel against the oracle
  expectAllPixelsMatchReference(r);

  // =============== Boundary Values Tests ==================
  // TC11: behind the spot (direction·l < 0, near the upper right vertex (95,100,-150)): the
  // light is on the viewer's side of the triangle but gives nothing: the ambient exactly
  const ReferenceShading out = r.reference(89, 24);
  ASSERT_TRUE(out.hit);
  ASSERT_EQ(out.litBy, 1);
  const SpotLight& spot = std::get<SpotLight>(r.setup.scene.lights[0]);
  ASSERT_LT(spot.direction.dot(Point(out.point) - spot.position), 0);
  EXPECT_TRUE(colorNear(r.pixel(89, 24), TRIANGLES_AMBIENT));
}

TEST(LightsSceneTests, trianglesSpotSharp) {
  const Render r(course::trianglesSpotSharp());
  r.save();
  const double d = std::sqrt(3500.0), nl = 50 / d;
  const double factor = std::pow(90 / std::sqrt(10500.0), 10);
  // ============ Equivalence Partitions Tests ==============
  // TC01: centre, attenuation 1.14 + 0.001·sqrt(3500), factor (90/sqrt(10500))^10
  EXPECT_TRUE(colorNear(r.pixel(50, 50), trianglesCentre(factor / (1.14 + 0.001 * d), nl)));
  // TC02: the point light with the same attenuation times the cone factor to the 10th power
  expectSpotIsConedPointLight(r);
  // TC03: every pixel against the oracle
  expectAllPixelsMatchReference(r);

  // =============== Boundary Values Tests ==================
  // TC11: behind the spot: the ambient exactly
  EXPECT_TRUE(colorNear(r.pixel(89, 24), TRIANGLES_AMBIENT));
}

// ---- several lights -------------------------------------------------------------------------

/// Phong is a sum over lights: the image with all lights equals the sum of the one-light
/// images minus the (lights-1) extra copies of ambient + emission, on every pixel.
void expectLightsAddUp(const SceneSetup<LitScene>& setup) {
  const Render all(setup);
  SceneSetup<LitScene> none = setup;
  none.scene.lights.clear();
  const Render base(none);
  std::vector<Render> singles;
  for (const LightSource& light : setup.scene.lights) {
    SceneSetup<LitScene> one = setup;
    one.scene.lights = {light};
    singles.emplace_back(one);
  }
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      Double3 sum = base.pixel(j, i).rgb();
      for (const Render& s : singles) sum = sum + (s.pixel(j, i).rgb() - base.pixel(j, i).rgb());
      if (!colorNear(all.pixel(j, i), sum)) {
        ADD_FAILURE() << "pixel (" << j << "," << i
                      << "): " << colorNear(all.pixel(j, i), sum).message();
        return;
      }
    }
  }
}

TEST(LightsSceneTests, sphereMultiLight) {
  const auto setup = course::sphereMultiLight();
  ASSERT_EQ(setup.scene.lights.size(), 3u);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the three lights add up on every pixel
  expectLightsAddUp(setup);
  // TC02: every pixel against the oracle, and the sphere is lit everywhere by some light
  const Render r(setup);
  r.save();
  expectAllPixelsMatchReference(r);
  EXPECT_GE(r.reference(50, 50).litBy, 1);
}

TEST(LightsSceneTests, trianglesMultiLight) {
  const auto setup = course::trianglesMultiLight();
  ASSERT_EQ(setup.scene.lights.size(), 3u);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the three lights add up on every pixel
  expectLightsAddUp(setup);
  // TC02: every pixel against the oracle
  const Render r(setup);
  r.save();
  expectAllPixelsMatchReference(r);

  // =============== Boundary Values Tests ==================
  // TC11: a miss: the background, without the ambient (WHITE x 0.05)
  EXPECT_TRUE(colorNear(r.pixel(0, 0), 0, 0, 0));
}

// ---- RenderTests.renderMultiColorTest -------------------------------------------------------

TEST(MultiColorRenderTests, renderMultiColor) {
  // 100 x 100 pixels over the 500 x 500 view plane at distance 100: 5 units per pixel in the
  // plane z = -100, pixel (j,i) centred at x = (j - 49.5)·5, y = -(i - 49.5)·5.
  const Render r(course::renderMultiColor(), 100);
  r.save();
  // ============ Equivalence Partitions Tests ==============
  // TC01: up-left triangle at (-77.5, 77.5): GREEN + ambient (51,51,51)
  EXPECT_TRUE(colorNear(r.pixel(34, 34), 51, 306, 51));
  // TC02: down-left triangle at (-77.5,-77.5): RED + ambient
  EXPECT_TRUE(colorNear(r.pixel(34, 65), 306, 51, 51));
  // TC03: down-right triangle at (77.5,-77.5): BLUE + ambient
  EXPECT_TRUE(colorNear(r.pixel(65, 65), 51, 51, 306));
  // TC04: the sphere (no emission, no material): the ambient only
  EXPECT_TRUE(colorNear(r.pixel(49, 49), 51, 51, 51));
  EXPECT_TRUE(colorNear(r.pixel(50, 50), 51, 51, 51));
  // TC05: the empty up-right quadrant at (77.5,77.5): the black background
  EXPECT_TRUE(colorNear(r.pixel(65, 34), 0, 0, 0));
  // TC06: every pixel is one of those five colours, each where the oracle says
  const std::set<std::uint32_t> seen = [&] {
    std::set<std::uint32_t> s;
    for (int i = 0; i < 100; ++i)
      for (int j = 0; j < 100; ++j)
        if (const auto ref = r.reference(j, i); ref.hit) s.insert(ref.geometry);
    return s;
  }();
  EXPECT_EQ(seen.size(), 4u);
  expectAllPixelsMatchReference(r, 100);

  // =============== Boundary Values Tests ==================
  // TC11: the corner pixel beyond every shape: background
  EXPECT_TRUE(colorNear(r.pixel(0, 0), 0, 0, 0));
}

// ---- the table the rt program lists ---------------------------------------------------------

TEST(CourseScenesTests, lightingScenes) {
  const auto scenes = lightingScenes();
  // ============ Equivalence Partitions Tests ==============
  // TC01: eleven scenes, with unique kebab-case names and a description each
  ASSERT_EQ(scenes.size(), 11u);
  // TC02: every scene builds, keeps shapes and appearances aligned and has a camera
  // (checkSceneTable, tested below), and the Phong tracer accepts it
  EXPECT_NO_THROW(checkSceneTable(scenes));
  for (const CourseScene& s : scenes) EXPECT_NO_THROW(PhongTracer{s.make().scene}) << s.name;
  // TC03: the LightsTests cameras: camera1 (VP 150) for the sphere, camera2 (VP 200) for the
  // triangles, both at (0,0,1000), distance 1000, 500 x 500
  const auto sphere = course::sphereSpot();
  EXPECT_EQ(sphere.camera.vpWidth, 150);
  EXPECT_EQ(sphere.camera.vpDistance, 1000);
  EXPECT_EQ(sphere.camera.nX, 500);
  EXPECT_EQ(sphere.camera.location, Point(0, 0, 1000));
  const auto triangles = course::trianglesSpotSharp();
  EXPECT_EQ(triangles.camera.vpWidth, 200);
  EXPECT_EQ(triangles.camera.nY, 500);
  // TC04: the sharp spot's values: kL 0.001, kQ 0.00004, narrowBeam 10
  const auto& spot = std::get<SpotLight>(triangles.scene.lights.at(0));
  EXPECT_EQ(spot.kL, 0.001);
  EXPECT_EQ(spot.kQ, 0.00004);
  EXPECT_EQ(spot.narrowBeam, 10);

  // =============== Boundary Values Tests ==================
  // TC11: the multi-colour scene asks for the course's white grid every 100 pixels
  EXPECT_EQ(scenes[0].gridInterval, 100);
  EXPECT_EQ(scenes[0].gridColor, Color::WHITE);
  EXPECT_EQ(scenes[1].gridInterval, 0);
}

// ---- checkSceneTable ------------------------------------------------------------------------

SceneSetup<LitScene> unnamedScene() {
  SceneSetup<LitScene> s = course::sphereDirectional();
  s.scene.name.clear();
  return s;
}

SceneSetup<LitScene> misalignedScene() {
  SceneSetup<LitScene> s = course::sphereDirectional();
  s.scene.geometries.add(Sphere(Point(0, 0, -500), 1));  // behind LitScene::add's back
  return s;
}

SceneSetup<LitScene> noCameraScene() {
  SceneSetup<LitScene> s = course::sphereDirectional();
  s.camera = CameraSpec{};
  return s;
}

SceneSetup<LitScene> throwingScene() { throw std::invalid_argument("bad value"); }

/// The message of the logic_error checkSceneTable throws for the table ("" for none).
std::string tableError(std::initializer_list<CourseScene> table) {
  return test::thrownMessage<std::logic_error>(
      [&] { checkSceneTable(std::span<const CourseScene>(table.begin(), table.size())); });
}

TEST(CourseScenesTests, checkSceneTable) {
  const CourseScene good{"good-scene", "a valid entry for the check", &course::sphereDirectional};
  // ============ Equivalence Partitions Tests ==============
  // TC01: a valid table: no error
  EXPECT_EQ(tableError({good, {"good-2", "another valid entry", &course::spherePoint}}), "");
  // TC02: a duplicate name: names the second entry, its name and the first one
  EXPECT_THAT(tableError({good, {"other", "a valid description", &course::spherePoint}, good}),
              AllOf(HasSubstr("entry 2"), HasSubstr("'good-scene'"), HasSubstr("duplicate"),
                    HasSubstr("entry 0")));
  // TC03: a name that is not kebab-case
  EXPECT_THAT(tableError({{"Good_Scene", "a valid description", &course::sphereDirectional}}),
              AllOf(HasSubstr("entry 0"), HasSubstr("'Good_Scene'"), HasSubstr("kebab-case")));
  // TC04: a short description
  EXPECT_THAT(tableError({good, {"short", "too short", &course::sphereDirectional}}),
              AllOf(HasSubstr("entry 1"), HasSubstr("'short'"), HasSubstr("'too short'")));
  // TC05: a scene without a name
  EXPECT_THAT(tableError({{"unnamed", "a scene without a name", &unnamedScene}}),
              AllOf(HasSubstr("'unnamed'"), HasSubstr("no name")));
  // TC06: more geometries than appearances: both sizes
  EXPECT_THAT(tableError({{"misaligned", "one shape without appearance", &misalignedScene}}),
              AllOf(HasSubstr("'misaligned'"), HasSubstr("2 geometries but 1 appearance indices")));
  // TC07: a camera that does not build: the builder's own message too
  EXPECT_THAT(tableError({{"no-camera", "a default camera spec", &noCameraScene}}),
              AllOf(HasSubstr("'no-camera'"), HasSubstr("camera"), HasSubstr("width")));
  // TC08: a make function that throws: its message
  EXPECT_THAT(tableError({{"throwing", "make throws an exception", &throwingScene}}),
              AllOf(HasSubstr("'throwing'"), HasSubstr("bad value")));

  // =============== Boundary Values Tests ==================
  // TC11: an empty table: nothing to check
  EXPECT_EQ(tableError({}), "");
  // TC12: an empty name and a null name
  EXPECT_THAT(tableError({{"", "a valid description", &course::sphereDirectional}}),
              AllOf(HasSubstr("entry 0"), HasSubstr("no name")));
  EXPECT_THAT(tableError({good, {nullptr, "a valid description", &course::sphereDirectional}}),
              AllOf(HasSubstr("entry 1"), HasSubstr("(null)"), HasSubstr("no name")));
  // TC13: descriptions of 10 characters (too short), 11 (enough) and null
  EXPECT_THAT(tableError({{"ten", "0123456789", &course::sphereDirectional}}), HasSubstr("'ten'"));
  EXPECT_EQ(tableError({{"eleven", "0123456789a", &course::sphereDirectional}}), "");
  EXPECT_THAT(tableError({{"null-description", nullptr, &course::sphereDirectional}}),
              HasSubstr("'null-description'"));
  // TC14: no make function
  EXPECT_THAT(tableError({{"no-make", "an entry without make", nullptr}}),
              AllOf(HasSubstr("'no-make'"), HasSubstr("no make function")));
}

}  // namespace
}  // namespace rt
