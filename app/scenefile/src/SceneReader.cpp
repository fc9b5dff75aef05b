// The scene format, as tables of keys (see KeyTable.h for the mechanism and
// docs/scene-format.md for the format). To add a key: add its field to the model (or to the
// Fields struct below), add one row to its table, document it in docs/scene-format.md.
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "KeyTable.h"
#include "Node.h"
#include "Readers.h"
#include "SourceMap.h"
#include "camera/Camera.h"
#include "camera/Image.h"
#include "common/NearestName.h"
#include "geometries/Geometry.h"
#include "reflections/WhittedTracer.h"
#include "scenefile/SceneFile.h"

namespace rt {

namespace scenefile {

namespace {

constexpr Presence REQUIRED = Presence::Required;
constexpr Presence DEFAULTED = Presence::Defaulted;
constexpr Presence OPTIONAL = Presence::Optional;

constexpr std::string_view TRACERS[] = {"ambient", "phong", "shadow", "whitted"};

// ---------------------------------------------------------------------------------------------
// camera

struct CameraFields {
  std::optional<Point> location, target;
  std::optional<Vector> to, up;
  double vpDistance = 0;
  std::array<double, 2> vpSize{};
  std::array<int, 2> resolution{};
};

const KeyTable<CameraFields>& cameraKeys() {
  static const KeyTable<CameraFields> keys = {
      {"location", REQUIRED, "", [](const Node& n, CameraFields& f) { f.location = readPoint(n); }},
      {"target", OPTIONAL, "none", [](const Node& n, CameraFields& f) { f.target = readPoint(n); }},
      {"to", OPTIONAL, "none", [](const Node& n, CameraFields& f) { f.to = readDirection(n); }},
      {"up", OPTIONAL, "[0,1,0]", [](const Node& n, CameraFields& f) { f.up = readDirection(n); }},
      {"vpDistance", REQUIRED, "",
       [](const Node& n, CameraFields& f) { f.vpDistance = readPositive(n); }},
      {"vpSize", REQUIRED, "",
       [](const Node& n, CameraFields& f) { f.vpSize = readPositivePair(n); }},
      // Checked here, before anything is allocated: an image side is at most Image::MAX_SIDE.
      {"resolution", REQUIRED, "",
       [](const Node& n, CameraFields& f) {
         f.resolution = readIntegerPair(n, 1, Image::MAX_SIDE);
       }},
  };
  return keys;
}

CameraSpec buildCamera(const Node& n, const CameraFields& f) {
  if (f.target && f.to) n.member("to").failAtKey("give either 'target' or 'to', not both");
  if (!f.target && !f.to) n.fail("missing required key 'target' (or 'to' with 'up')");
  if (f.to && !f.up) n.fail("missing required key 'up' (required with 'to')");
  CameraSpec spec;
  spec.location = *f.location;
  spec.target = f.target;
  spec.to = f.to;
  spec.up = f.up.value_or(Vector::AXIS_Y);
  spec.vpDistance = f.vpDistance;
  spec.vpWidth = f.vpSize[0];
  spec.vpHeight = f.vpSize[1];
  spec.nX = f.resolution[0];
  spec.nY = f.resolution[1];
  // The camera's own rules (vTo orthogonal to up, target not the location, up not along the
  // view, ...), checked by building it once; a 1x1 image keeps that cheap.
  try {
    (void)spec.builder().setResolution(1, 1).build();
  } catch (const std::exception& e) {
    n.fail(e.what());
  }
  return spec;
}

// ---------------------------------------------------------------------------------------------
// ambient, materials

struct AmbientFields {
  Color color;
  Double3 kA;
};

const KeyTable<AmbientFields>& ambientKeys() {
  static const KeyTable<AmbientFields> keys = {
      {"color", DEFAULTED, "[0,0,0]",
       [](const Node& n, AmbientFields& f) { f.color = readColor(n); }},
      {"kA", DEFAULTED, "1", [](const Node& n, AmbientFields& f) { f.kA = readCoefficient(n); }},
  };
  return keys;
}

const KeyTable<Material>& materialKeys() {
  static const KeyTable<Material> keys = {
      {"kD", DEFAULTED, "0", [](const Node& n, Material& m) { m.kD = readCoefficient(n); }},
      {"kS", DEFAULTED, "0", [](const Node& n, Material& m) { m.kS = readCoefficient(n); }},
      {"shininess", DEFAULTED, "0",
       [](const Node& n, Material& m) { m.shininess = readInteger(n, 0); }},
      {"kT", DEFAULTED, "0", [](const Node& n, Material& m) { m.kT = readCoefficient(n); }},
      {"kR", DEFAULTED, "0", [](const Node& n, Material& m) { m.kR = readCoefficient(n); }},
      {"ior", DEFAULTED, "1", [](const Node& n, Material& m) { m.ior = readPositive(n); }},
  };
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

// ---------------------------------------------------------------------------------------------
// lights

struct LightFields {
  std::optional<Color> intensity;
  std::optional<Point> position;
  std::optional<Vector> direction;
  double kC = 1, kL = 0, kQ = 0, narrowBeam = 1;
};

using LightKey = Key<LightFields>;

void addLight(const Node& n, LightSource light) {
  try {
    n.context().doc.scene.addLight(std::move(light));
  } catch (const std::invalid_argument& e) {
    n.fail(e.what());
  }
}

const std::vector<TypeRule<LightFields>>& lightTypes() {
  // The keys shared by several types, each defined once.
  static const LightKey INTENSITY{
      "intensity", REQUIRED, "", [](const Node& n, LightFields& f) { f.intensity = readColor(n); }};
  static const LightKey LIGHT_DIRECTION{
      "direction", REQUIRED, "",
      [](const Node& n, LightFields& f) { f.direction = readDirection(n); }};
  static const LightKey POSITION{"position", REQUIRED, "",
                                 [](const Node& n, LightFields& f) { f.position = readPoint(n); }};
  static const LightKey KC{"kC", DEFAULTED, "1",
                           [](const Node& n, LightFields& f) { f.kC = readPositive(n); }};
  static const LightKey KL{"kL", DEFAULTED, "0",
                           [](const Node& n, LightFields& f) { f.kL = readNonNegative(n); }};
  static const LightKey KQ{"kQ", DEFAULTED, "0",
                           [](const Node& n, LightFields& f) { f.kQ = readNonNegative(n); }};
  static const LightKey NARROW_BEAM{
      "narrowBeam", DEFAULTED, "1",
      [](const Node& n, LightFields& f) { f.narrowBeam = readNonNegative(n); }};
  static const KeyTable<LightFields> directional = {INTENSITY, LIGHT_DIRECTION};
  static const KeyTable<LightFields> point = {INTENSITY, POSITION, KC, KL, KQ};
  // clang-format off
  static const KeyTable<LightFields> spot = {INTENSITY, POSITION, KC, KL, KQ, LIGHT_DIRECTION,
                                             NARROW_BEAM};
  // clang-format on
  static const std::vector<TypeRule<LightFields>> types = {
      {"directional", &directional,
       [](const Node& n, LightFields& f) {
         addLight(n, DirectionalLight(*f.intensity, *f.direction));
       }},
      {"point", &point,
       [](const Node& n, LightFields& f) {
         addLight(n, PointLight(*f.intensity, *f.position).setKc(f.kC).setKl(f.kL).setKq(f.kQ));
       }},
      {"spot", &spot,
       [](const Node& n, LightFields& f) {
         addLight(n, SpotLight(*f.intensity, *f.position, *f.direction)
                         .setKc(f.kC)
                         .setKl(f.kL)
                         .setKq(f.kQ)
                         .setNarrowBeam(f.narrowBeam));
       }},
  };
  return types;
}

// ---------------------------------------------------------------------------------------------
// geometries

struct AxisFields {
  std::optional<Point> origin;
  std::optional<Vector> direction;
};

const KeyTable<AxisFields>& axisKeys() {
  static const KeyTable<AxisFields> keys = {
      {"origin", REQUIRED, "", [](const Node& n, AxisFields& f) { f.origin = readPoint(n); }},
      {"direction", REQUIRED, "",
       [](const Node& n, AxisFields& f) { f.direction = readDirection(n); }},
  };
  return keys;
}

struct GeometryFields {
  std::optional<Point> center, point;
  std::optional<Vector> normal;
  std::optional<std::vector<Point>> points;
  std::vector<Point> vertices;
  std::optional<Ray> axis;
  double radius = 0, height = 0;
  Color emission;
  Material material;
  std::optional<std::string> materialName;
  std::string name;
};

using GeometryKey = Key<GeometryFields>;

std::vector<std::string_view> materialNames(const SceneDocument& doc) {
  std::vector<std::string_view> names;
  for (const auto& [name, material] : doc.materials) names.push_back(name);
  return names;
}

void readGeometryMaterial(const Node& n, GeometryFields& f) {
  if (n.json().is_object()) {
    f.material = readMaterial(n);
    f.materialName.reset();
    return;
  }
  const SceneDocument& doc = n.context().doc;
  const std::vector<std::string_view> names = materialNames(doc);
  const std::string known = names.empty() ? "none is defined" : joinNames(names);
  if (!n.json().is_string())
    n.expected("a material object or the name of a material in \"materials\" (" + known + ")");
  const std::string name = n.json().get<std::string>();
  const auto it = doc.materials.find(name);
  if (it == doc.materials.end()) {
    n.fail("expected the name of a material in \"materials\" (" + known + "), got " + n.describe() +
           didYouMean(name, names));
  }
  f.material = it->second;
  f.materialName = name;
}

/// The bytes of a value, as a key: equal keys mean identical bits.
template <typename T>
void appendBits(std::string& key, const T& value) {
  key.append(reinterpret_cast<const char*>(&value), sizeof value);
}

/// The row of the appearance table for the geometry's emission and material (checked already):
/// an existing row when one is identical, else a new one.
std::uint32_t appearanceRow(Context& ctx, const GeometryFields& f) {
  std::string key;
  appendBits(key, f.emission.rgb());
  if (f.materialName) {
    key += 'N';
    key += *f.materialName;
  } else {
    const Material& m = f.material;
    key += 'M';
    for (const Double3* k : {&m.kD, &m.kS, &m.kT, &m.kR}) appendBits(key, *k);
    appendBits(key, m.shininess);
    appendBits(key, m.ior);
  }
  const auto [it, added] = ctx.appearanceRows.try_emplace(std::move(key), 0);
  if (added) {
    SceneDocument& doc = ctx.doc;
    it->second = doc.scene.addAppearance(f.emission, f.material);
    doc.appearanceMaterialNames.resize(doc.scene.appearances.size());
    doc.appearanceMaterialNames.back() = f.materialName;
  }
  return it->second;
}

/// Adds the shape built by make() to the scene; a constructor's refusal is reported at the
/// member `at` of the geometry (its "vertices", say), or at the geometry itself.
template <typename Make>
void addGeometry(const Node& n, GeometryFields& f, std::string_view at, Make make) {
  const Node& place = at.empty() || !n.find(at) ? n : n.member(at);
  std::optional<Geometry> shape;
  try {
    shape.emplace(make());
  } catch (const std::invalid_argument& e) {
    place.fail(e.what());
  }
  Context& ctx = n.context();
  SceneDocument& doc = ctx.doc;
  const std::uint32_t index = doc.scene.add(std::move(*shape), appearanceRow(ctx, f));
  if (!f.name.empty()) doc.geometryNames.emplace(index, std::move(f.name));
}

void buildPlane(const Node& n, GeometryFields& f) {
  if (f.points && (f.point || f.normal))
    n.member("points").failAtKey("give either 'point' and 'normal' or 'points', not both");
  if (f.points) {
    const std::vector<Point>& p = *f.points;
    addGeometry(n, f, "points", [&] { return Plane(p[0], p[1], p[2]); });
    return;
  }
  if (!f.point) n.fail("missing required key 'point' (or give 'points')");
  if (!f.normal) n.fail("missing required key 'normal' (or give 'points')");
  addGeometry(n, f, "normal", [&] { return Plane(*f.point, *f.normal); });
}

const std::vector<TypeRule<GeometryFields>>& geometryTypes() {
  // The keys shared by several types, each defined once.
  static const GeometryKey CENTER{
      "center", REQUIRED, "", [](const Node& n, GeometryFields& f) { f.center = readPoint(n); }};
  static const GeometryKey RADIUS{
      "radius", REQUIRED, "", [](const Node& n, GeometryFields& f) { f.radius = readPositive(n); }};
  static const GeometryKey HEIGHT{
      "height", REQUIRED, "", [](const Node& n, GeometryFields& f) { f.height = readPositive(n); }};
  static const GeometryKey AXIS{"axis", REQUIRED, "", [](const Node& n, GeometryFields& f) {
                                  AxisFields a;
                                  readObject(n, axisKeys(), a,
                                             "an axis object {origin, direction}");
                                  f.axis = Ray(*a.origin, *a.direction);
                                }};
  static const GeometryKey EMISSION{
      "emission", DEFAULTED, "[0,0,0]",
      [](const Node& n, GeometryFields& f) { f.emission = readColor(n); }};
  static const GeometryKey MATERIAL{"material", OPTIONAL, "none", readGeometryMaterial};
  static const GeometryKey NAME{"name", DEFAULTED, "\"\"",
                                [](const Node& n, GeometryFields& f) { f.name = readString(n); }};
  // A type's own keys, then the keys every geometry has.
  const auto withCommonKeys = [](KeyTable<GeometryFields> keys) {
    keys.insert(keys.end(), {EMISSION, MATERIAL, NAME});
    return keys;
  };
  static const KeyTable<GeometryFields> sphere = withCommonKeys({CENTER, RADIUS});
  static const KeyTable<GeometryFields> plane = withCommonKeys({
      {"point", OPTIONAL, "none", [](const Node& n, GeometryFields& f) { f.point = readPoint(n); }},
      {"normal", OPTIONAL, "none",
       [](const Node& n, GeometryFields& f) { f.normal = readDirection(n); }},
      {"points", OPTIONAL, "none",
       [](const Node& n, GeometryFields& f) { f.points = readPoints(n, 3, 3); }},
  });
  static const KeyTable<GeometryFields> triangle = withCommonKeys({
      {"vertices", REQUIRED, "",
       [](const Node& n, GeometryFields& f) { f.vertices = readPoints(n, 3, 3); }},
  });
  static const KeyTable<GeometryFields> polygon = withCommonKeys({
      {"vertices", REQUIRED, "",
       [](const Node& n, GeometryFields& f) { f.vertices = readPoints(n, 3, SIZE_MAX); }},
  });
  static const KeyTable<GeometryFields> tube = withCommonKeys({AXIS, RADIUS});
  static const KeyTable<GeometryFields> cylinder = withCommonKeys({AXIS, RADIUS, HEIGHT});
  static const std::vector<TypeRule<GeometryFields>> types = {
      {"sphere", &sphere,
       [](const Node& n, GeometryFields& f) {
         addGeometry(n, f, "radius", [&] { return Sphere(*f.center, f.radius); });
       }},
      {"plane", &plane, buildPlane},
      {"triangle", &triangle,
       [](const Node& n, GeometryFields& f) {
         const std::vector<Point>& v = f.vertices;
         addGeometry(n, f, "vertices", [&] { return Triangle(v[0], v[1], v[2]); });
       }},
      {"polygon", &polygon,
       [](const Node& n, GeometryFields& f) {
         addGeometry(n, f, "vertices", [&] { return Polygon(f.vertices); });
       }},
      {"tube", &tube,
       [](const Node& n, GeometryFields& f) {
         addGeometry(n, f, "", [&] { return Tube(f.radius, *f.axis); });
       }},
      {"cylinder", &cylinder,
       [](const Node& n, GeometryFields& f) {
         addGeometry(n, f, "", [&] { return Cylinder(f.radius, *f.axis, f.height); });
       }},
  };
  return types;
}

// ---------------------------------------------------------------------------------------------
// render settings and the document

const KeyTable<RenderSettings>& renderKeys() {
  static const KeyTable<RenderSettings> keys = {
      {"tracer", DEFAULTED, "\"whitted\"",
       [](const Node& n, RenderSettings& r) { r.tracer = readChoice(n, "a tracer", TRACERS); }},
      {"maxLevel", DEFAULTED, "10",
       [](const Node& n, RenderSettings& r) {
         r.maxLevel = readInteger(n, 1, WhittedSettings::MAX_LEVEL_LIMIT);
       }},
      {"minK", DEFAULTED, "0.001",
       [](const Node& n, RenderSettings& r) { r.minK = readNumberIn(n, 0, 1); }},
  };
  return keys;
}

template <typename F>
void readArray(const Node& n, std::string_view what, F readElement) {
  if (!n.json().is_array()) n.expected(what);
  n.forEachElement(readElement);
}

const KeyTable<SceneDocument>& documentKeys() {
  static const KeyTable<SceneDocument> keys = {
      {"name", DEFAULTED, "\"\"",
       [](const Node& n, SceneDocument& d) { d.scene.name = readString(n); }},
      {"camera", REQUIRED, "",
       [](const Node& n, SceneDocument& d) {
         CameraFields f;
         readObject(n, cameraKeys(), f, "a camera object");
         d.camera = buildCamera(n, f);
       }},
      {"background", DEFAULTED, "[0,0,0]",
       [](const Node& n, SceneDocument& d) { d.scene.background = readColor(n); }},
      {"ambient", DEFAULTED, "{}",
       [](const Node& n, SceneDocument& d) {
         AmbientFields f;
         readObject(n, ambientKeys(), f, "an ambient light object {color, kA}");
         d.scene.ambientLight = AmbientLight(f.color, f.kA);
       }},
      {"lights", DEFAULTED, "[]",
       [](const Node& n, SceneDocument&) {
         readArray(n, "an array of lights",
                   [](const Node& e) { readTyped(e, lightTypes(), "light"); });
       }},
      // Before "geometries": a geometry may name a material.
      {"materials", DEFAULTED, "{}",
       [](const Node& n, SceneDocument& d) {
         if (!n.json().is_object()) n.expected("an object of named materials");
         n.forEachMember([&](std::string_view name, const Node& m) {
           if (name.empty()) m.failAtKey("a material's name must not be empty");
           d.materials.emplace(std::string(name), readMaterial(m));
         });
       }},
      {"geometries", DEFAULTED, "[]",
       [](const Node& n, SceneDocument&) {
         readArray(n, "an array of geometries",
                   [](const Node& e) { readTyped(e, geometryTypes(), "geometry"); });
       }},
      {"render", DEFAULTED, "{}",
       [](const Node& n, SceneDocument& d) {
         readObject(n, renderKeys(), d.render, "a render object");
       }},
  };
  return keys;
}

template <typename Target>
void describeTable(std::vector<SceneKeyInfo>& out, const std::string& object,
                   const KeyTable<Target>& table) {
  for (const Key<Target>& key : table)
    out.push_back({object, std::string(key.name), key.presence == Presence::Required,
                   std::string(key.defaultText)});
}

}  // namespace

}  // namespace scenefile

// ---------------------------------------------------------------------------------------------
// The public API

SceneDocument parseScene(std::string_view text, const std::string& sourceName) {
  using namespace scenefile;
  SourceMap map;
  if (const std::optional<SyntaxProblem> problem = scanSource(text, map)) {
    const LineColumn lc = lineColumnOf(text, problem->offset);
    throw SceneError(sourceName, lc.line, lc.column, problem->path, problem->detail);
  }
  // The text is valid JSON (the first pass checked it with the same parser).
  const Json root = Json::parse(text.begin(), text.end());
  Context ctx{text, sourceName, map, {}, {}};
  readObject(Node(ctx, root), documentKeys(), ctx.doc, "a scene object");
  return std::move(ctx.doc);
}

SceneDocument loadScene(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw SceneError("cannot read " + path + ": it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError("cannot read " + path + ": " + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > MAX_SCENE_FILE_BYTES)
      throw SceneError("cannot read " + path + ": larger than " +
                       std::to_string(MAX_SCENE_FILE_BYTES >> 20) + " MiB");
  }
  if (in.bad()) throw SceneError("cannot read " + path + ": " + std::strerror(errno));
  return parseScene(text, path);
}

std::span<const std::string_view> knownTracers() { return scenefile::TRACERS; }

std::vector<SceneKeyInfo> sceneFormatKeys() {
  using namespace scenefile;
  std::vector<SceneKeyInfo> out;
  describeTable(out, "document", documentKeys());
  describeTable(out, "camera", cameraKeys());
  describeTable(out, "ambient", ambientKeys());
  describeTable(out, "material", materialKeys());
  for (const auto& rule : lightTypes()) {
    out.push_back({"light " + std::string(rule.type), "type", true, ""});
    describeTable(out, "light " + std::string(rule.type), *rule.keys);
  }
  for (const auto& rule : geometryTypes()) {
    out.push_back({"geometry " + std::string(rule.type), "type", true, ""});
    describeTable(out, "geometry " + std::string(rule.type), *rule.keys);
  }
  describeTable(out, "axis", axisKeys());
  describeTable(out, "render", renderKeys());
  return out;
}

}  // namespace rt
