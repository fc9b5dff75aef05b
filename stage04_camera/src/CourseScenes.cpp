#include "camera/CourseScenes.h"

namespace rt {

SceneSetup<Scene> twoColorScene() {
  SceneSetup<Scene> setup;
  Scene& scene = setup.scene;
  scene.name = "base render test";
  scene.background = Color(75, 127, 90);
  scene.ambientLight = AmbientLight(Color(255, 191, 191), 1.0);
  scene.geometries.add(
      Sphere(Point(0, 0, -100), 50),
      // up-left
      Triangle(Point(-100, 0, -100), Point(0, 100, -100), Point(-100, 100, -100)),
      // down-left
      Triangle(Point(-100, 0, -100), Point(0, -100, -100), Point(-100, -100, -100)),
      // down-right
      Triangle(Point(100, 0, -100), Point(0, -100, -100), Point(100, -100, -100)));

  CameraSpec& camera = setup.camera;
  camera.location = Point::ZERO;
  camera.to = Vector(0, 0, -1);
  camera.up = Vector::AXIS_Y;
  camera.vpDistance = 100;
  camera.vpWidth = 500;
  camera.vpHeight = 500;
  camera.nX = 1000;
  camera.nY = 1000;
  return setup;
}

}  // namespace rt
