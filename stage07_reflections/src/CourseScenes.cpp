#include "reflections/CourseScenes.h"

#include <array>

#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "geometries/Sphere.h"
#include "geometries/Triangle.h"
#include "lighting/LightSource.h"
#include "lighting/Material.h"
#include "primitives/Color.h"

namespace rt {
namespace course {

namespace {

/// The allFeatures camera: at `location` looking at (0,60,0), up +Y, view plane 200x200,
/// 1200x1200 pixels.
CameraSpec allFeaturesCamera(const Point& location, double distance) {
  return CameraSpec::squareView(location, Point(0, 60, 0), 200, distance, 1200);
}

/// The allFeaturesTest scene (catalogue §6); the camera is set by the caller.
LitScene allFeaturesScene(const char* name) {
  LitScene s;
  s.name = name;
  s.ambientLight = AmbientLight(Color::WHITE, 0.005);

  // The floor y = 0.
  s.add(Plane(Point::ZERO, Vector(0, 1, 0)), Color(30, 40, 70),
        Material::course(0.9, 0, 30, 0, 0.05));

  // The bi-pyramid: apexes (0,0,0) and (0,120,0) around the square y = 60, corners (±30,±30).
  const Point bottom(0, 0, 0), top(0, 120, 0);
  const std::array<Point, 4> square{Point(30, 60, 30), Point(30, 60, -30), Point(-30, 60, -30),
                                    Point(-30, 60, 30)};
  const Material glassy = Material::course(0.5, 0.5, 60, 0.3);
  for (int i = 0; i < 4; ++i) {
    s.add(Triangle(bottom, square[i], square[(i + 1) % 4]), Color(35, 120, 280), glassy);
  }
  for (int i = 0; i < 4; ++i) {
    s.add(Triangle(top, square[i], square[(i + 1) % 4]), Color(35, 140, 240), glassy);
  }
  // The mirror-like sphere inside the pyramid, and the reflective green one further back.
  s.add(Sphere(Point(0, 60, 0), 20), Color(100, 100, 100), Material::course(0.5, 0.5, 60, 0, 0.8));
  s.add(Sphere(Point(-170, 30, -200), 20), Color(10, 50, 15),
        Material::course(0.4, 0.6, 10, 0, 0.55));

  // The transparent cube x, z in [30,50], y in [5,25]. The catalogue gives no shininess: the
  // course's default 0. Faces in the order front, top, right, back, bottom, left, alternating
  // the two reds, so every pair of opposite faces differs.
  const Material cube = Material::course(0.5, 0.3, 0, 0.45);
  const double x0 = 30, x1 = 50, y0 = 5, y1 = 25, z0 = 30, z1 = 50;
  const Color red1(255, 50, 50), red2(300, 20, 20);
  s.add(Polygon{Point(x0, y0, z1), Point(x1, y0, z1), Point(x1, y1, z1), Point(x0, y1, z1)}, red1,
        cube);  // front z = 50
  s.add(Polygon{Point(x0, y1, z0), Point(x0, y1, z1), Point(x1, y1, z1), Point(x1, y1, z0)}, red2,
        cube);  // top y = 25
  s.add(Polygon{Point(x1, y0, z0), Point(x1, y1, z0), Point(x1, y1, z1), Point(x1, y0, z1)}, red1,
        cube);  // right x = 50
  s.add(Polygon{Point(x0, y0, z0), Point(x0, y1, z0), Point(x1, y1, z0), Point(x1, y0, z0)}, red2,
        cube);  // back z = 30
  s.add(Polygon{Point(x0, y0, z0), Point(x1, y0, z0), Point(x1, y0, z1), Point(x0, y0, z1)}, red1,
        cube);  // bottom y = 5
  s.add(Polygon{Point(x0, y0, z0), Point(x0, y0, z1), Point(x0, y1, z1), Point(x0, y1, z0)}, red2,
        cube);  // left x = 30

  // The small glass sphere wrapping the point light.
  s.add(Sphere(Point(-20, 3.5, 40), 3), Color(120, 120, 120), Material::course(0, 0, 0, 0.8));

  s.addLight(PointLight(Color(200, 200, 200), Point(-20, 3, 40)).setKl(0.01).setKq(0.001));
  s.addLight(SpotLight(Color(100, 180, 210), Point(100, 80, 0), Vector(-100, -30, 0))
                 .setKl(4e-5)
                 .setKq(2e-7));
  s.addLight(DirectionalLight(Color(25, 0, 45), Vector(1, -1, 1)));
  return s;
}

}  // namespace

SceneSetup<LitScene> twoSpheres() {
  SceneSetup<LitScene> s;
  s.scene.name = "refractionTwoSpheres";
  s.scene.add(Sphere(Point(0, 0, -50), 50), Color::BLUE, Material::course(0.4, 0.3, 100, 0.3));
  s.scene.add(Sphere(Point(0, 0, -50), 25), Color::RED, Material::course(0.5, 0.5, 100));
  s.scene.addLight(SpotLight(Color(1000, 600, 0), Point(-100, -100, 500), Vector(-1, -1, -2))
                       .setKl(0.0004)
                       .setKq(0.0000006));
  s.camera = CameraSpec::squareView(Point(0, 0, 1000), Vector(0, 0, -1), 150, 1000, 500);
  return s;
}

SceneSetup<LitScene> twoSpheresOnMirrors() {
  SceneSetup<LitScene> s;
  s.scene.name = "reflectionTwoSpheresMirrored";
  s.scene.ambientLight = AmbientLight(Color::WHITE, 0.1);
  Material outer = Material::course(0.25, 0.25, 20);
  outer.kT = Double3(0.5, 0, 0);
  s.scene.add(Sphere(Point(-950, -900, -1000), 400), Color(0, 50, 100), outer);
  s.scene.add(Sphere(Point(-950, -900, -1000), 200), Color(100, 50, 20),
              Material::course(0.25, 0.25, 20));
  s.scene.add(Triangle(Point(1500, -1500, -1500), Point(-1500, 1500, -1500), Point(670, 670, 3000)),
              Color(20, 20, 20), Material::course(0, 0, 0, 0, 1));
  Material tinted;
  tinted.kR = Double3(0.5, 0, 0.4);
  s.scene.add(
      Triangle(Point(1500, -1500, -1500), Point(-1500, 1500, -1500), Point(-1500, -1500, -2000)),
      Color(20, 20, 20), tinted);
  s.scene.addLight(SpotLight(Color(1020, 400, 400), Point(-750, -750, -150), Vector(-1, -1, -4))
                       .setKl(0.00001)
                       .setKq(0.000005));
  s.camera = CameraSpec::squareView(Point(0, 0, 10000), Vector(0, 0, -1), 2500, 10000, 500);
  return s;
}

SceneSetup<LitScene> trianglesTransparentSphere() {
  SceneSetup<LitScene> s;
  s.scene.name = "refractionShadow";
  s.scene.ambientLight = AmbientLight(Color::WHITE, 0.15);
  s.scene.add(Triangle(Point(-150, -150, -115), Point(150, -150, -135), Point(75, 75, -150)),
              Color::BLACK, Material::course(0.5, 0.5, 60));
  s.scene.add(Triangle(Point(-150, -150, -115), Point(-70, 70, -140), Point(75, 75, -150)),
              Color::BLACK, Material::course(0.5, 0.5, 60));
  s.scene.add(Sphere(Point(60, 50, -50), 30), Color::BLUE, Material::course(0.2, 0.2, 30, 0.6));
  s.scene.addLight(
      SpotLight(Color(700, 400, 400), Point(60, 50, 0), Vector(0, 0, -1)).setKl(4e-5).setKq(2e-7));
  s.camera = CameraSpec::squareView(Point(0, 0, 1000), Vector(0, 0, -1), 200, 1000, 600);
  return s;
}

SceneSetup<LitScene> allFeaturesBelow() {
  return {allFeaturesScene("allFeaturesFromBelow"), allFeaturesCamera(Point(100, 20, 1000), 1000)};
}

SceneSetup<LitScene> allFeaturesAbove() {
  return {allFeaturesScene("allFeaturesFromAbove"), allFeaturesCamera(Point(250, 300, 1000), 700)};
}

SceneSetup<LitScene> hallOfMirrors() {
  SceneSetup<LitScene> s;
  s.scene.name = "hallOfMirrors";
  s.scene.ambientLight = AmbientLight(Color::WHITE, 0.05);
  const Material mirror = Material::course(0, 0, 0, 0, 0.9);
  s.scene.add(Polygon{Point(-400, -50, -150), Point(400, -50, -150), Point(400, 250, -150),
                      Point(-400, 250, -150)},
              Color(5, 5, 8), mirror);
  s.scene.add(Polygon{Point(-400, -50, 150), Point(-400, 250, 150), Point(400, 250, 150),
                      Point(400, -50, 150)},
              Color(5, 5, 8), mirror);
  s.scene.add(Plane(Point(0, -50, 0), Vector(0, 1, 0)), Color(40, 40, 40),
              Material::course(0.6, 0.2, 20));
  s.scene.add(Sphere(Point(-40, -20, -60), 30), Color(120, 10, 10), Material::course(0.5, 0.5, 60));
  s.scene.add(Sphere(Point(50, -30, 40), 20), Color(10, 100, 20), Material::course(0.5, 0.5, 60));
  s.scene.addLight(PointLight(Color(400, 400, 350), Point(0, 150, 0)).setKl(0.001).setKq(0.00005));
  s.camera = CameraSpec::squareView(Point(60, 40, 120), Point(-20, -10, -150), 200, 150, 600);
  return s;
}

}  // namespace course

std::span<const CourseScene> reflectionScenes() {
  static const CourseScene table[] = {
      {"refraction-two-spheres",
       "ReflectionRefractionTests: a red sphere seen through a transparent blue one",
       &course::twoSpheres},
      {"reflection-two-spheres-mirrored",
       "ReflectionRefractionTests: two nested spheres reflected in two large mirrors",
       &course::twoSpheresOnMirrors},
      {"refraction-shadow",
       "ReflectionRefractionTests: a transparent sphere casts a partial shadow on two triangles",
       &course::trianglesTransparentSphere},
      {"all-features-below",
       "allFeaturesTest: 18 shapes with every effect (reflection, refraction, shadows), from below",
       &course::allFeaturesBelow},
      {"all-features-above", "allFeaturesTest: the same scene seen from above",
       &course::allFeaturesAbove},
      {"hall-of-mirrors", "Two parallel mirrors repeating two spheres into the distance",
       &course::hallOfMirrors},
  };
  return table;
}

}  // namespace rt
