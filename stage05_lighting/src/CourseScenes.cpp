#include "lighting/CourseScenes.h"

#include <array>

#include "geometries/Sphere.h"
#include "geometries/Triangle.h"
#include "lighting/LightSource.h"
#include "lighting/Material.h"

namespace rt {
namespace course {

namespace {

// ---- RenderTests -------------------------------------------------------------------------

CameraSpec renderTestsCamera() {
  CameraSpec c;
  c.location = Point::ZERO;
  c.to = Vector(0, 0, -1);
  c.up = Vector::AXIS_Y;
  c.vpWidth = 500;
  c.vpHeight = 500;
  c.vpDistance = 100;
  c.nX = 1000;
  c.nY = 1000;
  return c;
}

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

/// camera1 / camera2: at (0,0,1000) looking at the origin, up +Y, distance 1000.
CameraSpec lightsCamera(double vpSize, int pixels) {
  CameraSpec c;
  c.location = Point(0, 0, 1000);
  c.to = Vector(0, 0, -1);
  c.up = Vector::AXIS_Y;
  c.vpWidth = vpSize;
  c.vpHeight = vpSize;
  c.vpDistance = 1000;
  c.nX = pixels;
  c.nY = pixels;
  return c;
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

/// scene2 (ambient WHITE x 0.15) with the two triangles, seen by camera2.
SceneSetup<LitScene> trianglesScene(const char* name, double ambientKa) {
  SceneSetup<LitScene> s;
  s.scene.name = name;
  s.scene.ambientLight = AmbientLight(Color::WHITE, ambientKa);
  s.scene.add(Triangle(vertices[0], vertices[1], vertices[2]), Color::BLACK, trianglesMaterial());
  s.scene.add(Triangle(vertices[0], vertices[1], vertices[3]), Color::BLACK, trianglesMaterial());
  s.camera = lightsCamera(200, 500);
  return s;
}

}  // namespace

SceneSetup<LitScene> renderMultiColor() {
  SceneSetup<LitScene> s;
  s.scene.name = "color render test";
  s.scene.ambientLight = AmbientLight(Color::WHITE, Double3(0.2, 0.2, 0.2));
  s.scene.add(Sphere(Point(0, 0, -100), 50));
  s.scene.add(Triangle(Point(-100, 0, -100), Point(0, 100, -100), Point(-100, 100, -100)),
              Color::GREEN);  // up left
  s.scene.add(Triangle(Point(-100, 0, -100), Point(0, -100, -100), Point(-100, -100, -100)),
              Color::RED);  // down left
  s.scene.add(Triangle(Point(100, 0, -100), Point(0, -100, -100), Point(100, -100, -100)),
              Color::BLUE);  // down right
  s.camera = renderTestsCamera();
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
  SceneSetup<LitScene> s = trianglesScene("lightTrianglesDirectional", 0.15);
  s.scene.addLight(DirectionalLight(trianglesLightColor(), trianglesLightDirection()));
  return s;
}

SceneSetup<LitScene> trianglesPoint() {
  SceneSetup<LitScene> s = trianglesScene("lightTrianglesPoint", 0.15);
  s.scene.addLight(
      PointLight(trianglesLightColor(), trianglesLightPosition).setKl(0.001).setKq(0.0002));
  return s;
}

SceneSetup<LitScene> trianglesSpot() {
  SceneSetup<LitScene> s = trianglesScene("lightTrianglesSpot", 0.15);
  s.scene.addLight(
      SpotLight(trianglesLightColor(), trianglesLightPosition, trianglesLightDirection())
          .setKl(0.001)
          .setKq(0.0001));
  return s;
}

SceneSetup<LitScene> trianglesSpotSharp() {
  SceneSetup<LitScene> s = trianglesScene("lightTrianglesSpotSharp", 0.15);
  s.scene.addLight(
      SpotLight(trianglesLightColor(), trianglesLightPosition, trianglesLightDirection())
          .setKl(0.001)
          .setKq(0.00004)
          .setNarrowBeam(10));
  return s;
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
  SceneSetup<LitScene> s = trianglesScene("MultipleTestTriangle", 0.05);
  s.scene.addLight(DirectionalLight(Color(200, 10, 40), Vector(-3, 3, -3)));
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

}  // namespace rt
