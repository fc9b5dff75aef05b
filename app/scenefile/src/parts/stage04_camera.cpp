// The scene format's stage-4 part: the camera and its views, the background, the ambient light,
// the geometries' shapes and names, and the render settings every build has (tracer, seed).
// The scene it makes is a stage-4 Scene; a later stage's part may make a richer one.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "../Format.h"
#include "../Writers.h"
#include "camera/Camera.h"
#include "camera/Image.h"
#include "common/NearestName.h"
#include "primitives/Overloaded.h"
#include "scenefile/SceneFile.h"

namespace rt::scenefile {

namespace {

// ---------------------------------------------------------------------------------------------
// Reading

struct AmbientFields {
  Color color;
  Double3 kA;
};

struct AxisFields {
  std::optional<Point> origin;
  std::optional<Vector> direction;
};

const KeyTable<CameraFields>& cameraKeys() {
  static const KeyTable<CameraFields> keys = sceneFormat().table<CameraFields>("camera");
  return keys;
}

/// The camera object's fields as a CameraSpec, checked by building the camera once (a 1 x 1
/// image keeps that cheap): vTo orthogonal to up, the target not the location, up not along the
/// view, the view and focal planes not lost in the location's rounding.
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
  spec.aperture = f.aperture;
  spec.focalDistance = f.focalDistance;
  try {
    (void)spec.builder().setResolution(1, 1).build();
  } catch (const std::exception& e) {
    n.fail(e.what());
  }
  return spec;
}

/// The main camera (its lens samples are the render's) or a view (lensSamples not allowed: it
/// is a setting of the whole render, given once with the main camera).
CameraSpec readCamera(const Node& n, int* lensSamples = nullptr) {
  CameraFields f;
  readObject(n, cameraKeys(), f, "a camera object");
  if (lensSamples) {
    *lensSamples = f.lensSamples;
  } else if (n.find("lensSamples")) {
    n.member("lensSamples").failAtKey("lensSamples is given once, with the main camera");
  }
  return buildCamera(n, f);
}

void attachCamera(SceneFormat& format) {
  using F = CameraFields;
  format.attach<F>("camera", "location", [](const Node& n, F& f) { f.location = readPoint(n); });
  format.attach<F>("camera", "target", [](const Node& n, F& f) { f.target = readPoint(n); });
  format.attach<F>("camera", "to", [](const Node& n, F& f) { f.to = readDirection(n); });
  format.attach<F>("camera", "up", [](const Node& n, F& f) { f.up = readDirection(n); });
  format.attach<F>("camera", "vpDistance",
                   [](const Node& n, F& f) { f.vpDistance = readPositive(n); });
  format.attach<F>("camera", "vpSize", [](const Node& n, F& f) { f.vpSize = readPositivePair(n); });
  // Checked here, before anything is allocated: an image side is at most Image::MAX_SIDE.
  format.attach<F>("camera", "resolution", [](const Node& n, F& f) {
    f.resolution = readIntegerPair(n, 1, Image::MAX_SIDE);
  });
  format.attach<F>("camera", "aperture",
                   [](const Node& n, F& f) { f.aperture = readNonNegative(n); });
  format.attach<F>("camera", "focalDistance",
                   [](const Node& n, F& f) { f.focalDistance = readNonNegative(n); });
}

/// Adds the shape built by make() to the scene through the build's geometry adder; a
/// constructor's refusal is reported at the member `at` of the geometry (its "vertices", say),
/// or at the geometry itself.
template <typename Make>
void addGeometry(const Node& n, GeometryFields& f, std::string_view at, Make make) {
  const Node& place = at.empty() || !n.find(at) ? n : n.member(at);
  std::optional<Geometry> shape;
  try {
    shape.emplace(make());
  } catch (const std::invalid_argument& e) {
    place.fail(e.what());
  }
  sceneFormat().addGeometry(n, f, std::move(*shape));
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

/// The table of one geometry type: its own keys, then the keys every geometry has.
KeyTable<GeometryFields> geometryTable(std::string_view type) {
  KeyTable<GeometryFields> t = sceneFormat().table<GeometryFields>(type);
  const KeyTable<GeometryFields> common = sceneFormat().table<GeometryFields>("geometry");
  t.keys.insert(t.keys.end(), common.keys.begin(), common.keys.end());
  t.absent.insert(t.absent.end(), common.absent.begin(), common.absent.end());
  return t;
}

/// The rules of the geometry types this build has (the parts register them: stage 4 the
/// course's six shapes, mini 2 the mesh), and the types of the stages it lacks.
struct GeometryRules {
  std::vector<KeyTable<GeometryFields>> tables;  ///< the rules point into it: never resized
  std::vector<TypeRule<GeometryFields>> rules;
  std::vector<AbsentKey> absent;
};

const GeometryRules& geometryRules() {
  static const GeometryRules rules = [] {
    const std::vector<GeometryType>& types = sceneFormat().geometryTypes();
    GeometryRules r;
    r.tables.reserve(types.size());
    std::vector<std::string_view> names;
    for (const GeometryType& t : types) {
      r.tables.push_back(geometryTable("geometry " + std::string(t.type)));
      r.rules.push_back({t.type, &r.tables.back(), t.build});
      names.push_back(t.type);
    }
    r.absent = absentTypes("geometry", names);
    return r;
  }();
  return rules;
}

void addCourseShapeTypes(SceneFormat& format) {
  using F = GeometryFields;
  format.addGeometryType("sphere", [](const Node& n, F& f) {
    addGeometry(n, f, "radius", [&] { return Sphere(*f.center, f.radius); });
  });
  format.addGeometryType("plane", buildPlane);
  format.addGeometryType("triangle", [](const Node& n, F& f) {
    const std::vector<Point>& v = f.vertices;
    addGeometry(n, f, "vertices", [&] { return Triangle(v[0], v[1], v[2]); });
  });
  format.addGeometryType("polygon", [](const Node& n, F& f) {
    addGeometry(n, f, "vertices", [&] { return Polygon(f.vertices); });
  });
  format.addGeometryType("tube", [](const Node& n, F& f) {
    addGeometry(n, f, "", [&] { return Tube(f.radius, *f.axis); });
  });
  format.addGeometryType("cylinder", [](const Node& n, F& f) {
    addGeometry(n, f, "", [&] { return Cylinder(f.radius, *f.axis, f.height); });
  });
}

void attachGeometries(SceneFormat& format) {
  using F = GeometryFields;
  const auto center = [](const Node& n, F& f) { f.center = readPoint(n); };
  const auto radius = [](const Node& n, F& f) { f.radius = readLength(n); };
  const auto axis = [](const Node& n, F& f) {
    static const KeyTable<AxisFields> keys = sceneFormat().table<AxisFields>("axis");
    AxisFields a;
    readObject(n, keys, a, "an axis object {origin, direction}");
    f.axis = Ray(*a.origin, *a.direction);
  };
  format.attach<AxisFields>("axis", "origin",
                            [](const Node& n, AxisFields& a) { a.origin = readPoint(n); });
  format.attach<AxisFields>("axis", "direction",
                            [](const Node& n, AxisFields& a) { a.direction = readDirection(n); });
  format.attach<F>("geometry sphere", "center", center);
  format.attach<F>("geometry sphere", "radius", radius);
  format.attach<F>("geometry plane", "point", [](const Node& n, F& f) { f.point = readPoint(n); });
  format.attach<F>("geometry plane", "normal",
                   [](const Node& n, F& f) { f.normal = readDirection(n); });
  format.attach<F>("geometry plane", "points",
                   [](const Node& n, F& f) { f.points = readPoints(n, 3, 3); });
  format.attach<F>("geometry triangle", "vertices",
                   [](const Node& n, F& f) { f.vertices = readPoints(n, 3, 3); });
  format.attach<F>("geometry polygon", "vertices",
                   [](const Node& n, F& f) { f.vertices = readPoints(n, 3, SIZE_MAX); });
  format.attach<F>("geometry tube", "axis", axis);
  format.attach<F>("geometry tube", "radius", radius);
  format.attach<F>("geometry cylinder", "axis", axis);
  format.attach<F>("geometry cylinder", "radius", radius);
  format.attach<F>("geometry cylinder", "height",
                   [](const Node& n, F& f) { f.height = readLength(n); });
  format.attach<F>("geometry", "name", [](const Node& n, F& f) { f.name = readString(n); });

  // A stage-4 scene keeps the shapes only (a later stage's part replaces this adder).
  format.addGeometry = [](const Node& n, GeometryFields& f, Geometry shape) {
    SceneDocument& doc = n.context().doc;
    const std::uint32_t index = doc.scene->geometries.add(std::move(shape));
    if (!f.name.empty()) doc.geometryNames.emplace(index, std::move(f.name));
  };
}

void attachDocument(SceneFormat& format) {
  using D = SceneDocument;
  format.attach<D>("document", "name", [](const Node& n, D& d) { d.scene->name = readString(n); });
  format.attach<D>("document", "camera",
                   [](const Node& n, D& d) { d.camera = readCamera(n, &d.render.lensSamples); });
  format.attach<D>("document", "views", [](const Node& n, D& d) {
    if (!n.json().is_object()) n.expected("an object of named cameras");
    n.forEachMember([&](std::string_view name, const Node& view) {
      if (name.empty()) view.failAtKey("a view's name must not be empty");
      d.views.push_back({std::string(name), readCamera(view)});
    });
  });
  format.attach<D>("document", "background",
                   [](const Node& n, D& d) { d.scene->background = readColor(n); });
  format.attach<AmbientFields>("ambient", "color",
                               [](const Node& n, AmbientFields& f) { f.color = readColor(n); });
  format.attach<AmbientFields>("ambient", "kA",
                               [](const Node& n, AmbientFields& f) { f.kA = readCoefficient(n); });
  format.attach<D>("document", "ambient", [](const Node& n, D& d) {
    static const KeyTable<AmbientFields> keys = sceneFormat().table<AmbientFields>("ambient");
    AmbientFields f;
    readObject(n, keys, f, "an ambient light object {color, kA}");
    d.scene->ambientLight = AmbientLight(f.color, f.kA);
  });
  format.attach<D>("document", "geometries", [](const Node& n, D& d) {
    std::vector<std::uint32_t>& elementOf = n.context().state<ShapeElements>().elementOf;
    std::uint32_t element = 0;
    readArray(n, "an array of geometries", [&](const Node& e) {
      const GeometryRules& g = geometryRules();
      readTyped(e, g.rules, "geometry", g.absent);
      elementOf.resize(d.scene->geometries.size(), element++);
    });
  });
  format.attach<D>("document", "render", [](const Node& n, D& d) {
    static const KeyTable<RenderSettings> keys = sceneFormat().table<RenderSettings>("render");
    readObject(n, keys, d.render, "a render object");
  });
}

void attachRender(SceneFormat& format) {
  using R = RenderSettings;
  format.attach<R>("render", "tracer", [](const Node& n, R& r) {
    if (n.json().is_string()) {
      const std::string name = n.json().get<std::string>();
      if (const std::string_view stage = missingTracerStage(name); !stage.empty())
        n.fail(needsStageMessage("tracer", name, stage));
    }
    r.tracer = readChoice(n, "a tracer", sceneFormat().tracers());
  });
  format.attach<R>("render", "seed", [](const Node& n, R& r) {
    r.seed = static_cast<std::uint64_t>(readInteger(n, 0));
  });
  // The course's grid lines (Camera::printGrid), drawn on the image once it is rendered.
  format.attach<R>("render", "gridLines",
                   [](const Node& n, R& r) { r.gridLines = readInteger(n, 0, Image::MAX_SIDE); });
  format.attach<R>("render", "gridColor", [](const Node& n, R& r) { r.gridColor = readColor(n); });
}

// ---------------------------------------------------------------------------------------------
// Writing

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
  if (c.aperture != 0) j["aperture"] = jsonNumber(c.aperture);
  if (c.focalDistance != 0) j["focalDistance"] = jsonNumber(c.focalDistance);
  return j;
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

void writeDocument(const SceneDocument& doc, Json& j) {
  const Scene& scene = *doc.scene;
  const std::uint32_t n = scene.geometries.size();
  if (!doc.geometryNames.empty() && doc.geometryNames.rbegin()->first >= n)
    throw std::logic_error("toJson: a name for geometry " +
                           std::to_string(doc.geometryNames.rbegin()->first) + " but there are " +
                           std::to_string(n) + " geometries");
  if (!scene.name.empty()) j["name"] = scene.name;
  j["camera"] = cameraJson(doc.camera);
  if (!doc.views.empty()) {
    Json& views = j["views"] = Json::object();
    for (const NamedView& v : doc.views) views[v.name] = cameraJson(v.camera);
  }
  j["background"] = color(scene.background);
  j["ambient"] = {{"color", color(scene.ambientLight.ia())},
                  {"kA", coefficient(scene.ambientLight.kA())}};
  Json& geometries = j["geometries"] = Json::array();
  for (std::uint32_t i = 0; i < n; ++i) {
    Json g = shapeJson(scene.geometries[i]);
    if (const std::string* name = doc.geometryName(i)) g["name"] = *name;
    for (const auto& write : sceneFormat().writeGeometry) write(doc, i, g);
    orderKeys(g, {std::string("geometry ") + shapeName(scene.geometries[i]), "geometry"});
    geometries.push_back(std::move(g));
  }
  Json& render = j["render"] = Json::object();
  if (!doc.render.tracer.empty()) render["tracer"] = doc.render.tracer;
  if (doc.render.seed != 0) render["seed"] = doc.render.seed;
  const RenderSettings defaults;
  if (doc.render.gridLines != defaults.gridLines) render["gridLines"] = doc.render.gridLines;
  if (doc.render.gridColor != defaults.gridColor) render["gridColor"] = color(doc.render.gridColor);
}

}  // namespace

void registerFormat_stage04_camera(SceneFormat& format) {
  attachDocument(format);
  attachCamera(format);
  attachGeometries(format);
  addCourseShapeTypes(format);
  attachRender(format);
  for (const char* tracer : {"rays", "normals", "hits", "ambient"}) format.addTracer(tracer);
  format.liftScene = [](const Scene& scene) { return std::make_shared<Scene>(scene); };
  format.writeDocument.push_back(writeDocument);
}

}  // namespace rt::scenefile
