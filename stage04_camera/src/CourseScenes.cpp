#include "camera/CourseScenes.h"

namespace rt {

CameraSpec renderTestsCamera() {
  return CameraSpec::squareView(Point::ZERO, Vector(0, 0, -1), 500, 100, 1000);
}

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

  setup.camera = renderTestsCamera();
  return setup;
}

}  // namespace rt
