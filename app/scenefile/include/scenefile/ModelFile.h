#pragma once
/// @file ModelFile.h
/// Reading model files (OBJ, PLY, STL, glTF and the other formats Assimp knows) into stage 2's
/// TriangleMesh: the program reads files, the engine gets arrays (DESIGN.md §9).
///
/// One TriangleMesh per material group of the file (the file's meshes of one material joined),
/// triangulated (quads and n-gons become triangles), its vertices shared (identical vertices
/// joined, as STL repeats them per facet), with the file's vertex normals when it has them,
/// computed ones when smooth shading is asked and it has none, and none for flat shading.
/// Points and lines of the file are ignored and counted; triangles of zero area are dropped and
/// counted (TriangleMesh drops them); the caller warns about both.
///
/// Every error is a ModelError whose message starts with the model file's name; the caller (the
/// scene file's `mesh` entry) adds the scene file and the entry.

#include <cstddef>
#include <filesystem>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geometries/TriangleMesh.h"
#include "primitives/Double3.h"

namespace rt {

/// A model file that cannot be read, parsed or turned into meshes.
struct ModelError : std::runtime_error {
  /// message: "MODEL_FILE: detail".
  ModelError(std::string modelFile, const std::string& detail);
  std::string modelFile;  ///< the file's path, or the source name of the memory form
  std::string detail;     ///< what went wrong, without the file's name
};

/// How the vertices are placed: p' = R·(S·p) + translation, where S scales each axis by scale
/// and R rotates by rotationDegrees.x about x, then .y about y, then .z about z. Normals are
/// transformed by the inverse transpose of R·S (and normalised). Multiples of 90 degrees are
/// exact rotations (their sine and cosine exactly 0, 1 or -1). A negative scale mirrors the
/// model, which reverses the winding of its triangles (their flat normals turn inside).
struct ModelTransform {
  Double3 scale{1, 1, 1};            ///< every component finite and non-zero
  Double3 rotationDegrees{0, 0, 0};  ///< finite
  Double3 translation{0, 0, 0};      ///< finite
};

/// What readModelFile does with the file's triangles.
struct ModelOptions {
  /// Smooth: keep the file's vertex normals, or compute them (Assimp's GenSmoothNormals) when the
  /// file has none. Flat (false): no vertex normals, even when the file has them. A vertex
  /// normal that is zero or not finite gets the normal of a triangle of non-zero area using the
  /// vertex (Assimp computes such normals for vertices of zero-area triangles).
  bool smooth = true;
  ModelTransform transform;
};

/// One material group of a model file.
struct ModelGroup {
  /// The file's material name ("usemtl NAME" in OBJ); empty when the file names none.
  std::string material;
  TriangleMesh mesh;
};

/// A model file as meshes.
struct ModelFile {
  std::vector<ModelGroup> groups;    ///< at least one, in the order of the file's materials
  std::size_t droppedTriangles = 0;  ///< triangles of zero area dropped, over all groups
  std::size_t ignoredPoints = 0;     ///< point primitives of the file, not read
  std::size_t ignoredLines = 0;      ///< line primitives of the file, not read
};

/// The bytes of the files that model readings opened (each model file and the files it refers
/// to: an OBJ's material library, a glTF's buffers), by the path they were opened with. A render
/// across machines (rt-mpi) reads them on one machine and sends them to the others, which then
/// read the same models without a shared file system.
struct ModelFileSet {
  std::map<std::string, std::string> files;  ///< path as opened -> the file's bytes

  /// The bytes of every file together.
  std::size_t bytes() const noexcept {
    std::size_t n = 0;
    for (const auto& file : files) n += file.second.size();
    return n;
  }
};

/// Where readModelFile reads: the disk (both null, the default); the disk, with every file it
/// opens kept in *record; or *replay's files only, as if they were the disk (a file not among
/// them is missing).
struct ModelFileSource {
  ModelFileSet* record = nullptr;
  const ModelFileSet* replay = nullptr;
};

/// Reads the model file at file (from source: the disk unless it says otherwise). Replaying a
/// set recorded by the same reading gives the same model, bit for bit.
/// @throws ModelError, the message "FILE: ..." for: a file that is missing or unreadable (the
///         system's reason), a directory, a device or a pipe (not a regular file), a file
///         Assimp cannot parse or validate (its message, which names no line: an index out of
///         range is "OBJ: vertex index out of range" or "Validation failed:
///         aiMesh::mFaces[0]::mIndices[2] is out of range"), a PLY header
///         without an end_header line (on which Assimp would never return), a face without
///         indices, a model without triangles, a size TriangleMesh::requireFits refuses or that
///         memory cannot hold, non-finite coordinates (TriangleMesh's message), a degenerate
///         transform; and, in a build without Assimp, "reading model files needs Assimp:
///         install libassimp-dev (scripts/deps.sh installs it)".
ModelFile readModelFile(const std::filesystem::path& file, const ModelOptions& options,
                        const ModelFileSource& source = {});

/// The same for a model file's bytes in memory. formatHint is the file's extension without the
/// dot ("obj", "ply", "stl"); sourceName is what the messages call the file. Files the model
/// refers to (an OBJ's material library) are not read.
ModelFile readModelFromMemory(std::span<const std::byte> bytes, std::string_view formatHint,
                              const std::string& sourceName, const ModelOptions& options);

/// Whether this build reads model files (it was built with Assimp).
bool modelFilesSupported();

/// The mesh as a binary (little-endian) PLY file, which readModelFile reads back: every vertex
/// as three floats x, y, z (rounded from the mesh's doubles), every triangle as a list of three
/// 32-bit indices, and no normals (a reader with smooth shading computes them). comment, one
/// line, goes into the header (the file's origin). Needs no Assimp: how the project writes the
/// model files it ships (scenes/models/).
/// @throws std::invalid_argument for a comment with a line break.
std::string binaryPly(const TriangleMesh& mesh, const std::string& comment);

}  // namespace rt
