#include "shadows/CourseScenes.h"

#include "geometries/Sphere.h"
#include "geometries/Triangle.h"
#include "lighting/LightSource.h"
#include "lighting/Material.h"
#include "primitives/Color.h"

namespace rt {
namespace course {

namespace {

/// The ShadowTests camera: at (0,0,1000) looking at the origin, up +Y, view plane 200x200 at
/// distance 1000.
CameraSpec shadowCamera(int pixels) {
  return CameraSpec::squareView(Point(0, 0, 1000), Vector(0, 0, -1), 200, 1000, pixels);
}

/// kD 0.5, kS 0.5, nSh 30: the sphere's and the triangle's material in sphereTriangle*.
Material sphereTriangleMaterial() {
  Material m;
  m.kD = Double3(0.5);
  m.kS = Double3(0.5);
  m.shininess = 30;
  return m;
}

/// The course's sphereTriangleHelper: the sphere, the given triangle and the spot light at the
/// given position.
SceneSetup<LitScene> sphereTriangle(const char* name, const Triangle& triangle,
                                    const Point& spotLocation) {
  SceneSetup<LitScene> s;
  s.scene.name = name;
  s.scene.add(Sphere(Point(0, 0, -200), 60), Color::BLUE, sphereTriangleMaterial());
  s.scene.add(triangle, Color::BLUE, sphereTriangleMaterial());
  s.scene.addLight(
      SpotLight(Color(400, 240, 0), spotLocation, Vector(1, 1, -3)).setKl(1e-5).setKq(1.5e-7));
  s.camera = shadowCamera(400);
  return s;
}

Triangle initialTriangle() {
  return Triangle(Point(-70, -40, 0), Point(-40, -70, 0), Point(-68, -68, -4));
}

const Point initialLight{-100, -100, 200};

}  // namespace

SceneSetup<LitScene> sphereTriangleInitial() {
  return sphereTriangle("shadowSphereTriangleInitial", initialTriangle(), initialLight);
}

SceneSetup<LitScene> sphereTriangleMove1() {
  return sphereTriangle("shadowSphereTriangleMove1",
                        Triangle(Point(-60, -30, 0), Point(-30, -60, 0), Point(-58, -58, -4)),
                        initialLight);
}

SceneSetup<LitScene> sphereTriangleMove2() {
  return sphereTriangle("shadowSphereTriangleMove2",
                        Triangle(Point(-50, -20, 0), Point(-20, -50, 0), Point(-48, -48, -4)),
                        initialLight);
}

SceneSetup<LitScene> sphereTriangleSpot1() {
  return sphereTriangle("shadowSphereTriangleSpot1", initialTriangle(), Point(-85, -85, 105));
}

SceneSetup<LitScene> sphereTriangleSpot2() {
  return sphereTriangle("shadowSphereTriangleSpot2", initialTriangle(), Point(-75, -75, 65));
}

SceneSetup<LitScene> trianglesSphere() {
  SceneSetup<LitScene> s;
  s.scene.name = "shadowTrianglesSphere";
  s.scene.ambientLight = AmbientLight(Color::WHITE, 0.15);
  Material triangles;
  triangles.kS = Double3(0.8);
  triangles.shininess = 60;
  s.scene.add(Triangle(Point(-150, -150, -115), Point(150, -150, -135), Point(75, 75, -150)),
              Color::BLACK, triangles);
  s.scene.add(Triangle(Point(-150, -150, -115), Point(-70, 70, -140), Point(75, 75, -150)),
              Color::BLACK, triangles);
  s.scene.add(Sphere(Point(0, 0, -11), 30), Color::BLUE, sphereTriangleMaterial());
  s.scene.addLight(SpotLight(Color(700, 400, 400), Point(40, 40, 115), Vector(-1, -1, -4))
                       .setKl(4e-4)
                       .setKq(2e-5));
  s.camera = shadowCamera(600);
  return s;
}

}  // namespace course

std::span<const CourseScene> shadowScenes() {
  static const CourseScene table[] = {
      {"shadow-sphere-triangle-initial",
       "ShadowTests: a triangle between a spot light and a sphere casts its shadow on the sphere",
       &course::sphereTriangleInitial},
      {"shadow-sphere-triangle-move1", "ShadowTests: the triangle moved towards the sphere",
       &course::sphereTriangleMove1},
      {"shadow-sphere-triangle-move2", "ShadowTests: the triangle moved closer to the sphere",
       &course::sphereTriangleMove2},
      {"shadow-sphere-triangle-spot1", "ShadowTests: the spot light moved towards the triangle",
       &course::sphereTriangleSpot1},
      {"shadow-sphere-triangle-spot2", "ShadowTests: the spot light moved closer to the triangle",
       &course::sphereTriangleSpot2},
      {"shadow-triangles-sphere",
       "ShadowTests: a sphere above two specular triangles casts its shadow on them",
       &course::trianglesSphere},
  };
  return table;
}

}  // namespace rt
