#pragma once
/// @file SceneFile.h
/// Reading and writing scene files (JSON, format in docs/scene-format.md).
///
/// Reading is strict: every error is reported once, as a SceneError whose message names the
/// file, the line and column of the offending value (or its JSON path when no position is known)
/// and what was expected:
///
///     scenes/x.json:14:9: geometries[3].radius: expected a positive number, got -2
///
/// Writing produces a file that reads back to an identical document (every number written so
/// that it round-trips exactly, materials inline or by name as in the document, names kept).

#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenefile/ModelFile.h"
#include "scenefile/SceneDocument.h"

namespace rt {

/// The largest coordinate, radius or height a scene file may give (and `rt probe --ray` an
/// origin). The shapes' solvers and checks multiply differences of coordinates up to four at a
/// time (a sphere's |o - c|^2, a polygon's |e1 x e2|^2 against |e1|^2·|e2|^2): with every
/// coordinate within 10^75 those stay below about 10^302, finite. Beyond, a sphere at 10^155
/// overflowed into NaN and vanished from the image without a word, and a square polygon at 10^78
/// was refused as collinear; a scene scaled up to 10^75 renders as it does at its own size
/// (tests/cli/FarSceneTests.cpp).
inline constexpr double MAX_COORDINATE = 1e75;

/// A scene file that cannot be read or does not describe a valid scene.
struct SceneError : std::runtime_error {
  /// An error at a place in a file. line and column are 1-based; 0 when no position is known,
  /// and the message then reads "FILE: PATH: DETAIL". An empty path is the document itself.
  SceneError(std::string file, int line, int column, std::string path, std::string detail);
  /// An error that concerns the file as a whole ("cannot read FILE: reason").
  explicit SceneError(const std::string& message);

  std::string file;    ///< the source name given to parseScene, or the path given to loadScene
  int line = 0;        ///< 1-based line of the offending value; 0 when unknown
  int column = 0;      ///< 1-based column (in characters, not bytes); 0 when unknown
  std::string path;    ///< JSON path of the offending value ("geometries[3].radius")
  std::string detail;  ///< what was expected and what was found

  /// "FILE:LINE:COL: PATH: DETAIL", dropping the parts that are unknown or empty.
  static std::string format(const std::string& file, int line, int column, const std::string& path,
                            const std::string& detail);
};

/// Reads a scene from JSON text. sourceName is what the messages call the file; its folder is
/// where a model file's relative path starts (a mesh's "file"; none: the current directory).
/// models says where the model files are read (the disk, recorded, or replayed from memory).
/// @throws SceneError for malformed JSON or anything the format or a constructor rejects.
SceneDocument parseScene(std::string_view text, const std::string& sourceName,
                         const ModelFileSource& models = {});

/// The text of the scene file at path (at most MAX_SCENE_FILE_BYTES), as loadScene reads it.
/// @throws SceneError "cannot read PATH: reason".
std::string readSceneText(const std::string& path);

/// Reads the file at path (at most MAX_SCENE_FILE_BYTES) and parses it.
/// @throws SceneError "cannot read PATH: reason" when the file cannot be read, and as
///         parseScene for its contents.
SceneDocument loadScene(const std::string& path);

/// The largest scene file loadScene accepts: 64 MiB.
inline constexpr std::size_t MAX_SCENE_FILE_BYTES = std::size_t{64} << 20;

/// The document as JSON, in the format parseScene reads, keys in the documented order.
/// Directions (plane normals, axis and light directions) are stored normalised by the shapes;
/// each is written as a vector whose normalisation gives exactly the stored one (the shortest
/// such vector found among small integer ratios, the vector itself and its multiples), so that
/// reading the export rebuilds the same shapes bit for bit.
/// The meshes (mini 2) come after the shapes: a mesh read from a model file as its entry (the
/// file's path relative to folder, the folder of the file being written, or the current
/// directory when folder is empty; an absolute path as it was given), a mesh given inline or
/// made in code inline, every vertex and normal written so that it reads back to the same bits.
/// @throws std::logic_error for a document that cannot be written as a scene file: a camera
///         with neither target nor direction, name lists longer than the geometry list, or a
///         geometry whose material name is unknown or names a different material.
nlohmann::ordered_json toJson(const SceneDocument& doc, const std::filesystem::path& folder = {});

/// toJson(doc, folder) as text: two-space indentation, arrays of numbers on one line, final
/// newline.
std::string dumpScene(const SceneDocument& doc, const std::filesystem::path& folder = {});

/// The values of render.tracer this build accepts (its stages' tracers), in the course's order.
std::vector<std::string_view> knownTracers();

/// The stage that adds the course's tracer called name when this build does not have it (a
/// course cut before that stage); empty when the build has it, or when no stage adds one.
std::string_view missingTracerStage(std::string_view name);

/// The scene as this build's scene model: a LitScene from stage 5 on (every shape with the
/// default appearance when scene is a stage-4 Scene), else a copy of the Scene. What a
/// document's scene is.
std::shared_ptr<Scene> sceneModelOf(const Scene& scene);

/// One key of the format (for documentation and its test).
struct SceneKeyInfo {
  std::string object;       ///< "camera", "geometry sphere", "light spot", "material", ...
  std::string key;          ///< the key's name
  std::string stage;        ///< the stage that gives it a meaning: a build without it refuses it
  bool required = false;    ///< true when the key must be given
  std::string defaultText;  ///< the default as JSON, or a phrase ("none") for optional keys
};

/// Every key of every object type of the format (of every stage, present or not), in the
/// documented order.
std::vector<SceneKeyInfo> sceneFormatKeys();

}  // namespace rt
