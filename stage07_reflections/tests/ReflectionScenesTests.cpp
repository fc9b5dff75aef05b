// The course's ReflectionRefractionTests scenes, the all-features scene from both viewpoints and
// the hall of mirrors, rendered by the Whitted tracer at a lower resolution than the course's
// (`rt render NAME` gives the full one), with pixel checks. The images are written under the
// build tree, in images/stage07/.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <variant>

#include "camera/Camera.h"
#include "camera/ImageWriter.h"
#include "intersections/Intersect.h"
#include "lighting/PhongTracer.h"
#include "reflections/CourseScenes.h"
#include "reflections/Optics.h"
#include "reflections/WhittedTracer.h"
#include "shadows/ShadowTracer.h"

namespace rt {
namespace {

/// Renders the scene with the tracer at pixels x pixels (the view plane unchanged), and writes
/// the image to images/stage07/<file>.png when file is given.
Image render(const SceneSetup<LitScene>& s, const RayTracer& tracer, int pixels,
             const std::string& file = "") {
  CameraSpec spec = s.camera;
  spec.nX = pixels;
  spec.nY = pixels;
  Camera camera =
      spec.builder()
          .setRayTracer(std::shared_ptr<const RayTracer>(&tracer, [](const RayTracer*) {}))
          .setImageWriter(std::make_shared<PngImageWriter>())
          .build();
  camera.renderImage();
  if (!file.empty()) {
    std::filesystem::create_directories("images/stage07");
    camera.writeToImage("images/stage07/" + file + ".png");
  }
  return camera.image();
}

Camera cameraOf(const SceneSetup<LitScene>& s, int pixels) {
  CameraSpec spec = s.camera;
  spec.nX = pixels;
  spec.nY = pixels;
  return spec.builder().build();
}

/// The shape the primary ray of pixel (j, i) hits first, if any.
std::optional<Hit> primaryHit(const SceneSetup<LitScene>& s, const Camera& c, int pixels, int j,
                              int i) {
  return s.scene.geometries.closestHit(c.constructRay(pixels, pixels, j, i));
}

/// I0·max(0, D·l)/(kC + kL·d + kQ·d²) of a spot light at p, and l.
struct SpotAt {
  double factor;  ///< the scalar multiplying I0
  Double3 l;
};
SpotAt spotAt(const SpotLight& light, const Point& p) {
  const Double3 toP = p.xyz() - light.position.xyz();
  const double d = std::sqrt(toP.lengthSquared());
  const Double3 l = toP / d;
  const double cosine = std::max(0.0, light.direction.xyz().dot(l));
  return {cosine / (light.kC + light.kL * d + light.kQ * d * d), l};
}

/// Phong's kD·|n·l| + kS·max(0, −v·r)^nSh for scalar kD, kS.
double phong(double kD, double kS, int nSh, const Double3& n, const Double3& v, const Double3& l) {
  const double nl = n.dot(l);
  const Double3 r = l - n * (2 * nl);
  return kD * std::abs(nl) + kS * std::pow(std::max(0.0, -v.dot(r)), nSh);
}

TEST(ReflectionScenesTests, twoSpheres) {
  const SceneSetup<LitScene> s = course::twoSpheres();
  const WhittedTracer tracer(s.scene);
  // An odd resolution puts pixel (50,50) exactly on the axis: its ray is (0,0,-1).
  const Image image = render(s, tracer, 101, "refraction-two-spheres");
  const SpotLight& light = std::get<SpotLight>(s.scene.lights[0]);
  const Double3 v(0, 0, -1), n(0, 0, 1);

  /*
   * TC01: the red inner sphere seen through the blue one with the weight kT = 0.3.
   *
   *   eye ---> (0,0,0) outer sphere (BLUE, kD 0.4 kS 0.3 nSh 100, kT 0.3)
   *        ---> (0,0,-25) inner sphere (RED, kD 0.5 kS 0.5 nSh 100), straight through
   *
   * outer = BLUE + I(P1)·(0.4|n·l1| + 0.3·max(0,−v·r1)^100)                 (nothing shadows P1)
   * inner = RED  + I(P2)·0.3·(0.5|n·l2| + 0.5·max(0,−v·r2)^100)  (its shadow ray leaves the
   *                                                               outer sphere once: kT 0.3)
   * pixel = outer + 0.3·inner (no ambient light in this scene)
   */
  const SpotAt s1 = spotAt(light, Point(0, 0, 0));
  const SpotAt s2 = spotAt(light, Point(0, 0, -25));
  const double term1 = s1.factor * phong(0.4, 0.3, 100, n, v, s1.l);
  const double term2 = s2.factor * 0.3 * phong(0.5, 0.5, 100, n, v, s2.l);
  const Color expected(1000 * term1 + 0.3 * (255 + 1000 * term2),  // red
                       600 * term1 + 0.3 * (600 * term2),          // green
                       255);                                       // blue: emission only
  const Color& got = image.pixel(50, 50);
  EXPECT_NEAR(expected.r(), got.r(), 1e-9);
  EXPECT_NEAR(expected.g(), got.g(), 1e-9);
  EXPECT_NEAR(expected.b(), got.b(), 1e-9);
  // TC02: without refraction (the shadow tracer) no red comes through: red is only the light's
  EXPECT_NEAR(1000 * term1,
              ShadowTracer(s.scene).traceRay(Ray(Point(0, 0, 1000), Vector(0, 0, -1))).r(), 1e-9);
}

TEST(ReflectionScenesTests, twoSpheresOnMirrors) {
  constexpr int PIXELS = 125;
  const SceneSetup<LitScene> s = course::twoSpheresOnMirrors();
  const WhittedTracer whitted(s.scene);
  const ShadowTracer shadow(s.scene);
  const Image image = render(s, whitted, PIXELS, "reflection-two-spheres-mirrored");
  const Image flat = render(s, shadow, PIXELS);
  const Camera camera = cameraOf(s, PIXELS);
  const Color mirrorUnlit = Color(25.5, 25.5, 25.5) + Color(20, 20, 20);  // ambient + emission

  int reflectingSphere = 0, reflectingTinted = 0;
  for (int i = 0; i < PIXELS; ++i) {
    for (int j = 0; j < PIXELS; ++j) {
      const Ray ray = camera.constructRay(PIXELS, PIXELS, j, i);
      const std::optional<Hit> hit = s.scene.geometries.closestHit(ray);
      if (!hit || hit->geometry != 2) continue;  // the full mirror (kR 1) only
      // TC01: a mirror pixel without reflection: ambient + emission (the mirror has no kD, kS)
      ASSERT_EQ(mirrorUnlit, flat.pixel(j, i));
      const Point p = ray.point(hit->t);
      const Vector nrm = normalAt(s.scene.geometries[2], p);
      const Ray reflected(p + nrm * (nrm.dot(ray.direction()) < 0 ? 1e-6 : -1e-6),
                          reflect(ray.direction(), nrm));
      const std::optional<Hit> seen = s.scene.geometries.closestHit(reflected);
      ASSERT_TRUE(seen.has_value()) << j << "," << i;  // the mirrors face the spheres
      // TC02: with kR 1 the mirror adds at least the emission of the shape it reflects
      const Color& got = image.pixel(j, i);
      const Color& emission = s.scene.appearances[seen->geometry].emission;
      ASSERT_GE(got.r(), mirrorUnlit.r() + emission.r() - 1e-9) << j << "," << i;
      ASSERT_GE(got.g(), mirrorUnlit.g() + emission.g() - 1e-9) << j << "," << i;
      ASSERT_GE(got.b(), mirrorUnlit.b() + emission.b() - 1e-9) << j << "," << i;
      if (seen->geometry == 0) ++reflectingSphere;  // the blue-green outer sphere: (0,50,100)
      if (seen->geometry == 3) ++reflectingTinted;  // the tinted mirror: (20,20,20)
    }
  }
  RecordProperty("reflectingSphere", reflectingSphere);
  RecordProperty("reflectingTinted", reflectingTinted);
  EXPECT_GT(reflectingSphere, 100);
  EXPECT_GT(reflectingTinted, 100);
}

TEST(ReflectionScenesTests, trianglesTransparentSphere) {
  constexpr int PIXELS = 150;
  const SceneSetup<LitScene> s = course::trianglesTransparentSphere();
  const WhittedTracer whitted(s.scene);
  const PhongTracer phong(s.scene);
  const Image image = render(s, whitted, PIXELS, "refraction-shadow");
  const Image noShadow = render(s, phong, PIXELS);
  const Camera camera = cameraOf(s, PIXELS);
  const Point light = std::get<SpotLight>(s.scene.lights[0]).position;
  const Sphere& sphere = std::get<Sphere>(s.scene.geometries[2]);
  const double ambient = 38.25;  // WHITE x 0.15

  int partial = 0, lit = 0, throughSphere = 0;
  for (int i = 0; i < PIXELS; ++i) {
    for (int j = 0; j < PIXELS; ++j) {
      const Ray ray = camera.constructRay(PIXELS, PIXELS, j, i);
      const std::optional<Hit> hit = s.scene.geometries.closestHit(ray);
      if (!hit) continue;
      const Color& got = image.pixel(j, i);
      const Color& phongColor = noShadow.pixel(j, i);
      if (hit->geometry == 2) {
        // TC03: the sphere shows the triangles behind it: brighter than without refraction
        if (got.r() > ShadowTracer(s.scene).traceRay(ray).r() + 1) ++throughSphere;
        continue;
      }
      const Point p = ray.point(hit->t);
      const std::vector<Point> crossings =
          findIntersections(sphere, Ray(p, light - p), p.distance(light));
      if (crossings.size() == 2) {
        // TC01: the partial shadow: the light term is scaled by 0.6 · 0.6 = 0.36 exactly
        EXPECT_NEAR(0.36 * (phongColor.r() - ambient), got.r() - ambient, 1e-9) << j << "," << i;
        EXPECT_NEAR(0.36 * (phongColor.g() - ambient), got.g() - ambient, 1e-9) << j << "," << i;
        EXPECT_NEAR(0.36 * (phongColor.b() - ambient), got.b() - ambient, 1e-9) << j << "," << i;
        if (phongColor.r() > ambient + 1) ++partial;
      } else {
        // TC02: outside the shadow: the triangles (no kT, no kR) look as with Phong alone
        ASSERT_EQ(phongColor, got) << j << "," << i;
        if (got.r() > ambient + 1) ++lit;
      }
    }
  }
  EXPECT_GT(partial, 100);
  EXPECT_GT(lit, 1000);
  EXPECT_GT(throughSphere, 100);
}

/// The brightest-channel test: true when c's red exceeds its green and blue.
bool redDominant(const Color& c) { return c.r() > c.g() && c.r() > c.b(); }

TEST(ReflectionScenesTests, allFeaturesFromBothViewpoints) {
  constexpr int PIXELS = 150;
  const SceneSetup<LitScene> below = course::allFeaturesBelow();
  const SceneSetup<LitScene> above = course::allFeaturesAbove();
  ASSERT_EQ(18u, below.scene.geometries.size());
  const WhittedTracer belowTracer(below.scene), aboveTracer(above.scene);
  const Image imageBelow = render(below, belowTracer, PIXELS, "all-features-below");
  const Image imageAbove = render(above, aboveTracer, PIXELS, "all-features-above");

  for (const auto* view : {&below, &above}) {
    const Image& image = view == &below ? imageBelow : imageAbove;
    const Camera camera = cameraOf(*view, PIXELS);
    int cube = 0, floor = 0, pyramid = 0;
    for (int i = 0; i < PIXELS; ++i) {
      for (int j = 0; j < PIXELS; ++j) {
        const std::optional<Hit> hit = primaryHit(*view, camera, PIXELS, j, i);
        if (!hit) continue;
        const Color& c = image.pixel(j, i);
        if (hit->geometry >= 11 && hit->geometry <= 16) {
          // TC01: a pixel on the cube is red (emissions (255,50,50) and (300,20,20))
          EXPECT_TRUE(redDominant(c)) << "cube pixel " << j << "," << i << ": " << c;
          ++cube;
        } else if (hit->geometry == 0) {
          // TC02: a pixel on the floor is blue (emission (30,40,70), blue-heavy lights)
          EXPECT_GT(c.b(), c.r()) << "floor pixel " << j << "," << i << ": " << c;
          ++floor;
        } else if (hit->geometry >= 1 && hit->geometry <= 8) {
          ++pyramid;
        }
      }
    }
    EXPECT_GT(cube, 20);
    EXPECT_GT(floor, 1000);
    EXPECT_GT(pyramid, 500);
  }
  // TC03: the two viewpoints see different images: most pixels differ
  int differ = 0;
  for (int i = 0; i < PIXELS; ++i)
    for (int j = 0; j < PIXELS; ++j)
      if (!(imageBelow.pixel(j, i) == imageAbove.pixel(j, i))) ++differ;
  EXPECT_GT(differ, PIXELS * PIXELS / 2);
}

TEST(ReflectionScenesTests, hallOfMirrors) {
  constexpr int PIXELS = 120;
  const SceneSetup<LitScene> s = course::hallOfMirrors();
  const WhittedTracer tracer(s.scene);
  const Image image = render(s, tracer, PIXELS, "hall-of-mirrors");
  const Camera camera = cameraOf(s, PIXELS);
  int redReflections = 0;
  for (int i = 0; i < PIXELS; ++i) {
    for (int j = 0; j < PIXELS; ++j) {
      const Ray ray = camera.constructRay(PIXELS, PIXELS, j, i);
      const std::optional<Hit> hit = s.scene.geometries.closestHit(ray);
      if (!hit || hit->geometry != 0) continue;
      const Point p = ray.point(hit->t);
      const Vector nrm = normalAt(s.scene.geometries[0], p);
      const Ray reflected(p + nrm * (nrm.dot(ray.direction()) < 0 ? 1e-6 : -1e-6),
                          reflect(ray.direction(), nrm));
      const std::optional<Hit> seen = s.scene.geometries.closestHit(reflected);
      if (seen && seen->geometry == 3) {
        // TC01: the mirror shows the red sphere: red dominates
        EXPECT_TRUE(redDominant(image.pixel(j, i))) << j << "," << i;
        ++redReflections;
      }
    }
  }
  EXPECT_GT(redReflections, 50);
}

/// The course's Whitted recursion written out directly (refraction straight through, no index of
/// refraction), as the reference for "ior == 1 renders bit for bit as the course".
class CourseWhitted : public ShadowTracer {
 public:
  using ShadowTracer::ShadowTracer;
  using ShadowTracer::traceRay;
  Color traceRay(const Ray& ray, SampleContext& ctx) const override {
    const std::optional<Hit> hit = intersector().closestHit(ray);
    if (!hit) return scene().background;
    return scene().ambientLight.intensity() +
           calcColor(makeContext(*hit, ray), 10, Double3::ONE, ctx);
  }

 private:
  Color calcColor(const HitContext& h, int level, const Double3& k, SampleContext& ctx) const {
    const Color local = localEffects(h, k, ctx);
    if (level == 1) return local;
    const Material& m = h.appearance->material;
    const Double3 r = h.v.xyz() - h.normal.xyz() * (2 * h.v.xyz().dot(h.normal.xyz()));
    return local +
           (effect(h, h.v, level, k, m.kT, ctx) + effect(h, Vector(r), level, k, m.kR, ctx));
  }
  Color effect(const HitContext& h, const Vector& dir, int level, const Double3& k,
               const Double3& kx, SampleContext& ctx) const {
    const Double3 kkx = k * kx;
    if (kkx.lowerThan(0.001)) return Color::BLACK;
    const Ray ray = rayOffset().ray(h.point, h.normal, dir);
    const std::optional<Hit> hit = intersector().closestHit(ray);
    if (!hit) return scene().background * kx;
    return calcColor(makeContext(*hit, ray), level - 1, kkx, ctx) * kx;
  }
};

bool identical(const Image& a, const Image& b) {
  for (int i = 0; i < a.nY(); ++i) {
    for (int j = 0; j < a.nX(); ++j) {
      const Double3& x = a.pixel(j, i).rgb();
      const Double3& y = b.pixel(j, i).rgb();
      if (x.x != y.x || x.y != y.y || x.z != y.z) return false;
    }
  }
  return true;
}

TEST(ReflectionScenesTests, iorOneIsTheCourseBitForBit) {
  constexpr int PIXELS = 80;
  for (const CourseScene& entry : reflectionScenes()) {
    SceneSetup<LitScene> s = entry.make();
    // TC01: every scene (all materials ior 1): the same bits as the course's recursion
    const WhittedTracer whitted(s.scene);
    const CourseWhitted course(s.scene);
    EXPECT_TRUE(identical(render(s, course, PIXELS), render(s, whitted, PIXELS))) << entry.name;
  }
  // TC02: with an index of refraction the image changes (the test can fail)
  SceneSetup<LitScene> glass = course::twoSpheres();
  glass.scene.appearances[0].material.ior = 1.5;
  const WhittedTracer whitted(glass.scene);
  const CourseWhitted course(glass.scene);
  EXPECT_FALSE(identical(render(glass, course, PIXELS), render(glass, whitted, PIXELS)));
}

TEST(ReflectionScenesTable, namesAreUniqueAndScenesBuild) {
  // TC01: every entry has a unique name, a description and a scene with an image name, one
  // appearance per shape and a camera (stage 5's checkSceneTable)
  EXPECT_NO_THROW(checkSceneTable(reflectionScenes()));
  // TC02: three course scenes, two viewpoints of allFeatures, the hall of mirrors
  std::set<std::string> names;
  for (const CourseScene& c : reflectionScenes()) names.insert(c.name);
  EXPECT_EQ(6u, reflectionScenes().size());
  EXPECT_EQ(1u, names.count("all-features-below"));
  EXPECT_EQ(1u, names.count("all-features-above"));
}

}  // namespace
}  // namespace rt
