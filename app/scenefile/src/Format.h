#pragma once
/// @file Format.h
/// The scene format as its parts assemble it: one part per stage present in the build (the files
/// in parts/, registered by the generated FormatParts.cpp), each attaching the readers and
/// writers of the keys its stage gives a meaning to, on top of one catalogue of every key of
/// every stage (Catalogue.cpp). A cut of the course therefore reads exactly the keys of its
/// stages, and names the stage a missing key needs.

#include <any>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "KeyTable.h"
#include "Node.h"
#include "geometries/Geometry.h"
#include "scenefile/SceneDocument.h"

namespace rt::scenefile {

/// One key of the format: the object it belongs to ("camera", "light spot", "geometry sphere",
/// "geometry" for the keys every geometry has), its name, the stage that gives it a meaning, how
/// it may be given, and its default (JSON text) or a phrase ("none").
struct CatalogueKey {
  std::string_view object;
  std::string_view key;
  std::string_view stage;
  Presence presence;
  std::string_view defaultText;
};

/// Every key of every stage, object by object, each object's keys in the documented order.
std::span<const CatalogueKey> keyCatalogue();

/// Every tracer of the course and the stage that adds it, in the course's order.
struct CatalogueTracer {
  std::string_view name;
  std::string_view stage;
};
std::span<const CatalogueTracer> tracerCatalogue();

// ---- The fields of the objects the core part builds, before they are built ----

struct CameraFields {
  std::optional<Point> location, target;
  std::optional<Vector> to, up;
  double vpDistance = 0;
  std::array<double, 2> vpSize{};
  std::array<int, 2> resolution{};
  double aperture = 0, focalDistance = 0;
  int lensSamples = 1;  ///< mini 1: rays through the lens per sample (kept in RenderSettings)
};

struct GeometryFields {
  std::optional<Point> center, point;
  std::optional<Vector> normal;
  std::optional<std::vector<Point>> points;
  std::vector<Point> vertices;
  std::optional<Ray> axis;
  double radius = 0, height = 0;
  std::string name;
  /// What later stages read on a geometry (stage 5: its emission and material).
  std::any look;
  /// What a geometry type of a later stage reads (mini 2: a mesh's keys).
  std::any typeFields;
};

/// Makes a geometry of one type from its fields, once its keys are read (node: the whole object,
/// for messages).
using GeometryBuilder = std::function<void(const Node& node, GeometryFields& fields)>;

/// A geometry type: its name and its builder. Its keys are the catalogue's "geometry TYPE" and
/// those every geometry has ("geometry").
struct GeometryType {
  std::string_view type;
  GeometryBuilder build;
};

/// Which element of the file's "geometries" made each shape, by shape index. An element that
/// makes no shape (a mesh, whose triangles are not shapes) moves the shapes after it, so that
/// shape i need not be element i; a message about a shape is put at its element. Kept in the
/// reading context (Context::state).
struct ShapeElements {
  std::vector<std::uint32_t> elementOf;
};

using JsonWriter = std::function<void(const SceneDocument& doc, Json& object)>;

/// A writer of geometries that are not shapes (mini 2: the meshes), which appends them to the
/// document's "geometries" array. folder is that of the file being written (empty: the current
/// directory), so that a model file's path is written relative to it.
using MoreGeometriesWriter = std::function<void(
    const SceneDocument& doc, const std::filesystem::path& folder, Json& geometries)>;

class SceneFormat {
 public:
  /// Attaches the reader of (object, key); the key must be in the catalogue.
  template <typename Target>
  void attach(std::string_view object, std::string_view key, typename Key<Target>::Reader read) {
    readers_[{std::string(object), std::string(key)}] = std::move(read);
  }

  /// The table of object: the catalogue's keys of object that have a reader, in order; the
  /// others (their stage is not in the build) as absent keys.
  template <typename Target>
  KeyTable<Target> table(std::string_view object) const {
    KeyTable<Target> t;
    for (const CatalogueKey& k : keyCatalogue()) {
      if (k.object != object) continue;
      const auto it = readers_.find({std::string(object), std::string(k.key)});
      if (it == readers_.end()) {
        t.absent.push_back({k.key, k.stage});
      } else {
        t.keys.emplace_back(k.key, k.presence, k.defaultText,
                            std::any_cast<typename Key<Target>::Reader>(it->second));
      }
    }
    return t;
  }

  /// Adds a geometry type (stage 4: the course's six shapes; mini 2: the mesh), in the course's
  /// order: the order in which messages list them.
  void addGeometryType(std::string_view type, GeometryBuilder build) {
    geometryTypes_.push_back({type, std::move(build)});
  }
  const std::vector<GeometryType>& geometryTypes() const { return geometryTypes_; }

  /// Declares that this build has the tracer called name.
  void addTracer(std::string_view name) { tracers_.push_back(name); }
  /// The tracers this build has, in the course's order.
  std::vector<std::string_view> tracers() const;

  /// The scene as the highest stage's model (set by each part that has one: a stage-4 Scene, a
  /// LitScene from stage 5 on). A document starts with liftScene(Scene{}).
  std::function<std::shared_ptr<Scene>(const Scene&)> liftScene;
  /// Adds a geometry read from a file to the document's scene (set by each part that changes
  /// what a shape carries: stage 4 adds the shape; stage 5 its appearance too).
  std::function<void(const Node& node, GeometryFields& fields, Geometry shape)> addGeometry;

  /// Checks of a document just read, called with the file's root value once every key is read;
  /// each may add warnings to the document (root.context().doc.warnings; stage 7: the winding of
  /// the faces of glass shapes).
  std::vector<std::function<void(const Node& root)>> checkRead;
  /// Checks run before anything is written (stage 5: the scene holds together); each throws
  /// std::logic_error or std::invalid_argument for a document that cannot be written.
  std::vector<std::function<void(const SceneDocument&)>> checkDocument;
  /// Writers, called in stage order: each adds its keys to the object it is given (the keys
  /// are put in the catalogue's order afterwards).
  std::vector<JsonWriter> writeDocument;
  std::vector<std::function<void(const SceneDocument&, std::uint32_t, Json&)>> writeGeometry;
  /// Called after writeDocument, in stage order: the geometries after the shapes.
  std::vector<MoreGeometriesWriter> writeMoreGeometries;

 private:
  std::map<std::pair<std::string, std::string>, std::any> readers_;
  std::vector<std::string_view> tracers_;
  std::vector<GeometryType> geometryTypes_;
};

/// The types of a typed object (object "geometry": the catalogue's objects "geometry TYPE") that
/// the catalogue has and present lacks, each with its stage (that of its first key): what a
/// course cut names when a file uses one ("the geometry type 'mesh' needs mini2_bvh").
std::vector<AbsentKey> absentTypes(std::string_view object,
                                   std::span<const std::string_view> present);

/// The format of this build, every present stage's part registered (on the first call).
const SceneFormat& sceneFormat();

/// Puts the members of object j in the catalogue's order for the given object names (the keys
/// of the first name first); "type" first when present.
void orderKeys(Json& j, std::initializer_list<std::string_view> objects);

/// Reads a JSON array element by element.
template <typename F>
void readArray(const Node& n, std::string_view what, F readElement) {
  if (!n.json().is_array()) n.expected(what);
  n.forEachElement(readElement);
}

}  // namespace rt::scenefile
