#include "glossy/DemoScenes.h"

#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "geometries/Cylinder.h"
#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "geometries/Sphere.h"

namespace rt {

namespace demo {

namespace {

/// nx x nz square tiles of side `tile` on the plane y = 0 from corner (x0, z0), alternating the
/// looks a and b (a at the corner), each face's normal +Y; only the tiles whose centre (x, z)
/// passes keep(x, z), when given.
template <typename Keep = bool (*)(double, double)>
void addCheckerboard(LitScene& s, double x0, double z0, double tile, int nx, int nz,
                     std::uint32_t a, std::uint32_t b, Keep keep = nullptr) {
  for (int k = 0; k < nz; ++k) {
    for (int i = 0; i < nx; ++i) {
      const double x = x0 + i * tile, z = z0 + k * tile;
      if constexpr (!std::is_pointer_v<Keep>) {
        if (!keep(x + tile / 2, z + tile / 2)) continue;
      }
      s.add(Polygon{Point(x, 0, z), Point(x, 0, z + tile), Point(x + tile, 0, z + tile),
                    Point(x + tile, 0, z)},
            (i + k) % 2 == 0 ? a : b);
    }
  }
}

/// An empty scene named `name`: a dark background and a faint white ambient light.
LitScene darkRoom(const char* name) {
  LitScene s;
  s.name = name;
  s.background = Color(20, 22, 30);
  s.ambientLight = AmbientLight(Color::WHITE, 0.05);
  return s;
}

/// A grey checkerboard floor of nx x nz diffuse tiles of side 1 from corner (x0, z0).
void addFloorBoard(LitScene& s, double x0, double z0, int nx, int nz) {
  const std::uint32_t light = s.addAppearance(Color(20, 20, 20), Material::course(0.6, 0.1, 20));
  const std::uint32_t dark = s.addAppearance(Color(5, 5, 8), Material::course(0.15, 0.1, 20));
  addCheckerboard(s, x0, z0, 1, nx, nz, light, dark);
}

/// A camera at `from` looking at `at`, up +Y, a view plane `width` wide at `distance`, nX x nY
/// pixels (the view plane's height follows, so pixels are square).
CameraSpec view(const Point& from, const Point& at, double width, double distance, int nX, int nY) {
  CameraSpec c;
  c.location = from;
  c.target = at;
  c.vpWidth = width;
  c.vpHeight = width * nY / nX;
  c.vpDistance = distance;
  c.nX = nX;
  c.nY = nY;
  return c;
}

}  // namespace

SceneSetup<LitScene> glossySpheres(const GlossySpheresParams& params) {
  LitScene s = darkRoom("glossy spheres");
  addFloorBoard(s, -12, -20, 24, 32);
  // Behind the camera, seen only in the mirrors: a wall of coloured stripes.
  const std::array<Color, 4> stripes{Color(230, 60, 40), Color(240, 200, 60), Color(40, 120, 230),
                                     Color(235, 235, 235)};
  for (int i = 0; i < 20; ++i) {
    const double x = -15 + 1.5 * i;
    s.add(Polygon{Point(x, 0, 12), Point(x, 14, 12), Point(x + 1.5, 14, 12), Point(x + 1.5, 0, 12)},
          stripes[static_cast<std::size_t>(i) % stripes.size()]);
  }
  const std::array<double, 4> radii{0, 0.03, 0.08, 0.2};
  for (std::size_t i = 0; i < radii.size(); ++i) {
    Material m = Material::course(0.1, 0.6, 100, 0, 0.8);
    m.reflectedBeam = {1, radii[i], params.beamGrid};
    s.add(Sphere(Point(-3.3 + 2.2 * static_cast<double>(i), 1, 0), 1), Color(8, 8, 10), m);
  }
  s.addLight(PointLight(Color(210, 200, 190), Point(3, 9, 7)));
  return {s, view(Point(0, 2.4, 9), Point(0, 0.9, 0), 10.5, 9, 640, 320)};
}

SceneSetup<LitScene> frostedGlass(const FrostedGlassParams& params) {
  LitScene s = darkRoom("frosted glass");
  s.add(Plane(Point(0, 0, 0), Vector(0, 1, 0)), Color(15, 15, 15), Material::course(0.6, 0.1, 20));
  // The pattern: a wall of small coloured tiles at z = -3.
  const std::array<Color, 4> tiles{Color(230, 70, 50), Color(240, 240, 235), Color(40, 110, 220),
                                   Color(20, 20, 25)};
  const double t = 0.4;
  for (int j = 0; j < 14; ++j) {
    for (int i = 0; i < 30; ++i) {
      const double x = -6 + i * t, y = j * t;
      s.add(Polygon{Point(x, y, -3), Point(x + t, y, -3), Point(x + t, y + t, -3),
                    Point(x, y + t, -3)},
            tiles[static_cast<std::size_t>((i + 2 * j) % 4)], Material::course(0.3, 0, 0));
    }
  }
  // A sphere behind each pane, close to it: blurred less than the wall further back.
  const Material ball = Material::course(0.5, 0.5, 60);
  for (const double x : {-2.4, 0.0, 2.4})
    s.add(Sphere(Point(x + 0.45, 0.45, -1), 0.45), Color(200, 140, 20), ball);
  // The panes at z = 0: clear, then frosted with a radius of 0.05 and 0.15 at distance 1, each
  // in a thin frame just in front of it.
  const std::array<double, 3> radii{0, 0.05, 0.15};
  const std::uint32_t frame = s.addAppearance(Color(35, 35, 40), Material::course(0.3, 0.5, 40));
  const auto bar = [&](double x0, double y0, double x1, double y1) {
    s.add(
        Polygon{Point(x0, y0, 0.01), Point(x1, y0, 0.01), Point(x1, y1, 0.01), Point(x0, y1, 0.01)},
        frame);
  };
  for (std::size_t i = 0; i < radii.size(); ++i) {
    Material glass = Material::course(0.05, 0.4, 60, 0.85, 0.05);
    glass.refractedBeam = {1, radii[i], params.beamGrid};
    const double x = -2.4 + 2.4 * static_cast<double>(i), w = 0.06;
    s.add(Polygon{Point(x - 1, 0.15, 0), Point(x + 1, 0.15, 0), Point(x + 1, 2.75, 0),
                  Point(x - 1, 2.75, 0)},
          Color(4, 6, 8), glass);
    bar(x - 1 - w, 0.15 - w, x + 1 + w, 0.15);  // bottom
    bar(x - 1 - w, 2.75, x + 1 + w, 2.75 + w);  // top
    bar(x - 1 - w, 0.15, x - 1, 2.75);          // left
    bar(x + 1, 0.15, x + 1 + w, 2.75);          // right
  }
  s.addLight(PointLight(Color(220, 215, 205), Point(0, 12, 8)));
  return {s, view(Point(0, 1.6, 8), Point(0, 1.3, 0), 8.4, 8, 640, 320)};
}

SceneSetup<LitScene> softShadows(const SoftShadowsParams& params) {
  LitScene s = darkRoom("soft shadows");
  s.add(Plane(Point(0, 0, 0), Vector(0, 1, 0)), Color(20, 20, 20), Material::course(0.8, 0.05, 10));
  const Material paint = Material::course(0.6, 0.4, 60);
  s.add(Sphere(Point(-2.3, 0.8, 0.2), 0.8), Color(40, 10, 5), paint);  // resting on the floor
  s.add(Sphere(Point(0.2, 2.1, -0.2), 0.6), Color(5, 25, 45), paint);  // floating
  s.add(Cylinder(0.22, Ray(Point(1.9, 0, -1.2), Vector(0, 1, 0)), 3.2), Color(10, 30, 10),
        paint);  // a post
  s.addLight(PointLight(Color(230, 220, 200), Point(-0.5, 6, 2))
                 .setRadius(1.2)
                 .setShadowSamples(params.shadowSamples));
  return {s, view(Point(0, 4.4, 8.5), Point(0.3, 0.7, -0.8), 10, 10, 600, 400)};
}

SceneSetup<LitScene> antialiasing() {
  LitScene s;
  s.name = "antialiasing";
  s.background = Color(30, 50, 90);
  const std::uint32_t white = s.addAppearance(Color(235, 235, 235));
  const std::uint32_t black = s.addAppearance(Color(15, 15, 15));
  // Only the tiles the camera sees, within 12 of it or within 45 and 32° of its view (across the
  // floor): without the bounding volume hierarchy of mini project 2 every ray tests every tile.
  const Point from(0, 1.6, 5), at(-3, -0.4, -3);
  const double ax = at.x() - from.x(), az = at.z() - from.z(), a = std::hypot(ax, az);
  addCheckerboard(s, -80, -80, 1, 96, 96, white, black, [&](double x, double z) {
    const double dx = x - from.x(), dz = z - from.z(), d = std::hypot(dx, dz);
    return d <= 12 ||
           (d <= 45 && (dx * ax + dz * az) >= d * a * std::cos(32 * std::numbers::pi / 180));
  });
  s.add(Sphere(Point(-3.2, 0.9, -1.2), 0.6), Color(220, 40, 30));
  s.add(Sphere(Point(-0.6, 0.5, -2.4), 0.35), Color(250, 200, 40));
  return {s, view(from, at, 6, 6, 400, 300)};
}

SceneSetup<LitScene> depthOfField(const DepthOfFieldParams& params) {
  LitScene s = darkRoom("depth of field");
  addFloorBoard(s, -12, -40, 24, 48);
  const std::array<Color, 7> colours{Color(220, 50, 40), Color(230, 130, 30), Color(220, 200, 40),
                                     Color(60, 180, 70), Color(40, 150, 210), Color(70, 80, 220),
                                     Color(160, 70, 200)};
  const Material paint = Material::course(0.3, 0.5, 80);
  for (int i = 0; i < 7; ++i)
    s.add(Sphere(Point(-2.4 + 0.9 * i, 0.5, 2 - 3 * i), 0.5),
          colours[static_cast<std::size_t>(i)] * 0.6, paint);
  s.addLight(PointLight(Color(220, 215, 205), Point(-3, 8, 6)));
  const Point target(0, 0.3, -5);
  CameraSpec c = view(Point(-0.8, 2.6, 9), target, 9, 10, 640, 360);
  // Focused on the middle sphere (the fourth, centre (0.3, 0.5, -7)): the focal plane holds its
  // centre, at distance (centre − location)·vTo from the camera.
  const Double3 to = (target - c.location).xyz();
  c.focalDistance =
      (Point(0.3, 0.5, -7) - c.location).xyz().dot(to) / std::sqrt(to.lengthSquared());
  c.aperture = params.aperture;
  return {s, c};
}

SceneSetup<LitScene> adaptiveEdges() {
  LitScene s;
  s.name = "adaptive";
  s.background = Color(25, 35, 70);
  s.add(Polygon{Point(-4, -2.5, -1), Point(1.5, -2.5, -1), Point(-1.5, 2.6, -1)},
        Color(240, 190, 40));
  s.add(Sphere(Point(1.6, 0.4, 0), 1.6), Color(210, 50, 40));
  s.add(Polygon{Point(-0.5, -2.8, 0.5), Point(3.8, -2.2, 0.5), Point(3.2, -0.9, 0.5),
                Point(-0.2, -1.4, 0.5)},
        Color(40, 160, 90));
  for (int i = 0; i < 3; ++i) {  // thin bars, tilted
    const double x = -3.6 + 0.5 * i;
    s.add(Polygon{Point(x, 2.8, 1), Point(x + 0.12, 2.8, 1), Point(x + 1.2, -2.8, 1),
                  Point(x + 1.08, -2.8, 1)},
          Color(235, 235, 240));
  }
  return {s, CameraSpec::squareView(Point(0, 0, 10), Point(0, 0, 0), 6.6, 10, 300)};
}

SceneSetup<LitScene> superSampling(const SuperSamplingParams& params) {
  LitScene s = darkRoom("super-sampling");
  addFloorBoard(s, -6, -14, 12, 20);
  // A glossy sphere (its beam off while glossyGrid is 1), two coloured spheres further back.
  Material glossy = Material::course(0.1, 0.6, 100, 0, 0.8);
  glossy.reflectedBeam = {1, 0.08, params.glossyGrid};
  s.add(Sphere(Point(-1.3, 1, 0), 1), Color(8, 8, 10), glossy);
  s.add(Sphere(Point(1.2, 0.6, -4.5), 0.6), Color(150, 40, 30), Material::course(0.4, 0.5, 60));
  s.add(Sphere(Point(-0.4, 0.6, -9), 0.6), Color(30, 80, 150), Material::course(0.4, 0.5, 60));
  // A pane of glass in front of the right half of the red sphere (clear while frostedGrid is 1).
  Material glass = Material::course(0.05, 0.4, 60, 0.85, 0.05);
  glass.refractedBeam = {1, 0.08, params.frostedGrid};
  s.add(Polygon{Point(1, 0.1, -2.5), Point(3, 0.1, -2.5), Point(3, 2.3, -2.5), Point(1, 2.3, -2.5)},
        Color(4, 6, 8), glass);
  // A light of radius 1 (one shadow ray while shadowSamples is 1).
  s.addLight(PointLight(Color(230, 220, 200), Point(-2, 7, 4))
                 .setRadius(1)
                 .setShadowSamples(params.shadowSamples));
  CameraSpec c = view(Point(0, 2.2, 7), Point(0, 0.8, -2), 7.2, 8, 400, 300);
  // In focus: the glossy sphere's centre (when aperture > 0).
  c.aperture = params.aperture;
  const Double3 to = (Point(0, 0.8, -2) - c.location).xyz();
  c.focalDistance = (Point(-1.3, 1, 0) - c.location).xyz().dot(to) / std::sqrt(to.lengthSquared());
  return {s, c};
}

}  // namespace demo
}  // namespace rt
