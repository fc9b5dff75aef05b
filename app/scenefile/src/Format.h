#pragma once
/// @file Format.h
/// The scene format as its parts assemble it: one part per stage present in the build (the files
/// in parts/, registered by the generated FormatParts.cpp), each attaching the readers and
/// writers of the keys its stage gives a meaning to, on top of one catalogue of every key of
/// every stage (Catalogue.cpp). A cut of the course therefore reads exactly the keys of its
/// stages, and names the stage a missing key needs.

#include <cstdint>
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
};

using JsonWriter = std::function<void(const SceneDocument& doc, Json& object)>;

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

 private:
  std::map<std::pair<std::string, std::string>, std::any> readers_;
  std::vector<std::string_view> tracers_;
};

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
