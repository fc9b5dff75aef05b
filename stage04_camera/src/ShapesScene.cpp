#include "camera/ShapesScene.h"

namespace rt {

SceneSetup<Scene> shapesScene() {
  SceneSetup<Scene> setup;
  Scene& scene = setup.scene;
  scene.name = "shapes";
  scene.background = Color(20, 20, 30);
  scene.ambientLight = AmbientLight(Color::WHITE, 1.0);
  scene.geometries.add(
      Plane(Point(0, -300, 0), Vector(0, 1, 0)), Sphere(Point(-250, 180, 0), 100),
      Cylinder(70, Ray(Point(300, 200, -40), Vector(0, 3, 4)), 120),
      // wound counter-clockwise as the camera sees them: their normals face it
      Triangle(Point(-140, 320, -200), Point(60, 360, -260), Point(-100, 540, -220)),
      // in the plane -x - y + 2z = -700: the normal (-1, -1, 2)/√6
      Polygon{Point(30, 52, -309), Point(160, 72, -234), Point(200, 182, -159),
              Point(130, 262, -154), Point(20, 182, -249)},
      Tube(30, Ray(Point(0, 100, -300), Vector(2, 1, 0))));
  setup.camera = CameraSpec::squareView(Point(0, 0, 1000), Point(0, 100, 0), 800, 1000, 500);
  return setup;
}

}  // namespace rt
