// Writing a SceneDocument as a scene file that reads back to the same document, bit for bit.
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <variant>

#include "common/JsonText.h"
#include "geometries/Geometry.h"
#include "primitives/Overloaded.h"
#include "scenefile/SceneFile.h"

namespace rt {

namespace {

using Json = nlohmann::ordered_json;

/// Bitwise equality: 0 and -0 differ, as they do when read back.
bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(const Double3& a, const Double3& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}
bool same(const Material& a, const Material& b) {
  return same(a.kD, b.kD) && same(a.kS, b.kS) && same(a.kT, b.kT) && same(a.kR, b.kR) &&
         a.shininess == b.shininess && same(a.ior, b.ior);
}

// Numbers go through jsonNumber (integral values as integers, 2 rather than 2.0); dumpScene
// writes the text with formatJson, every double in its shortest round-trip form.
Json color(const Color& c) { return jsonTriple(c.rgb()); }

/// One number when the three channels are the same, else [r,g,b].
Json coefficient(const Double3& k) {
  return same(k.x, k.y) && same(k.y, k.z) ? jsonNumber(k.x) : jsonTriple(k);
}

/// True when the shapes' normalisation of c gives exactly u.
bool normalisesTo(const Double3& c, const Vector& u) {
  if (!c.isFinite() || c.isZero() || !std::isfinite(c.lengthSquared())) return false;
  return same(Vector(c).normalized().xyz(), u.xyz());
}

/// A vector that the loader's normalisation turns into exactly u (a stored plane normal, axis
/// or light direction). u itself often is not one: normalising a unit vector again moves about
/// a third of them by an ulp. Tried in order: small integer ratios (a built-in scene's (1,1,1)
/// comes back as [1,1,1]), u itself, then multiples of u.
Double3 directionPreimage(const Vector& u) {
  const Double3& x = u.xyz();
  double smallest = INFINITY, largest = 0;
  for (double c : {x.x, x.y, x.z})
    if (c != 0) {
      smallest = std::min(smallest, std::abs(c));
      largest = std::max(largest, std::abs(c));
    }
  if (largest / smallest <= 1000) {
    for (int k = 1; k <= 24; ++k) {
      const Double3 scaled = x * (k / smallest);
      const Double3 rounded(std::round(scaled.x), std::round(scaled.y), std::round(scaled.z));
      const bool integral = std::abs(scaled.x - rounded.x) < 1e-9 * k &&
                            std::abs(scaled.y - rounded.y) < 1e-9 * k &&
                            std::abs(scaled.z - rounded.z) < 1e-9 * k;
      if (integral && normalisesTo(rounded, u)) return rounded;
    }
  }
  if (normalisesTo(x, u)) return x;
  for (int s = 3; s <= 2000; ++s)
    if (normalisesTo(x * s, u)) return x * s;
  return x;  // not found (rare): the copy may differ from the original by an ulp
}

Json direction(const Vector& u) { return jsonTriple(directionPreimage(u)); }

Json materialJson(const Material& m) {
  const Material d;
  Json j = Json::object();
  if (!same(m.kD, d.kD)) j["kD"] = coefficient(m.kD);
  if (!same(m.kS, d.kS)) j["kS"] = coefficient(m.kS);
  if (m.shininess != d.shininess) j["shininess"] = m.shininess;
  if (!same(m.kT, d.kT)) j["kT"] = coefficient(m.kT);
  if (!same(m.kR, d.kR)) j["kR"] = coefficient(m.kR);
  if (!same(m.ior, d.ior)) j["ior"] = jsonNumber(m.ior);
  return j;
}

Json cameraJson(const CameraSpec& c) {
  Json j = Json::object();
  j["location"] = jsonTriple(c.location.xyz());
  if (c.target) {
    j["target"] = jsonTriple(c.target->xyz());
  } else if (c.to) {
    j["to"] = jsonTriple(c.to->xyz());
  } else {
    throw std::logic_error("toJson: the camera has neither a target nor a direction (to)");
  }
  j["up"] = jsonTriple(c.up.xyz());
  j["vpDistance"] = jsonNumber(c.vpDistance);
  j["vpSize"] = Json::array({jsonNumber(c.vpWidth), jsonNumber(c.vpHeight)});
  j["resolution"] = Json::array({c.nX, c.nY});
  return j;
}

void attenuation(Json& j, const PointLight& l) {
  j["position"] = jsonTriple(l.position.xyz());
  j["kC"] = jsonNumber(l.kC);
  j["kL"] = jsonNumber(l.kL);
  j["kQ"] = jsonNumber(l.kQ);
}

Json lightJson(const LightSource& light) {
  return std::visit(Overloaded{
                        [](const DirectionalLight& l) {
                          Json j = {{"type", "directional"}};
                          j["intensity"] = color(l.intensity);
                          j["direction"] = direction(l.direction);
                          return j;
                        },
                        [](const PointLight& l) {
                          Json j = {{"type", "point"}};
                          j["intensity"] = color(l.intensity);
                          attenuation(j, l);
                          return j;
                        },
                        [](const SpotLight& l) {
                          Json j = {{"type", "spot"}};
                          j["intensity"] = color(l.intensity);
                          attenuation(j, l);
                          j["direction"] = direction(l.direction);
                          j["narrowBeam"] = jsonNumber(l.narrowBeam);
                          return j;
                        },
                    },
                    light);
}

Json axisJson(const Ray& axis) {
  return {{"origin", jsonTriple(axis.head().xyz())}, {"direction", direction(axis.direction())}};
}

Json pointsJson(std::span<const Point> points) {
  Json j = Json::array();
  for (const Point& p : points) j.push_back(jsonTriple(p.xyz()));
  return j;
}

Json shapeJson(const Geometry& g) {
  return std::visit(Overloaded{
                        [](const Sphere& s) {
                          return Json{{"type", "sphere"},
                                      {"center", jsonTriple(s.center().xyz())},
                                      {"radius", jsonNumber(s.radius())}};
                        },
                        [](const Plane& p) {
                          return Json{{"type", "plane"},
                                      {"point", jsonTriple(p.point().xyz())},
                                      {"normal", direction(p.normal())}};
                        },
                        [](const Triangle& t) {
                          return Json{{"type", "triangle"}, {"vertices", pointsJson(t.vertices())}};
                        },
                        [](const Polygon& p) {
                          return Json{{"type", "polygon"}, {"vertices", pointsJson(p.vertices())}};
                        },
                        [](const Tube& t) {
                          return Json{{"type", "tube"},
                                      {"axis", axisJson(t.axis())},
                                      {"radius", jsonNumber(t.radius())}};
                        },
                        [](const Cylinder& c) {
                          return Json{{"type", "cylinder"},
                                      {"axis", axisJson(c.axis())},
                                      {"radius", jsonNumber(c.radius())},
                                      {"height", jsonNumber(c.height())}};
                        },
                    },
                    g);
}

}  // namespace

Json toJson(const SceneDocument& doc) {
  const LitScene& scene = doc.scene;
  const std::uint32_t n = scene.geometries.size();
  scene.validate();  // every shape has a row of the appearance table, every row is valid
  if (!doc.geometryNames.empty() && doc.geometryNames.rbegin()->first >= n)
    throw std::logic_error("toJson: a name for geometry " +
                           std::to_string(doc.geometryNames.rbegin()->first) + " but there are " +
                           std::to_string(n) + " geometries");

  Json j = Json::object();
  if (!scene.name.empty()) j["name"] = scene.name;
  j["camera"] = cameraJson(doc.camera);
  j["background"] = color(scene.background);
  j["ambient"] = {{"color", color(scene.ambientLight.ia())},
                  {"kA", coefficient(scene.ambientLight.kA())}};
  j["lights"] = Json::array();
  for (const LightSource& light : scene.lights) j["lights"].push_back(lightJson(light));
  if (!doc.materials.empty()) {
    Json& materials = j["materials"] = Json::object();
    for (const auto& [name, material] : doc.materials) materials[name] = materialJson(material);
  }
  Json& geometries = j["geometries"] = Json::array();
  for (std::uint32_t i = 0; i < n; ++i) {
    Json g = shapeJson(scene.geometries[i]);
    const Appearance& look = scene.appearanceOf(i);
    if (!same(look.emission.rgb(), Color::BLACK.rgb())) g["emission"] = color(look.emission);
    if (const std::string* materialName = doc.materialNameOf(i)) {
      const auto it = doc.materials.find(*materialName);
      if (it == doc.materials.end())
        throw std::logic_error("toJson: geometry " + std::to_string(i) + " names material '" +
                               *materialName + "', which is not among the document's materials");
      if (!same(it->second, look.material))
        throw std::logic_error("toJson: geometry " + std::to_string(i) + " names material '" +
                               *materialName + "' but carries a different material");
      g["material"] = *materialName;
    } else if (!same(look.material, Material{})) {
      g["material"] = materialJson(look.material);
    }
    if (const std::string* name = doc.geometryName(i)) g["name"] = *name;
    geometries.push_back(std::move(g));
  }
  j["render"] = {{"tracer", doc.render.tracer},
                 {"maxLevel", doc.render.maxLevel},
                 {"minK", jsonNumber(doc.render.minK)}};
  return j;
}

std::string dumpScene(const SceneDocument& doc) { return formatJson(toJson(doc)); }

}  // namespace rt
