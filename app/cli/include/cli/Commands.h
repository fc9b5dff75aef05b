#pragma once
/// @file Commands.h
/// The `rt` program as a library: runRt() is main() without the process (streams in, exit code
/// out), so the tests can call it directly, and the pieces the commands share are testable on
/// their own.
///
///   rt list                                   the built-in scenes, one per line
///   rt render SCENE [-o FILE.png] [--width W] [--height H] [--tracer T] [--quiet]
///   rt probe SCENE (--ray OX,OY,OZ DX,DY,DZ | --pixel X,Y) [--width W] [--height H] [--tracer T]
///   rt export NAME [-o FILE.json]
///   rt compare A.png B.png [--diff OUT.png] [--tolerance T]   (cli/Compare.h)
///   rt --help | rt COMMAND --help | rt --version
///
/// Exit codes: 0 ok, 1 runtime failure, 2 bad usage or input, 130 interrupted (Ctrl-C).

#include <atomic>
#include <exception>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>

#include "primitives/Color.h"
#include "primitives/Ray.h"
#include "scenefile/ModelFile.h"
#include "scenefile/SceneDocument.h"

namespace rt::cli {

inline constexpr int EXIT_OK = 0;
inline constexpr int EXIT_FAILURE_RUNTIME = 1;
inline constexpr int EXIT_BAD_INPUT = 2;
inline constexpr int EXIT_INTERRUPTED = 130;  ///< 128 + SIGINT, as shells report it

/// Where a command writes, and how it is stopped.
struct Io {
  std::ostream& out;
  std::ostream& err;
  /// Progress is a percentage redrawn in place on a terminal, a plain line per 10% otherwise.
  bool errIsTerminal = false;
  /// Raised (by a SIGINT handler) to stop a render; nullptr: cannot be stopped.
  const std::atomic<bool>* stop = nullptr;
};

/// What an error means for the user: the exit code (EXIT_BAD_INPUT for bad usage, a bad scene
/// or a value the engine refuses; EXIT_FAILURE_RUNTIME otherwise) and the message ("out of
/// memory" for std::bad_alloc), as rt prints them after "rt: ".
struct ErrorReport {
  int code = EXIT_FAILURE_RUNTIME;
  std::string message;
};
ErrorReport describeError(std::exception_ptr error);

/// Runs `rt` with args (without the program's name) and returns the exit code. Errors are one
/// line on io.err starting with "rt: ".
int runRt(std::span<const std::string> args, const Io& io);

/// "rt 0.4.0" (the CMake project's version).
std::string versionString();

// ---- Pieces shared by the commands (and tested on their own) ----

/// A scene file's text and where its model files come from, given instead of the disk: what a
/// rank of rt-mpi received from rank 0 (the models replayed), or what rank 0 read and records.
struct SceneFileInput {
  std::string text;        ///< the scene file's contents
  ModelFileSource models;  ///< the disk, recorded, or replayed
};

/// A built-in scene's name (with its --param values) or a path ending in ".json", as a document.
/// With input, a scene file is parsed from input->text (the path is then only its name and the
/// folder its model files' paths start from) and its models read as input->models says.
/// @throws UsageError for an unknown name (suggesting the nearest one) or a bad parameter; the
///         scene-file library's SceneError (its message names file, line and column) for a bad
///         file.
SceneDocument loadSceneArgument(std::string_view scene, std::span<const std::string> params = {},
                                const SceneFileInput* input = nullptr);

/// Whether the scene argument names a scene file (it ends in .json and is no built-in's name).
bool isSceneFileArgument(std::string_view scene);

/// Where `rt render SCENE` writes without -o: NAME.png for a built-in scene, the file's name
/// with .png instead of .json for a scene file; in the current directory either way.
std::string defaultOutputPath(std::string_view scene);

/// What a command's output must be: the ending of its name, and the sentence that says why.
struct OutputKind {
  std::string_view ending;  ///< ".png"
  std::string_view rule;    ///< "the image is written as PNG, so its name must end in .png"
};
inline constexpr OutputKind PNG_IMAGE{".png",
                                      "the image is written as PNG, so its name must end in .png"};
inline constexpr OutputKind SCENE_FILE{".json", "a scene file's name must end in .json"};
inline constexpr OutputKind MP4_VIDEO{".mp4",
                                      "the video is encoded as MP4, so its name must end in .mp4"};

/// Refuses, before any work is done, an output path that cannot be written, in this order: an
/// existing directory, a path that names no file, a name without kind's ending, a missing
/// parent directory, or one where no file can be created (tried for real: stage04's
/// checkTemporaryFileBeside). what names the path's origin in the message ("-o").
/// @throws UsageError "WHAT: cannot write 'PATH': REASON" or "WHAT: RULE; got 'PATH'".
void checkOutputWritable(const std::string& path, const OutputKind& kind,
                         std::string_view what = "-o");

/// Whether the paths x and y name one file, so that writing one would overwrite the other. Two
/// that exist are compared by the file they reach (its device and inode: a hard link, a
/// symbolic link and any spelling match); otherwise by their absolute paths, the symbolic links
/// at their ends followed as a write follows them (a chain too, a relative target from its
/// link's folder: a link to a file not made yet names that file), the existing part with its
/// symbolic links resolved and the rest made lexically normal ("x", "./x" and "d/../x" match for
/// a file not made yet).
bool sameFile(const std::string& x, const std::string& y);

/// Refuses, before any work, an output that would overwrite a file the scene argument reads:
/// the scene file (when scene names one) or a model file of doc's meshes (sameFile; an input
/// that does not exist is not overwritten). what names the output's origin ("-o"), written what
/// would be written there ("the image").
/// @throws UsageError "WHAT: 'OUTPUT' is SCENE ('FILE'): WRITTEN would overwrite the scene file
///         it reads; give another file", or "... is a model file of SCENE ('FILE'): WRITTEN would
///         overwrite a file the scene reads; give another file".
void checkOutputIsNoInput(const std::string& output, std::string_view what,
                          std::string_view written, std::string_view scene,
                          const SceneDocument& doc);

/// The JSON that `rt probe` prints for ray:
/// {"ray": {"origin": [..], "direction": [..]}, "hits": [{"t", "point", "normal", "geometry",
/// "name"}, ..], "color": [r, g, b]}. Hits are findGeoIntersections' (t > 0, sorted), normals
/// the outward geometric ones, name the geometry's name in the document or null, color the
/// colour given (unclamped): the tracer's for the ray, or the pixel's. Written by formatJson
/// (common/JsonText.h), the scene files' layout.
std::string probeJson(const SceneDocument& doc, const Ray& ray, const Color& color);

}  // namespace rt::cli
