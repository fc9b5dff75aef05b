#include "glossy/DemoScenes.h"

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "geometries/Cylinder.h"
#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "geometries/Sphere.h"

namespace rt {

// ---------------------------------------------------------------------------------------------
// The knobs

namespace {

constexpr std::array<DemoKnobInfo, 7> KNOBS{{
    {"samples", "N x N jittered samples per pixel", 1, JitteredSampler::MAX_GRID, true},
    {"lensSamples", "rays through the lens per sample", 1, JitteredSampler::MAX_LENS_SAMPLES, true},
    {"aperture", "the lens radius (0: the pinhole)", 0, 1000, false},
    {"adaptive", "adaptive super-sampling instead of the jittered grid", 0, 1, true},
    {"shadowSamples", "shadow rays per light with a radius", 1, PointLight::MAX_SHADOW_SAMPLES,
     true},
    {"glossyGrid", "N of every reflected beam (1: a sharp mirror)", 1, BeamSettings::MAX_GRID,
     true},
    {"frostedGrid", "N of every refracted beam (1: clear glass)", 1, BeamSettings::MAX_GRID, true},
}};

/// The lights with a size (point and spot lights of radius > 0).
template <typename Visit>
void forEachAreaLight(auto& lights, Visit&& visit) {
  for (auto& light : lights) {
    std::visit(
        [&](auto& l) {
          if constexpr (std::is_base_of_v<PointLight, std::remove_cvref_t<decltype(l)>>) {
            if (l.radius > 0) visit(l);
          }
        },
        light);
  }
}

/// The beams with a radius of one kind (reflected or refracted) in the appearance table.
template <typename Visit>
void forEachBeam(auto& appearances, bool reflected, Visit&& visit) {
  for (auto& a : appearances) {
    auto& beam = reflected ? a.material.reflectedBeam : a.material.refractedBeam;
    if (beam.radius > 0) visit(beam);
  }
}

}  // namespace

const DemoKnobInfo& knobInfo(DemoKnob knob) { return KNOBS.at(static_cast<std::size_t>(knob)); }

bool knobApplies(const DemoSetup& setup, DemoKnob knob) {
  bool found = false;
  switch (knob) {
    case DemoKnob::ShadowSamples:
      forEachAreaLight(setup.scene.lights, [&](const PointLight&) { found = true; });
      return found;
    case DemoKnob::GlossyGrid:
    case DemoKnob::FrostedGrid:
      forEachBeam(setup.scene.appearances, knob == DemoKnob::GlossyGrid,
                  [&](const BeamSettings&) { found = true; });
      return found;
    default:
      return true;
  }
}

double knobValue(const DemoSetup& setup, DemoKnob knob) {
  const SamplingSettings& s = setup.sampling;
  std::optional<int> first;
  switch (knob) {
    case DemoKnob::Samples:
      return s.samples;
    case DemoKnob::LensSamples:
      return s.lensSamples;
    case DemoKnob::Aperture:
      return setup.camera.aperture;
    case DemoKnob::Adaptive:
      return s.adaptive ? 1 : 0;
    case DemoKnob::ShadowSamples:
      forEachAreaLight(setup.scene.lights, [&](const PointLight& l) {
        if (!first) first = l.shadowSamples;
      });
      return first.value_or(1);
    case DemoKnob::GlossyGrid:
    case DemoKnob::FrostedGrid:
      forEachBeam(setup.scene.appearances, knob == DemoKnob::GlossyGrid,
                  [&](const BeamSettings& b) {
                    if (!first) first = b.grid;
                  });
      return first.value_or(1);
  }
  return 0;  // not reached: every knob is a case above
}

void setKnob(DemoSetup& setup, DemoKnob knob, double value) {
  const DemoKnobInfo& info = knobInfo(knob);
  if (!(value >= info.min && value <= info.max) || (info.integer && value != std::floor(value))) {
    throw std::invalid_argument(std::string(info.name) + ": expected " +
                                (info.integer ? "an integer" : "a number") + " from " +
                                formatNumber(info.min) + " to " + formatNumber(info.max) +
                                ", got " + formatNumber(value));
  }
  SamplingSettings& s = setup.sampling;
  const int n = static_cast<int>(value);
  switch (knob) {
    case DemoKnob::Samples:
      s.samples = n;
      break;
    case DemoKnob::LensSamples:
      s.lensSamples = n;
      break;
    case DemoKnob::Aperture:
      setup.camera.aperture = value;
      break;
    case DemoKnob::Adaptive:
      s.adaptive = n == 1;
      break;
    case DemoKnob::ShadowSamples:
      forEachAreaLight(setup.scene.lights, [&](PointLight& l) { l.shadowSamples = n; });
      break;
    case DemoKnob::GlossyGrid:
    case DemoKnob::FrostedGrid:
      forEachBeam(setup.scene.appearances, knob == DemoKnob::GlossyGrid,
                  [&](BeamSettings& b) { b.grid = n; });
      break;
  }
}

// ---------------------------------------------------------------------------------------------
// The table

DemoSetup DemoScene::build() const {
  SceneSetup<LitScene> s = course.make();
  return {std::move(s.scene), s.camera, sampling};
}

std::span<const DemoScene> demoScenes() {
  using K = DemoKnob;
  static const std::vector<DemoScene> table{
      {{"glossy-spheres",
        "Four mirror spheres whose reflected beams widen from left to right: sharp to glossy",
        &demo::glossySpheres},
       {},
       {K::GlossyGrid, K::Samples}},
      {{"frosted-glass",
        "Clear glass and two panes of diffused glass, of growing radius, in front of a pattern",
        &demo::frostedGlass},
       {},
       {K::FrostedGrid, K::Samples}},
      {{"soft-shadows",
        "Shapes under a light of radius 1.2: penumbrae widening away from what casts them",
        &demo::softShadows},
       {},
       {K::ShadowSamples, K::Samples}},
      {{"antialiasing",
        "A checkerboard to the horizon, 4 x 4 jittered samples per pixel (samples=1: aliased)",
        &demo::antialiasing},
       {.samples = 4},
       {K::Samples}},
      {{"depth-of-field", "Spheres at seven depths seen through a lens focused on the middle one",
        &demo::depthOfField},
       {.lensSamples = 24},
       {K::LensSamples, K::Aperture, K::Samples}},
      {{"adaptive",
        "Flat shapes with sharp edges, adaptively super-sampled: extra rays only on the edges",
        &demo::adaptiveEdges},
       {.adaptive = true, .adaptiveDepth = 3},
       {K::Adaptive, K::Samples}},
      {{"super-sampling",
        "Every technique of mini project 1 in one scene, each off until a --param turns it on",
        &demo::superSampling},
       {},
       {K::GlossyGrid, K::FrostedGrid, K::ShadowSamples, K::Samples, K::LensSamples, K::Aperture,
        K::Adaptive}},
  };
  return table;
}

void checkDemoTable(std::span<const DemoScene> table) {
  std::vector<CourseScene> course;
  course.reserve(table.size());
  for (const DemoScene& entry : table) course.push_back(entry.course);
  checkSceneTable(course);  // so every entry has a name from here on
  for (std::size_t i = 0; i < table.size(); ++i) {
    const DemoScene& entry = table[i];
    const auto refuse = [&](const std::string& what) {
      throw std::logic_error("checkDemoTable: entry " + std::to_string(i) + " ('" +
                             entry.course.name + "'): " + what);
    };
    try {
      (void)makePixelSampler(entry.sampling);
    } catch (const std::exception& e) {
      refuse(std::string("its sampling settings are refused: ") + e.what());
    }
    const DemoSetup setup = entry.build();
    for (std::size_t k = 0; k < entry.knobs.size(); ++k) {
      const std::string name = knobInfo(entry.knobs[k]).name;
      for (std::size_t j = 0; j < k; ++j)
        if (entry.knobs[j] == entry.knobs[k]) refuse("the knob " + name + " is listed twice");
      if (!knobApplies(setup, entry.knobs[k]))
        refuse("the knob " + name + " has nothing to act on in its scene");
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The scenes

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

SceneSetup<LitScene> glossySpheres() {
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
    m.reflectedBeam = {1, radii[i], 8};
    s.add(Sphere(Point(-3.3 + 2.2 * static_cast<double>(i), 1, 0), 1), Color(8, 8, 10), m);
  }
  s.addLight(PointLight(Color(210, 200, 190), Point(3, 9, 7)));
  return {s, view(Point(0, 2.4, 9), Point(0, 0.9, 0), 10.5, 9, 640, 320)};
}

SceneSetup<LitScene> frostedGlass() {
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
    glass.refractedBeam = {1, radii[i], 8};
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

SceneSetup<LitScene> softShadows() {
  LitScene s = darkRoom("soft shadows");
  s.add(Plane(Point(0, 0, 0), Vector(0, 1, 0)), Color(20, 20, 20), Material::course(0.8, 0.05, 10));
  const Material paint = Material::course(0.6, 0.4, 60);
  s.add(Sphere(Point(-2.3, 0.8, 0.2), 0.8), Color(40, 10, 5), paint);  // resting on the floor
  s.add(Sphere(Point(0.2, 2.1, -0.2), 0.6), Color(5, 25, 45), paint);  // floating
  s.add(Cylinder(0.22, Ray(Point(1.9, 0, -1.2), Vector(0, 1, 0)), 3.2), Color(10, 30, 10),
        paint);  // a post
  s.addLight(
      PointLight(Color(230, 220, 200), Point(-0.5, 6, 2)).setRadius(1.2).setShadowSamples(32));
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

SceneSetup<LitScene> depthOfField() {
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
  c.aperture = 0.2;
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

SceneSetup<LitScene> superSampling() {
  LitScene s = darkRoom("super-sampling");
  addFloorBoard(s, -6, -14, 12, 20);
  // A glossy sphere (its beam off until glossyGrid > 1), two coloured spheres further back.
  Material glossy = Material::course(0.1, 0.6, 100, 0, 0.8);
  glossy.reflectedBeam = {1, 0.08, 1};
  s.add(Sphere(Point(-1.3, 1, 0), 1), Color(8, 8, 10), glossy);
  s.add(Sphere(Point(1.2, 0.6, -4.5), 0.6), Color(150, 40, 30), Material::course(0.4, 0.5, 60));
  s.add(Sphere(Point(-0.4, 0.6, -9), 0.6), Color(30, 80, 150), Material::course(0.4, 0.5, 60));
  // A pane of glass in front of the right half of the red sphere (clear until frostedGrid > 1).
  Material glass = Material::course(0.05, 0.4, 60, 0.85, 0.05);
  glass.refractedBeam = {1, 0.08, 1};
  s.add(Polygon{Point(1, 0.1, -2.5), Point(3, 0.1, -2.5), Point(3, 2.3, -2.5), Point(1, 2.3, -2.5)},
        Color(4, 6, 8), glass);
  // A light of radius 1 (a point until shadowSamples > 1).
  s.addLight(PointLight(Color(230, 220, 200), Point(-2, 7, 4)).setRadius(1));
  CameraSpec c = view(Point(0, 2.2, 7), Point(0, 0.8, -2), 7.2, 8, 400, 300);
  // In focus: the glossy sphere's centre (when aperture > 0).
  const Double3 to = (Point(0, 0.8, -2) - c.location).xyz();
  c.focalDistance = (Point(-1.3, 1, 0) - c.location).xyz().dot(to) / std::sqrt(to.lengthSquared());
  return {s, c};
}

}  // namespace demo
}  // namespace rt
