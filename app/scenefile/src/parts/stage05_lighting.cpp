// The scene format's stage-5 part: lights, materials (named or inline), and each geometry's
// emission and material. Its scene is a LitScene: geometries that look the same share one row of
// the appearance table (lighting/AppearanceInterner.h).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "../Format.h"
#include "../Writers.h"
#include "Lighting.h"
#include "lighting/AppearanceInterner.h"
#include "primitives/Overloaded.h"
#include "scenefile/LitDocument.h"

namespace rt {

namespace scenefile {

namespace {

// ---------------------------------------------------------------------------------------------
// Reading

/// What a geometry says about its looks (kept in GeometryFields::look).
struct Look {
  Color emission;
  Material material;
  std::optional<std::string> materialName;
};

Look& lookOf(GeometryFields& f) {
  if (!f.look.has_value()) f.look = Look{};
  return std::any_cast<Look&>(f.look);
}

const KeyTable<Material>& materialKeys() {
  static const KeyTable<Material> keys = sceneFormat().table<Material>("material");
  return keys;
}

Material readMaterial(const Node& n) {
  Material m;
  readObject(n, materialKeys(), m, "a material object");
  try {
    m.validate();
  } catch (const std::invalid_argument& e) {
    n.fail(e.what());
  }
  return m;
}

std::vector<std::string_view> materialNames(const NamedMaterials& named) {
  std::vector<std::string_view> names;
  for (const auto& [name, material] : named.materials) names.push_back(name);
  return names;
}

void readGeometryMaterial(const Node& n, GeometryFields& f) {
  Look& look = lookOf(f);
  if (n.json().is_object()) {
    look.material = readMaterial(n);
    look.materialName.reset();
    return;
  }
  const NamedMaterials& named = namedMaterials(n.context().doc);
  const std::vector<std::string_view> names = materialNames(named);
  const std::string known = names.empty() ? "none is defined" : joinNames(names);
  if (!n.json().is_string())
    n.expected("a material object or the name of a material in \"materials\" (" + known + ")");
  const std::string name = n.json().get<std::string>();
  const auto it = named.materials.find(name);
  if (it == named.materials.end()) {
    std::string detail =
        "expected the name of a material in \"materials\" (" + known + "), got " + n.describe();
    n.fail(detail + didYouMean(name, names));
  }
  look.material = it->second;
  look.materialName = name;
}

/// The reading context's interner of the appearance table (see lighting/AppearanceInterner.h).
struct Rows {
  std::optional<AppearanceInterner> interner;
};

/// The row of the appearance table for the geometry's emission and material (checked already):
/// a row shared with every geometry that looks the same and names the same material (or none).
std::uint32_t appearanceRow(Context& ctx, const Look& look) {
  LitScene& scene = litScene(ctx.doc);
  std::optional<AppearanceInterner>& interner = ctx.state<Rows>().interner;
  if (!interner) interner.emplace(scene);
  if (&interner->scene() != &scene)
    throw std::logic_error("appearanceRow: the document's scene changed while it was read");
  const std::size_t before = scene.appearances.size();
  const std::uint32_t row =
      interner->row({look.emission, look.material}, look.materialName ? *look.materialName : "");
  if (scene.appearances.size() != before) {
    NamedMaterials& named = namedMaterials(ctx.doc);
    named.rowNames.resize(scene.appearances.size());
    named.rowNames.back() = look.materialName;
  }
  return row;
}

}  // namespace

std::uint32_t appearanceRowOf(const Node& node, GeometryFields& fields) {
  return appearanceRow(node.context(), lookOf(fields));
}

std::uint32_t appearanceRowWith(const Node& material, const GeometryFields& fields) {
  GeometryFields other;
  other.look = fields.look;
  readGeometryMaterial(material, other);
  return appearanceRow(material.context(), lookOf(other));
}

namespace {

void addLight(const Node& n, LightSource light) {
  try {
    litScene(n.context().doc).addLight(std::move(light));
  } catch (const std::invalid_argument& e) {
    n.fail(e.what());
  }
}

const std::vector<TypeRule<LightFields>>& lightTypes() {
  static const KeyTable<LightFields> directional =
      sceneFormat().table<LightFields>("light directional");
  static const KeyTable<LightFields> point = sceneFormat().table<LightFields>("light point");
  static const KeyTable<LightFields> spot = sceneFormat().table<LightFields>("light spot");
  static const std::vector<TypeRule<LightFields>> types = {
      {"directional", &directional,
       [](const Node& n, LightFields& f) {
         addLight(n, DirectionalLight(*f.intensity, *f.direction));
       }},
      {"point", &point,
       [](const Node& n, LightFields& f) {
         addLight(n, PointLight(*f.intensity, *f.position)
                         .setKc(f.kC)
                         .setKl(f.kL)
                         .setKq(f.kQ)
                         .setRadius(f.radius)
                         .setShadowSamples(f.shadowSamples));
       }},
      {"spot", &spot,
       [](const Node& n, LightFields& f) {
         addLight(n, SpotLight(*f.intensity, *f.position, *f.direction)
                         .setKc(f.kC)
                         .setKl(f.kL)
                         .setKq(f.kQ)
                         .setNarrowBeam(f.narrowBeam)
                         .setRadius(f.radius)
                         .setShadowSamples(f.shadowSamples));
       }},
  };
  return types;
}

void attachLights(SceneFormat& format) {
  using F = LightFields;
  for (const char* type : {"light directional", "light point", "light spot"})
    format.attach<F>(type, "intensity", [](const Node& n, F& f) { f.intensity = readColor(n); });
  for (const char* type : {"light directional", "light spot"})
    format.attach<F>(type, "direction",
                     [](const Node& n, F& f) { f.direction = readDirection(n); });
  for (const char* type : {"light point", "light spot"}) {
    format.attach<F>(type, "position", [](const Node& n, F& f) { f.position = readPoint(n); });
    format.attach<F>(type, "kC", [](const Node& n, F& f) { f.kC = readConstantAttenuation(n); });
    format.attach<F>(type, "kL", [](const Node& n, F& f) { f.kL = readNonNegative(n); });
    format.attach<F>(type, "kQ", [](const Node& n, F& f) { f.kQ = readNonNegative(n); });
  }
  format.attach<F>("light spot", "narrowBeam",
                   [](const Node& n, F& f) { f.narrowBeam = readNonNegative(n); });
}

void attachMaterials(SceneFormat& format) {
  using M = Material;
  format.attach<M>("material", "kD", [](const Node& n, M& m) { m.kD = readCoefficient(n); });
  format.attach<M>("material", "kS", [](const Node& n, M& m) { m.kS = readCoefficient(n); });
  format.attach<M>("material", "shininess",
                   [](const Node& n, M& m) { m.shininess = readInteger(n, 0); });
  format.attach<M>("material", "kT", [](const Node& n, M& m) { m.kT = readCoefficient(n); });
  format.attach<M>("material", "kR", [](const Node& n, M& m) { m.kR = readCoefficient(n); });
  format.attach<M>("material", "ior", [](const Node& n, M& m) { m.ior = readPositive(n); });
}

void attachDocument(SceneFormat& format) {
  using D = SceneDocument;
  format.attach<D>("document", "lights", [](const Node& n, D&) {
    readArray(n, "an array of lights", [](const Node& e) { readTyped(e, lightTypes(), "light"); });
  });
  // Before "geometries" (the catalogue's order): a geometry may name a material.
  format.attach<D>("document", "materials", [](const Node& n, D& d) {
    if (!n.json().is_object()) n.expected("an object of named materials");
    NamedMaterials& named = namedMaterials(d);
    n.forEachMember([&](std::string_view name, const Node& m) {
      if (name.empty()) m.failAtKey("a material's name must not be empty");
      named.materials.emplace(std::string(name), readMaterial(m));
    });
  });
  using G = GeometryFields;
  format.attach<G>("geometry", "emission",
                   [](const Node& n, G& f) { lookOf(f).emission = readColor(n); });
  format.attach<G>("geometry", "material", readGeometryMaterial);

  // A lit scene gives every shape a row of its appearance table.
  format.addGeometry = [](const Node& n, GeometryFields& f, Geometry shape) {
    SceneDocument& doc = n.context().doc;
    const std::uint32_t row = appearanceRow(n.context(), lookOf(f));
    const std::uint32_t index = litScene(doc).add(std::move(shape), row);
    if (!f.name.empty()) doc.geometryNames.emplace(index, std::move(f.name));
  };
}

// ---------------------------------------------------------------------------------------------
// Writing

bool same(const BeamSettings& a, const BeamSettings& b) {
  return scenefile::same(a.distance, b.distance) && scenefile::same(a.radius, b.radius) &&
         a.grid == b.grid;
}

/// Bitwise equality of every field (mini 1's beams included: they are the material's data).
bool same(const Material& a, const Material& b) {
  return scenefile::same(a.kD, b.kD) && scenefile::same(a.kS, b.kS) &&
         scenefile::same(a.kT, b.kT) && scenefile::same(a.kR, b.kR) && a.shininess == b.shininess &&
         scenefile::same(a.ior, b.ior) && same(a.reflectedBeam, b.reflectedBeam) &&
         same(a.refractedBeam, b.refractedBeam);
}

Json materialJson(const Material& m) {
  const Material d;
  Json j = Json::object();
  if (!scenefile::same(m.kD, d.kD)) j["kD"] = coefficient(m.kD);
  if (!scenefile::same(m.kS, d.kS)) j["kS"] = coefficient(m.kS);
  if (m.shininess != d.shininess) j["shininess"] = m.shininess;
  if (!scenefile::same(m.kT, d.kT)) j["kT"] = coefficient(m.kT);
  if (!scenefile::same(m.kR, d.kR)) j["kR"] = coefficient(m.kR);
  if (!scenefile::same(m.ior, d.ior)) j["ior"] = jsonNumber(m.ior);
  // A beam is mini 1's key; a build without mini 1 has no material with one.
  for (const auto& [key, beam] :
       {std::pair{"reflectedBeam", &m.reflectedBeam}, std::pair{"refractedBeam", &m.refractedBeam}})
    if (!same(*beam, BeamSettings{}))
      j[key] = {{"distance", jsonNumber(beam->distance)},
                {"radius", jsonNumber(beam->radius)},
                {"grid", beam->grid}};
  return j;
}

void attenuation(Json& j, const PointLight& l) {
  j["position"] = jsonTriple(l.position.xyz());
  j["kC"] = jsonNumber(l.kC);
  j["kL"] = jsonNumber(l.kL);
  j["kQ"] = jsonNumber(l.kQ);
  // mini 1's keys, written only when the light has a size.
  if (l.radius != 0) j["radius"] = jsonNumber(l.radius);
  if (l.shadowSamples != 1) j["shadowSamples"] = l.shadowSamples;
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
                          orderKeys(j, {"light point"});
                          return j;
                        },
                        [](const SpotLight& l) {
                          Json j = {{"type", "spot"}};
                          j["intensity"] = color(l.intensity);
                          attenuation(j, l);
                          j["direction"] = direction(l.direction);
                          j["narrowBeam"] = jsonNumber(l.narrowBeam);
                          orderKeys(j, {"light spot"});
                          return j;
                        },
                    },
                    light);
}

void writeDocument(const SceneDocument& doc, Json& j) {
  const LitScene& scene = litScene(doc);
  j["lights"] = Json::array();
  for (const LightSource& light : scene.lights) j["lights"].push_back(lightJson(light));
  const NamedMaterials& named = namedMaterials(doc);
  if (!named.materials.empty()) {
    Json& materials = j["materials"] = Json::object();
    for (const auto& [name, material] : named.materials) materials[name] = materialJson(material);
  }
}

void writeGeometry(const SceneDocument& doc, std::uint32_t i, Json& g) {
  writeAppearance(doc, litScene(doc).appearanceIndex[i], g, "geometry " + std::to_string(i));
}

}  // namespace

void writeAppearance(const SceneDocument& doc, std::uint32_t row, Json& g,
                     const std::string& what) {
  const Appearance& look = litScene(doc).appearances.at(row);
  if (!scenefile::same(look.emission.rgb(), Color::BLACK.rgb()))
    g["emission"] = color(look.emission);
  if (const std::string* materialName = materialNameOfRow(doc, row)) {
    const NamedMaterials& named = namedMaterials(doc);
    const auto it = named.materials.find(*materialName);
    if (it == named.materials.end())
      throw std::logic_error("toJson: " + what + " names material '" + *materialName +
                             "', which is not among the document's materials");
    if (!same(it->second, look.material))
      throw std::logic_error("toJson: " + what + " names material '" + *materialName +
                             "' but carries a different material");
    g["material"] = *materialName;
  } else if (!same(look.material, Material{})) {
    g["material"] = materialJson(look.material);
  }
}

void registerFormat_stage05_lighting(SceneFormat& format) {
  attachLights(format);
  attachMaterials(format);
  attachDocument(format);
  format.addTracer("phong");
  format.liftScene = [](const Scene& scene) {
    if (const auto* lit = dynamic_cast<const LitScene*>(&scene))
      return std::shared_ptr<Scene>(std::make_shared<LitScene>(*lit));
    return std::shared_ptr<Scene>(std::make_shared<LitScene>(scene));
  };
  // Every shape has a row of the appearance table, every row is valid.
  format.checkDocument.push_back([](const SceneDocument& doc) { litScene(doc).validate(); });
  format.writeDocument.push_back(writeDocument);
  format.writeGeometry.push_back(writeGeometry);
}

}  // namespace scenefile
}  // namespace rt
