// Writing a SceneDocument as a scene file that reads back to the same document, bit for bit.
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <variant>

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

/// A number as JSON: integral values as integers (2 rather than 2.0), everything else as a
/// double, which nlohmann writes in the shortest form that reads back to the same double.
Json number(double v) {
  constexpr double EXACT_INTEGERS = 9007199254740992.0;  // 2^53
  if (v == std::trunc(v) && std::abs(v) < EXACT_INTEGERS && !(v == 0 && std::signbit(v)))
    return Json(static_cast<std::int64_t>(v));
  return Json(v);
}

Json triple(const Double3& d) { return Json::array({number(d.x), number(d.y), number(d.z)}); }
Json color(const Color& c) { return triple(c.rgb()); }

/// One number when the three channels are the same, else [r,g,b].
Json coefficient(const Double3& k) {
  return same(k.x, k.y) && same(k.y, k.z) ? number(k.x) : triple(k);
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

Json direction(const Vector& u) { return triple(directionPreimage(u)); }

Json materialJson(const Material& m) {
  const Material d;
  Json j = Json::object();
  if (!same(m.kD, d.kD)) j["kD"] = coefficient(m.kD);
  if (!same(m.kS, d.kS)) j["kS"] = coefficient(m.kS);
  if (m.shininess != d.shininess) j["shininess"] = m.shininess;
  if (!same(m.kT, d.kT)) j["kT"] = coefficient(m.kT);
  if (!same(m.kR, d.kR)) j["kR"] = coefficient(m.kR);
  if (!same(m.ior, d.ior)) j["ior"] = number(m.ior);
  return j;
}

Json cameraJson(const CameraSpec& c) {
  Json j = Json::object();
  j["location"] = triple(c.location.xyz());
  if (c.target) {
    j["target"] = triple(c.target->xyz());
  } else if (c.to) {
    j["to"] = triple(c.to->xyz());
  } else {
    throw std::logic_error("toJson: the camera has neither a target nor a direction (to)");
  }
  j["up"] = triple(c.up.xyz());
  j["vpDistance"] = number(c.vpDistance);
  j["vpSize"] = Json::array({number(c.vpWidth), number(c.vpHeight)});
  j["resolution"] = Json::array({c.nX, c.nY});
  return j;
}

void attenuation(Json& j, const PointLight& l) {
  j["position"] = triple(l.position.xyz());
  j["kC"] = number(l.kC);
  j["kL"] = number(l.kL);
  j["kQ"] = number(l.kQ);
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
                          j["narrowBeam"] = number(l.narrowBeam);
                          return j;
                        },
                    },
                    light);
}

Json axisJson(const Ray& axis) {
  return {{"origin", triple(axis.head().xyz())}, {"direction", direction(axis.direction())}};
}

Json pointsJson(std::span<const Point> points) {
  Json j = Json::array();
  for (const Point& p : points) j.push_back(triple(p.xyz()));
  return j;
}

Json shapeJson(const Geometry& g) {
  return std::visit(Overloaded{
                        [](const Sphere& s) {
                          return Json{{"type", "sphere"},
                                      {"center", triple(s.center().xyz())},
                                      {"radius", number(s.radius())}};
                        },
                        [](const Plane& p) {
                          return Json{{"type", "plane"},
                                      {"point", triple(p.point().xyz())},
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
                                      {"radius", number(t.radius())}};
                        },
                        [](const Cylinder& c) {
                          return Json{{"type", "cylinder"},
                                      {"axis", axisJson(c.axis())},
                                      {"radius", number(c.radius())},
                                      {"height", number(c.height())}};
                        },
                    },
                    g);
}

/// j on one line: {"kA": 0.15, "color": [255, 255, 255]}.
std::string oneLine(const Json& j) {
  if (!j.is_structured()) return j.dump();
  std::string out(1, j.is_object() ? '{' : '[');
  std::size_t i = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++i) {
    if (i) out += ", ";
    if (j.is_object()) {
      out += Json(it.key()).dump();
      out += ": ";
    }
    out += oneLine(it.value());
  }
  out += j.is_object() ? '}' : ']';
  return out;
}

/// Writes j with two-space indentation, starting at column. A value whose one-line form fits
/// in LINE_WIDTH stays on one line (a point, a light, a short geometry), except a list of
/// objects.
void write(std::string& out, const Json& j, int indent, std::size_t column) {
  constexpr std::size_t LINE_WIDTH = 100;
  if (!j.is_structured() || j.empty()) {
    out += oneLine(j);
    return;
  }
  // A list of objects (lights, geometries) always gets one line per object.
  const bool listOfObjects = j.is_array() && j.front().is_object();
  if (std::string line = oneLine(j); !listOfObjects && column + line.size() <= LINE_WIDTH) {
    out += line;
    return;
  }
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  out += j.is_object() ? "{\n" : "[\n";
  std::size_t i = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++i) {
    if (i) out += ",\n";
    out += pad;
    if (j.is_object()) {
      out += Json(it.key()).dump();
      out += ": ";
    }
    write(out, it.value(), indent + 2, out.size() - out.rfind('\n') - 1);
  }
  out += '\n';
  out.append(static_cast<std::size_t>(indent), ' ');
  out += j.is_object() ? '}' : ']';
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
                 {"minK", number(doc.render.minK)}};
  return j;
}

std::string dumpScene(const SceneDocument& doc) {
  std::string out;
  write(out, toJson(doc), 0, 0);
  out += '\n';
  return out;
}

}  // namespace rt
