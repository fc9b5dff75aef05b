#include "glossy/Galaxy.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geometries/Plane.h"
#include "geometries/Polygon.h"
#include "geometries/Sphere.h"
#include "primitives/Checks.h"
#include "primitives/Random.h"

namespace rt {

namespace {

/// The six faces of the box [lo, hi], each with its vertices counter-clockwise seen from
/// outside (so every face's normal points out: what refraction needs, see docs/scene-format.md).
void addBox(LitScene& s, const Double3& lo, const Double3& hi, std::uint32_t look) {
  const double x0 = lo.x, y0 = lo.y, z0 = lo.z, x1 = hi.x, y1 = hi.y, z1 = hi.z;
  s.add(Polygon{Point(x0, y0, z0), Point(x0, y0, z1), Point(x0, y1, z1), Point(x0, y1, z0)},
        look);  // −x
  s.add(Polygon{Point(x1, y0, z0), Point(x1, y1, z0), Point(x1, y1, z1), Point(x1, y0, z1)},
        look);  // +x
  s.add(Polygon{Point(x0, y0, z0), Point(x1, y0, z0), Point(x1, y0, z1), Point(x0, y0, z1)},
        look);  // −y
  s.add(Polygon{Point(x0, y1, z0), Point(x0, y1, z1), Point(x1, y1, z1), Point(x1, y1, z0)},
        look);  // +y
  s.add(Polygon{Point(x0, y0, z0), Point(x0, y1, z0), Point(x1, y1, z0), Point(x1, y0, z0)},
        look);  // −z
  s.add(Polygon{Point(x0, y0, z1), Point(x1, y0, z1), Point(x1, y1, z1), Point(x0, y1, z1)},
        look);  // +z
}

/// The disc's point (x, y, z) (y off the disc's plane) tilted by angle about the X axis and moved
/// to the galaxy's centre.
Point placeInDisc(double x, double y, double z) {
  const double angle = 20 * std::numbers::pi / 180;
  const double c = std::cos(angle), s = std::sin(angle);
  return Point(x + 4, y * c - z * s + 8, y * s + z * c + 4);
}

}  // namespace

void GalaxyParams::validate() const {
  requireBetween(arms, 1, MAX_ARMS, "galaxy", "arms");
  requireBetween(perArm, 1, MAX_PER_ARM, "galaxy", "perArm");
  requireBetween(stars, 0, MAX_STARS, "galaxy", "stars");
  // perArm sets the stars when stars is 0: the product is bounded as stars is.
  if (stars == 0 && static_cast<long>(arms) * perArm > MAX_STARS)
    throw std::invalid_argument("galaxy: arms x perArm must be at most " +
                                std::to_string(MAX_STARS) + " stars, got " + std::to_string(arms) +
                                " x " + std::to_string(perArm) + " = " +
                                std::to_string(static_cast<long>(arms) * perArm));
}

int GalaxyParams::positionsPerArm() const {
  if (stars <= 0) return perArm;
  return static_cast<int>(std::max(1L, std::lround(static_cast<double>(stars) / arms)));
}

GalaxySetup galaxy(const GalaxyParams& p) {
  p.validate();
  GalaxySetup g;
  LitScene& s = g.scene;
  s.name = "Glassed Galaxy";
  s.background = Color::BLACK;

  const int m = p.positionsPerArm();
  const long positions = static_cast<long>(p.arms) * m;
  s.geometries.reserve(static_cast<std::uint32_t>(positions + 110));
  s.appearanceIndex.reserve(static_cast<std::size_t>(positions + 110));

  // Floor, pedestal, glass box, frame.
  s.add(Plane(Point(0, 0, 0), Vector(0, 1, 0)), Color(30, 40, 70), Material::course(1, 0, 0));
  const std::uint32_t brown = s.addAppearance(Color(80, 40, 5), Material::course(0.5, 0.35, 10));
  addBox(s, {-7, 2, -7}, {19, 4, 15}, brown);
  addBox(s, {-7.5, 0, -7.5}, {19.5, 2, 15.5}, brown);
  Material glassMaterial = Material::course(0.35, 0.4, 10, 0.85, 0.2);
  if (p.diffusion) glassMaterial.reflectedBeam = glassMaterial.refractedBeam = {12, 0.2, 10};
  const std::uint32_t glass = s.addAppearance(Color(20, 25, 25), glassMaterial);
  addBox(s, {-6.5, 4, -6.5}, {18.5, 15, 14.5}, glass);
  const std::uint32_t metal =
      s.addAppearance(Color(45, 30, 30), Material::course(0.5, 0.35, 10, 0, 0.05));
  constexpr double w = 0.15;  // half the bars' width
  for (const double x : {-6.5, 18.5})
    for (const double z : {-6.5, 14.5})
      addBox(s, {x - w, 4, z - w}, {x + w, 15 + w, z + w}, metal);  // corner posts
  for (const double z : {-6.5, 14.5})
    addBox(s, {-6.5 + w, 15 - w, z - w}, {18.5 - w, 15 + w, z + w}, metal);  // top edges along x
  for (const double x : {-6.5, 18.5})
    addBox(s, {x - w, 15 - w, -6.5 + w}, {x + w, 15 + w, 14.5 - w}, metal);  // top edges along z

  // The galaxy.
  const Material starMaterial = Material::course(0.2, 0.33, 10);
  const std::uint32_t lightBlue = s.addAppearance(Color(80, 255, 230), starMaterial);
  const std::uint32_t nearWhite = s.addAppearance(Color(200, 250, 255), starMaterial);
  const double starRadius = 0.05 * std::sqrt(50.0 / m);
  // i' = step·i runs over the reference report's 0..49
  const double step = m > 1 ? 49.0 / (m - 1) : 0;
  for (int arm = 0; arm < p.arms; ++arm) {
    const double offset = 2 * std::numbers::pi * arm / p.arms;
    const bool sunArm = arm % 7 == 4;
    for (int i = 0; i < m; ++i) {
      RandomStream r(p.seed, static_cast<std::uint32_t>(arm), static_cast<std::uint32_t>(i), 0);
      const double seedIndex = step * i;
      const double theta = 0.15 * seedIndex;
      const double radius = 1.7 * std::exp(0.25 * theta);
      const double spread = 0.2 * std::floor(seedIndex / 8);
      const double x = radius * std::cos(theta + offset) + (r.next() - 0.5) * spread;
      const double z = radius * std::sin(theta + offset) + (r.next() - 0.5) * spread;
      const double y = r.next() * 0.2 - 0.1;
      const Point centre = placeInDisc(x, y, z);
      if (!sunArm) {
        s.add(Sphere(centre, starRadius), i % 2 == 0 ? lightBlue : nearWhite);
        continue;
      }
      const double kind = r.next(), brightness = 0.9 + 0.3 * r.next(), size = r.next();
      if (kind < 0.4) {
        s.add(Sphere(centre, 0.20 + 0.03 * size), Color(255, 150, 90) * brightness,
              starMaterial);  // an orange sun
      } else if (kind < 0.9) {
        s.add(Sphere(centre, 0.16 + 0.03 * size), Color(255, 200, 50) * brightness,
              starMaterial);  // a yellow sun
      }                       // else: no sun at this position
    }
  }
  const Color coreColor(255, 220, 110);
  s.add(Sphere(Point(4, 8, 4), 1), coreColor, starMaterial);
  s.add(Sphere(Point(4, 8, 4), 1.3), coreColor * 0.3, Material::course(0.1, 0.9, 10, 0.9));

  // The lights.
  const auto spot = [&](const Color& c, const Point& at, const Vector& along) {
    s.addLight(SpotLight(c, at, along).setKl(0.002).setKq(0.002));
  };
  spot(Color(0, 120, 120), Point(20, 30, 4), Vector(-1.8, -3, 0));
  spot(Color(140, 100, 0), Point(0, 30, 30), Vector(0, -3, -1.8));
  spot(Color(120, 0, 120), Point(0, 30, -20), Vector(0, -3, 1.8));

  // The cameras.
  const auto view = [](const Point& from, const Point& at, double vpWidth, double vpDistance) {
    CameraSpec c;
    c.location = from;
    c.target = at;
    c.vpWidth = vpWidth;
    c.vpHeight = vpWidth * 216 / 384;
    c.vpDistance = vpDistance;
    c.nX = 1280;
    c.nY = 720;
    return c;
  };
  g.camera = view(Point(100, 27, 22), Point(4, 8, 4), 384, 750);
  g.views = {{"main", g.camera},
             {"above", view(Point(6, 70, 40), Point(6, 8, 4), 384, 700)},
             {"inside", view(Point(30, 14, 16), Point(4, 8, 4), 384, 400)},
             {"side", view(Point(-40, 14, 90), Point(6, 8, 4), 384, 800)}};
  return g;
}

}  // namespace rt
