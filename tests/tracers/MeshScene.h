#pragma once
// The triangle-mesh scene of the no-allocation tests: the teapot with its vertex normals (smooth)
// and a flat mesh (a square of two triangles as a mirror behind it), on a floor, with a glass
// sphere, every light type, shadows through the meshes, reflection and refraction; and the camera
// that sees it.

#include <memory>
#include <vector>

#include "camera/Camera.h"
#include "geometries/UtahTeapot.h"
#include "lighting/LitScene.h"

namespace rt::test {

inline LitScene meshScene() {
  LitScene scene;
  scene.background = Color(5, 5, 5);
  scene.ambientLight = AmbientLight(Color::WHITE, 0.1);
  Material pot;
  pot.kD = Double3(0.5);
  pot.kS = Double3(0.5);
  pot.shininess = 60;
  pot.kR = Double3(0.1);
  scene.addMesh(std::make_shared<const TriangleMesh>(utahTeapot(4)),
                scene.addAppearance(Color(60, 10, 0), pot));
  Material mirror;
  mirror.kR = Double3(0.9);
  scene.addMesh(
      std::make_shared<const TriangleMesh>(
          std::vector<Point>{Point(-6, -4, 0), Point(6, -4, 0), Point(6, -4, 6), Point(-6, -4, 6)},
          std::vector<TriangleMesh::Indices>{{0, 1, 2}, {0, 2, 3}}),
      scene.addAppearance(Color::BLACK, mirror));
  Material floor;
  floor.kD = Double3(0.6);
  floor.kS = Double3(0.2);
  floor.shininess = 20;
  scene.add(Plane(Point(0, 0, 0), Vector(0, 0, 1)), Color(20, 20, 20), floor);
  Material glass;
  glass.kS = Double3(0.5);
  glass.shininess = 50;
  glass.kT = Double3(0.7);
  glass.kR = Double3(0.2);
  glass.ior = 1.5;
  scene.add(Sphere(Point(4, 2, 1.2), 1.2), Color(0, 0, 20), glass);
  scene.addLight(DirectionalLight(Color(100, 100, 100), Vector(1, 1, -1)));
  scene.addLight(PointLight(Color(300, 300, 300), Point(3, 8, 8)).setKl(0.01).setKq(0.001));
  scene.addLight(SpotLight(Color(300, 200, 100), Point(-5, 6, 5), Vector(1, -1, -1))
                     .setKl(0.01)
                     .setNarrowBeam(4));
  return scene;
}

/// 40 x 40 pixels from the front, above: the teapot fills the middle, the mirror behind it.
inline Camera meshSceneCamera() {
  return Camera::builder()
      .setLocation(Point(0, 14, 6))
      .setDirection(Point(0, 0, 1.5), Vector(0, 0, 1))
      .setVpSize(10, 10)
      .setVpDistance(20)
      .setResolution(40, 40)
      .build();
}

}  // namespace rt::test
