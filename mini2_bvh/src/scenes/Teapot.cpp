#include "scenes/Teapot.h"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "geometries/Sphere.h"
#include "geometries/UtahTeapot.h"
#include "primitives/Checks.h"
#include "primitives/Random.h"

namespace rt {

namespace {

/// The course's placement of Newell's teapot (Teapot.h): the scale and where his origin goes.
constexpr double kScale = 28.42544;
constexpr Double3 kOrigin{0.831025, -39.8754, -1.10804};

/// Newell's z up turned to the course's y up, Newell's +y to -z: a rotation (no mirror), exact
/// (only signs and places change), so the normals turn the same way.
Double3 turned(const Double3& p) { return {p.x, p.z, -p.y}; }

/// The teapot and its light, the camera at (0,0,-1000) with `pixels` pixels a side.
SceneSetup<LitScene> teapotTest(const TeapotOptions& options, int pixels) {
  SceneSetup<LitScene> setup;
  LitScene& s = setup.scene;
  const std::uint32_t red = s.addAppearance(Color(200, 0, 0), Material::course(0.5, 0.5, 60));
  s.addMesh(teapotMesh(options), red);
  requireNonNegative(options.floor, "teapotScene", "floor");
  if (options.floor > 0) {
    // Wound so that both normals are +y: (0,0,2L) x (2L,0,2L) and (2L,0,2L) x (2L,0,0).
    const double l = options.floor, y = kOrigin.y;
    s.addMesh(
        std::make_shared<const TriangleMesh>(
            std::vector<Point>{Point(-l, y, -l), Point(-l, y, l), Point(l, y, l), Point(l, y, -l)},
            std::vector<TriangleMesh::Indices>{{0, 1, 2}, {0, 2, 3}}),
        s.addAppearance(Color(20, 20, 20), Material::course(0.6, 0, 0)));
  }
  s.addLight(PointLight(Color(500, 500, 500), Point(100, 0, -100)).setKq(0.000001));
  setup.camera = CameraSpec::squareView(Point(0, 0, -1000), Vector(0, 0, 1), 200, 1000, pixels);
  return setup;
}

}  // namespace

std::shared_ptr<const TriangleMesh> teapotMesh(const TeapotOptions& options) {
  std::vector<Point> vertices;
  std::vector<Double3> normals;
  std::vector<TriangleMesh::Indices> triangles;
  {  // Newell's mesh is freed before the placed one is built: at 10^6 triangles, 36 MB less
    const TriangleMesh newell = utahTeapot(options.detail);
    vertices.reserve(newell.vertexCount());
    for (const Point& p : newell.vertices())
      vertices.emplace_back(turned(p.xyz()) * kScale + kOrigin);
    if (options.smooth) {
      normals.reserve(newell.vertexCount());
      for (const Vector& n : newell.normals()) normals.push_back(turned(n.xyz()));
    }
    triangles = newell.triangles();
  }
  return std::make_shared<const TriangleMesh>(std::move(vertices), std::move(triangles),
                                              std::move(normals));
}

SceneSetup<LitScene> teapotScene(const TeapotOptions& options) {
  SceneSetup<LitScene> setup = teapotTest(options, 800);
  setup.scene.name = "Teapot";
  return setup;
}

SceneSetup<LitScene> bubblesScene(const TeapotOptions& options, const BubbleOptions& bubbles) {
  requireBetween(bubbles.count, 0, BubbleOptions::MAX_COUNT, "bubblesScene", "count");
  SceneSetup<LitScene> setup = teapotTest(options, 1000);
  LitScene& s = setup.scene;
  s.name = "Teapot with bubbles";
  const auto count = static_cast<std::uint32_t>(bubbles.count);
  s.geometries.reserve(count);
  s.appearanceIndex.reserve(count);
  s.appearances.reserve(s.appearances.size() + count);
  for (std::uint32_t i = 0; i < count; ++i) {
    RandomStream r(bubbles.seed, i, 0, 0);
    const double height = 70 * r.next();
    const double distance = 0.3 * height * r.next();
    const double angle = 2 * std::numbers::pi * r.next();
    const double radius = 0.1 + 0.9 * r.next();
    Material m = Material::course(0, 0.2, 0, 0, 0.1);
    const double red = r.next(), green = r.next(), blue = r.next();  // in this order
    m.kD = Double3(0.1 * red, 0.1 * green, 0.1 * blue);
    s.add(Sphere(
              Point(90 + distance * std::cos(angle), 30 + height, 0.2 + distance * std::sin(angle)),
              radius),
          Color::BLACK, m);
  }
  return setup;
}

}  // namespace rt
