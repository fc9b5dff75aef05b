#include "lighting/CourseScenes.h"

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "camera/Camera.h"
#include "camera/CourseScenes.h"
#include "geometries/Sphere.h"
#include "geometries/Triangle.h"
#include "lighting/LightSource.h"
#include "lighting/Material.h"

namespace rt {
namespace course {

namespace {

// ---- LightsTests: the shared values of the course's test class ------------------------------

constexpr int SHININESS = 301;
constexpr double KD = 0.5;
constexpr Double3 KD3{0.2, 0.6, 0.4};
constexpr double KS = 0.5;
constexpr Double3 KS3{0.2, 0.4, 0.3};

Color trianglesLightColor() { return Color(800, 500, 250); }
Color sphereLightColor() { return Color(800, 500, 0); }
Color sphereColor() { return Color::BLUE / 2; }  // (0,0,127.5)

const Point sphereCenter{0, 0, -50};
constexpr double SPHERE_RADIUS = 50;
const std::array<Point, 4> vertices{Point(-110, -110, -150), Point(95, 100, -150),
                                    Point(110, -110, -150), Point(-75, 78, 100)};
const Point sphereLightPosition{-50, -50, 25};
Vector sphereLightDirection() { return Vector(1, 1, -0.5); }
const Point trianglesLightPosition{30, 10, -100};
Vector trianglesLightDirection() { return Vector(-2, -2, -2); }

Material sphereMaterial() {
  Material m;
  m.kD = Double3(KD);
  m.kS = Double3(KS);
  m.shininess = SHININESS;
  return m;
}

Material trianglesMaterial() {
  Material m;
  m.kD = KD3;
  m.kS = KS3;
  m.shininess = SHININESS;
  return m;
}

/// camera1 / camera2: at (0,0,1000) looking along -Z (at the origin), up +Y, distance 1000.
CameraSpec lightsCamera(double vpSize, int pixels) {
  return CameraSpec::squareView(Point(0, 0, 1000), Vector(0, 0, -1), vpSize, 1000, pixels);
}

/// scene1 with the sphere, seen by camera1.
SceneSetup<LitScene> sphereScene(const char* name, LightSource light) {
  SceneSetup<LitScene> s;
  s.scene.name = name;
  s.scene.add(Sphere(sphereCenter, SPHERE_RADIUS), sphereColor(), sphereMaterial());
  s.scene.addLight(std::move(light));
  s.camera = lightsCamera(150, 500);
  return s;
}

/// scene2 (ambient WHITE x ambientKa, 0.15 in LightsTests) with the two triangles and the
/// light, seen by camera2.
SceneSetup<LitScene> trianglesScene(const char* name, double ambientKa, LightSource light) {
  SceneSetup<LitScene> s;
  s.scene.name = name;
  s.scene.ambientLight = AmbientLight(Color::WHITE, ambientKa);
  s.scene.add(Triangle(vertices[0], vertices[1], vertices[2]), Color::BLACK, trianglesMaterial());
  s.scene.add(Triangle(vertices[0], vertices[1], vertices[3]), Color::BLACK, trianglesMaterial());
  s.scene.addLight(std::move(light));
  s.camera = lightsCamera(200, 500);
  return s;
}

}  // namespace

SceneSetup<LitScene> renderMultiColor() {
  // Stage 4's two-colour scene (its shapes and camera), with other lights and emissions.
  SceneSetup<Scene> base = twoColorScene();
  SceneSetup<LitScene> s{LitScene(base.scene), base.camera};
  s.scene.name = "color render test";
  s.scene.background = Color::BLACK;
  s.scene.ambientLight = AmbientLight(Color::WHITE, Double3(0.2, 0.2, 0.2));
  // Geometry 0 is the sphere, which keeps the default appearance (row 0).
  s.scene.appearanceIndex[1] = s.scene.addAppearance(Color::GREEN);  // up left
  s.scene.appearanceIndex[2] = s.scene.addAppearance(Color::RED);    // down left
  s.scene.appearanceIndex[3] = s.scene.addAppearance(Color::BLUE);   // down right
  return s;
}

SceneSetup<LitScene> sphereDirectional() {
  return sphereScene("lightSphereDirectional",
                     DirectionalLight(sphereLightColor(), sphereLightDirection()));
}

SceneSetup<LitScene> spherePoint() {
  return sphereScene(
      "lightSpherePoint",
      PointLight(sphereLightColor(), sphereLightPosition).setKl(0.001).setKq(0.0002));
}

SceneSetup<LitScene> sphereSpot() {
  return sphereScene("lightSphereSpot",
                     SpotLight(sphereLightColor(), sphereLightPosition, sphereLightDirection())
                         .setKl(0.001)
                         .setKq(0.0001));
}

SceneSetup<LitScene> sphereSpotSharp() {
  return sphereScene("lightSphereSpotSharp",
                     SpotLight(sphereLightColor(), sphereLightPosition, sphereLightDirection())
                         .setKl(0.001)
                         .setKq(0.00004)
                         .setNarrowBeam(10));
}

SceneSetup<LitScene> trianglesDirectional() {
  return trianglesScene("lightTrianglesDirectional", 0.15,
                        DirectionalLight(trianglesLightColor(), trianglesLightDirection()));
}

SceneSetup<LitScene> trianglesPoint() {
  return trianglesScene(
      "lightTrianglesPoint", 0.15,
      PointLight(trianglesLightColor(), trianglesLightPosition).setKl(0.001).setKq(0.0002));
}

SceneSetup<LitScene> trianglesSpot() {
  return trianglesScene(
      "lightTrianglesSpot", 0.15,
      SpotLight(trianglesLightColor(), trianglesLightPosition, trianglesLightDirection())
          .setKl(0.001)
          .setKq(0.0001));
}

SceneSetup<LitScene> trianglesSpotSharp() {
  return trianglesScene(
      "lightTrianglesSpotSharp", 0.15,
      SpotLight(trianglesLightColor(), trianglesLightPosition, trianglesLightDirection())
          .setKl(0.001)
          .setKq(0.00004)
          .setNarrowBeam(10));
}

SceneSetup<LitScene> sphereMultiLight() {
  SceneSetup<LitScene> s =
      sphereScene("MultipleTest", DirectionalLight(Color(550, 120, 30), Vector(3, 1, 2)));
  s.scene.addLight(PointLight(Color(550, 120, 30), Point(50, 100, 50)).setKl(0.0005).setKq(0.0002));
  s.scene.addLight(SpotLight(Color(300, 500, 30), Point(60, -130, 100), Vector(0, 1.2, -1))
                       .setKl(0.001)
                       .setKq(0.00003)
                       .setNarrowBeam(8));
  s.camera.nX = 1000;
  s.camera.nY = 1000;
  return s;
}

SceneSetup<LitScene> trianglesMultiLight() {
  SceneSetup<LitScene> s = trianglesScene("MultipleTestTriangle", 0.05,
                                          DirectionalLight(Color(200, 10, 40), Vector(-3, 3, -3)));
  s.scene.addLight(PointLight(Color(150, 350, 510), Point(70, 50, -50)).setKl(0.001).setKq(0.0001));
  s.scene.addLight(SpotLight(Color(0, 0, 800), Point(50, -200, 50), Vector(0, 1.2, -1))
                       .setKl(0.001)
                       .setKq(0.0001)
                       .setNarrowBeam(10));
  return s;
}

}  // namespace course

std::span<const CourseScene> lightingScenes() {
  static const CourseScene table[] = {
      {"color-render",
       "RenderTests multi-colour: three emitting triangles and a sphere, ambient only",
       &course::renderMultiColor, 100, Color::WHITE},
      {"light-sphere-directional", "LightsTests: sphere under a directional light",
       &course::sphereDirectional},
      {"light-sphere-point", "LightsTests: sphere under an attenuated point light",
       &course::spherePoint},
      {"light-sphere-spot", "LightsTests: sphere under a spot light", &course::sphereSpot},
      {"light-sphere-spot-sharp", "LightsTests: sphere under a focused spot light (narrow beam 10)",
       &course::sphereSpotSharp},
      {"light-triangles-directional", "LightsTests: two triangles under a directional light",
       &course::trianglesDirectional},
      {"light-triangles-point", "LightsTests: two triangles under an attenuated point light",
       &course::trianglesPoint},
      {"light-triangles-spot", "LightsTests: two triangles under a spot light",
       &course::trianglesSpot},
      {"light-triangles-spot-sharp",
       "LightsTests: two triangles under a focused spot light (narrow beam 10)",
       &course::trianglesSpotSharp},
      {"light-sphere-multi", "tomi832: sphere under a directional, a point and a spot light",
       &course::sphereMultiLight},
      {"light-triangles-multi", "tomi832: two triangles under three coloured lights",
       &course::trianglesMultiLight},
  };
  return table;
}

namespace {

[[noreturn]] void throwBadEntry(std::size_t index, const char* name, const std::string& what) {
  throw std::logic_error("checkSceneTable: entry " + std::to_string(index) + " ('" +
                         (name ? name : "(null)") + "'): " + what);
}

}  // namespace

void checkSceneTable(std::span<const CourseScene> table) {
  for (std::size_t i = 0; i < table.size(); ++i) {
    const CourseScene& entry = table[i];
    const std::string name = entry.name ? entry.name : "";
    if (name.empty()) throwBadEntry(i, entry.name, "no name");
    if (name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos)
      throwBadEntry(i, entry.name, "the name is not kebab-case (a-z, 0-9, '-')");
    for (std::size_t j = 0; j < i; ++j) {
      if (table[j].name && name == table[j].name)
        throwBadEntry(i, entry.name, "duplicate name, as entry " + std::to_string(j));
    }
    if (!entry.description || std::strlen(entry.description) <= 10)
      throwBadEntry(i, entry.name,
                    "description '" + std::string(entry.description ? entry.description : "") +
                        "' has 10 characters or fewer");
    if (!entry.make) throwBadEntry(i, entry.name, "no make function");
    SceneSetup<LitScene> setup;
    try {
      setup = entry.make();
    } catch (const std::exception& e) {
      throwBadEntry(i, entry.name, std::string("its make function throws: ") + e.what());
    }
    if (setup.scene.name.empty()) throwBadEntry(i, entry.name, "its scene has no name");
    try {
      setup.scene.validate();
    } catch (const std::exception& e) {
      throwBadEntry(i, entry.name, std::string("its scene does not hold together: ") + e.what());
    }
    try {
      (void)setup.camera.builder().build();
    } catch (const std::exception& e) {
      throwBadEntry(i, entry.name, std::string("its camera does not build: ") + e.what());
    }
  }
}

}  // namespace rt
