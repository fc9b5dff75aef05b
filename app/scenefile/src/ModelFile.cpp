/// @file ModelFile.cpp
/// readModelFile through Assimp. Assimp does the parsing, its validation of what it read (an
/// index out of range is refused there; the OFF reader's, which it replaces and only logs, by
/// ImportErrors below; a PLY header's counts are checked before) and three post-processing steps
/// (Triangulate, JoinIdenticalVertices, and GenSmoothNormals when smooth shading is asked: it
/// leaves alone a mesh that has normals), after RemoveComponent drops what the mesh does not
/// keep (see flagsFor); this file walks the node tree, applies the node
/// transforms and the caller's transform in double precision, joins the meshes of one material
/// and hands the arrays to TriangleMesh, which validates them.
#include <sys/types.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <assimp/MemoryIOWrapper.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/Logger.hpp>

#include "ModelTransform.h"
#include "scenefile/ModelFile.h"

namespace rt {

namespace {

using scenefile::Affine;
using scenefile::affineOf;

/// The caller's transform as a map; a degenerate one is refused naming the model file.
Affine fromOptions(const ModelTransform& transform, const std::string& source) {
  try {
    return affineOf(transform);
  } catch (const std::invalid_argument& e) {
    throw ModelError(source, e.what());
  }
}

Affine fromAssimp(const aiMatrix4x4& a) {
  Affine r;
  r.m = {Double3(a.a1, a.a2, a.a3), Double3(a.b1, a.b2, a.b3), Double3(a.c1, a.c2, a.c3)};
  r.t = {a.a4, a.b4, a.c4};
  return r;
}

/// The arrays of one material group while they are gathered.
struct GroupArrays {
  std::vector<const aiMesh*> meshes;
  std::vector<Affine> transforms;
};

void collect(const aiScene& scene, const aiNode& node, const Affine& parent,
             std::map<unsigned, GroupArrays>& groups) {
  const Affine here = parent.after(fromAssimp(node.mTransformation));
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const unsigned meshIndex = node.mMeshes[i];
    if (meshIndex >= scene.mNumMeshes || scene.mMeshes[meshIndex] == nullptr) continue;
    const aiMesh* mesh = scene.mMeshes[meshIndex];
    GroupArrays& g = groups[mesh->mMaterialIndex];
    g.meshes.push_back(mesh);
    g.transforms.push_back(here);
  }
  for (unsigned i = 0; i < node.mNumChildren; ++i)
    if (node.mChildren[i] != nullptr) collect(scene, *node.mChildren[i], here, groups);
}

/// Vertex normals that are zero or not finite (GenSmoothNormals gives them to a vertex whose
/// triangles all have zero area, which TriangleMesh then drops; some exporters write them) are
/// replaced by the normal of the first triangle of non-zero area that uses the vertex, or by
/// (0, 0, 1) for a vertex that no such triangle uses (no kept triangle is shaded with it).
void repairNormals(const std::vector<Point>& vertices,
                   const std::vector<TriangleMesh::Indices>& triangles,
                   std::vector<Double3>& normals) {
  std::vector<bool> bad(normals.size(), false);
  std::size_t badCount = 0;
  for (std::size_t i = 0; i < normals.size(); ++i)
    if (!normals[i].isFinite() || normals[i].isZero()) bad[i] = true, ++badCount;
  if (badCount == 0) return;
  for (const TriangleMesh::Indices& t : triangles) {
    if (!(bad[t[0]] || bad[t[1]] || bad[t[2]])) continue;
    const Double3 p0 = vertices[t[0]].xyz();
    const Double3 n = (vertices[t[1]].xyz() - p0).cross(vertices[t[2]].xyz() - p0);
    if (!n.isFinite() || n.isZero()) continue;
    for (std::uint32_t i : t)
      if (bad[i]) normals[i] = n, bad[i] = false;
  }
  for (std::size_t i = 0; i < normals.size(); ++i)
    if (bad[i]) normals[i] = Double3(0, 0, 1);
}

std::string materialName(const aiScene& scene, unsigned index) {
  if (index >= scene.mNumMaterials || scene.mMaterials[index] == nullptr) return {};
  aiString name;
  if (scene.mMaterials[index]->Get(AI_MATKEY_NAME, name) != AI_SUCCESS) return {};
  std::string s(name.C_Str());
  return s == AI_DEFAULT_MATERIAL_NAME ? std::string{} : s;
}

ModelFile toModel(const aiScene* scene, const Assimp::Importer& importer, const std::string& source,
                  const ModelOptions& options) {
  if (scene == nullptr) throw ModelError(source, importer.GetErrorString());
  const Affine user = fromOptions(options.transform, source);

  std::map<unsigned, GroupArrays> arrays;
  if (scene->mRootNode != nullptr) collect(*scene, *scene->mRootNode, user, arrays);

  ModelFile model;
  for (auto& [materialIndex, g] : arrays) {
    // Counts first, from what Assimp reports: the size is refused before anything is allocated.
    std::uint64_t vertexCount = 0, triangleCount = 0;
    bool withNormals = options.smooth;
    for (const aiMesh* mesh : g.meshes) {
      std::uint64_t meshTriangles = 0;
      for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const unsigned n = mesh->mFaces[f].mNumIndices;
        if (n == 3)
          ++meshTriangles;
        else if (n == 1)
          ++model.ignoredPoints;
        else if (n == 2)
          ++model.ignoredLines;
      }
      if (meshTriangles == 0) continue;
      vertexCount += mesh->mNumVertices;
      triangleCount += meshTriangles;
      if (!mesh->HasNormals()) withNormals = false;
    }
    if (triangleCount == 0) continue;

    std::vector<Point> vertices;
    std::vector<TriangleMesh::Indices> triangles;
    std::vector<Double3> normals;
    try {
      TriangleMesh::requireFits(vertexCount, triangleCount, withNormals);
      vertices.reserve(vertexCount);
      triangles.reserve(triangleCount);
      if (withNormals) normals.reserve(vertexCount);

      for (std::size_t k = 0; k < g.meshes.size(); ++k) {
        const aiMesh& mesh = *g.meshes[k];
        bool hasTriangles = false;
        for (unsigned f = 0; f < mesh.mNumFaces && !hasTriangles; ++f)
          hasTriangles = mesh.mFaces[f].mNumIndices == 3;
        if (!hasTriangles) continue;
        const auto offset = static_cast<std::uint32_t>(vertices.size());
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
          const aiVector3D& p = mesh.mVertices[v];
          vertices.emplace_back(p.x, p.y, p.z);
          if (withNormals) {
            const aiVector3D& n = mesh.mNormals[v];
            normals.emplace_back(n.x, n.y, n.z);
          }
        }
        g.transforms[k].place(
            std::span(vertices).subspan(offset),
            withNormals ? std::span(normals).subspan(offset) : std::span<Double3>());
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
          const aiFace& face = mesh.mFaces[f];
          if (face.mNumIndices != 3) continue;
          TriangleMesh::Indices t{};
          for (int c = 0; c < 3; ++c) {
            if (face.mIndices[c] >= mesh.mNumVertices)
              throw ModelError(source, "mesh " + std::to_string(k) + " face " + std::to_string(f) +
                                           ": index " + std::to_string(face.mIndices[c]) +
                                           " is out of range (" +
                                           std::to_string(mesh.mNumVertices) + " vertices)");
            t[static_cast<std::size_t>(c)] = offset + face.mIndices[c];
          }
          triangles.push_back(t);
        }
      }
      repairNormals(vertices, triangles, normals);
      TriangleMesh mesh(std::move(vertices), std::move(triangles), std::move(normals));
      model.droppedTriangles += mesh.droppedTriangles();
      model.groups.push_back({materialName(*scene, materialIndex), std::move(mesh)});
    } catch (const std::invalid_argument& e) {
      throw ModelError(source, e.what());
    } catch (const std::bad_alloc&) {
      throw ModelError(
          source,
          "out of memory for " + std::to_string(vertexCount) + " vertices and " +
              std::to_string(triangleCount) + " triangles (" +
              std::to_string(TriangleMesh::bytesFor(vertexCount, triangleCount, withNormals)) +
              " bytes)");
    }
  }
  if (model.groups.empty())
    throw ModelError(source, "the model has no triangles (" + std::to_string(model.ignoredPoints) +
                                 " points and " + std::to_string(model.ignoredLines) +
                                 " lines ignored)");
  return model;
}

/// Triangulate and JoinIdenticalVertices; GenSmoothNormals when smooth. The components the mesh
/// does not keep (texture coordinates, colours, tangents, and the normals when flat) are removed
/// first, so that vertices differing only in them are joined: an STL cube's 36 corners are 8
/// vertices when flat (its facet normals would keep 24 apart).
unsigned flagsFor(Assimp::Importer& importer, const ModelOptions& options) {
  int unused = aiComponent_TEXCOORDS | aiComponent_COLORS | aiComponent_TANGENTS_AND_BITANGENTS;
  if (!options.smooth) unused |= aiComponent_NORMALS;
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, unused);
  unsigned flags =
      aiProcess_RemoveComponent | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;
  if (options.smooth) flags |= aiProcess_GenSmoothNormals;
  return flags;
}

/// The errors Assimp logs on the importing thread: where ImportErrors collects them, or none.
thread_local std::vector<std::string>* tImportErrors = nullptr;

/// Assimp's logger for the process (Assimp has one): it hands each error to the thread that
/// logged it and drops everything else.
class ErrorsToThread final : public Assimp::Logger {
 public:
  ErrorsToThread() : Logger(NORMAL) {}
  bool attachStream(Assimp::LogStream*, unsigned) override { return false; }
  bool detachStream(Assimp::LogStream*, unsigned) override { return false; }

 private:
  void OnDebug(const char*) override {}
  void OnVerboseDebug(const char*) override {}
  void OnInfo(const char*) override {}
  void OnWarn(const char*) override {}
  void OnError(const char* message) override {
    if (tImportErrors != nullptr) tImportErrors->emplace_back(message);
  }
};

/// Assimp's OFF reader goes on after three faults of the data, logging an error for each and
/// returning a model that is not the file's: an index out of range becomes the last vertex's,
/// a face of no vertex or of more than 9 is dropped, and vertices the file has no lines for are
/// left at the origin. ImportErrors collects the errors logged while it lives, and check()
/// refuses a model read with any of the OFF reader's.
class ImportErrors {
 public:
  ImportErrors() {
    static const bool installed = [] {
      Assimp::DefaultLogger::set(new ErrorsToThread);  // Assimp owns it
      return true;
    }();
    static_cast<void>(installed);
    previous_ = tImportErrors;
    tImportErrors = &errors_;
  }
  ImportErrors(const ImportErrors&) = delete;
  ImportErrors& operator=(const ImportErrors&) = delete;
  ~ImportErrors() { tImportErrors = previous_; }

  /// @throws ModelError naming the OFF reader's faults and how often each was met; scene, when
  /// not null, gives the number of vertices.
  void check(const aiScene* scene, const std::string& source) const {
    std::size_t outOfRange = 0, badFaces = 0, fewLines = 0;  // of each fault, how many
    std::vector<std::string> others;
    for (const std::string& e : errors_) {
      if (e.rfind("OFF: ", 0) != 0) continue;  // another reader's: it decides for itself
      if (e.find("index is out of range") != std::string::npos)
        ++outOfRange;
      else if (e.find("zero indices") != std::string::npos)
        ++badFaces;
      else if (e.find("in the header is incorrect") != std::string::npos)
        ++fewLines;  // of vertices or of faces
      else
        others.push_back(e.substr(5));
    }
    std::string faults;
    const auto add = [&faults](const std::string& fault) {
      faults += (faults.empty() ? "" : "; ") + fault;
    };
    // Assimp 5.2 reads a line more for each face it drops, and then misses the last: its "number
    // of faces" error follows from a dropped face, which is the fault to name.
    if (fewLines > 0 && badFaces == 0)
      add("the file has fewer lines than its header announces vertices and faces");
    if (outOfRange > 0) {
      std::string range;
      if (scene != nullptr && scene->mNumMeshes == 1 && scene->mMeshes[0] != nullptr) {
        const unsigned n = scene->mMeshes[0]->mNumVertices;
        range = " (the file has " + std::to_string(n) + " vertices, numbered 0 to " +
                std::to_string(n - 1) + ")";
      }
      add(std::to_string(outOfRange) + (outOfRange == 1 ? " vertex index" : " vertex indices") +
          " of its faces out of range" + range);
    }
    if (badFaces > 0)
      add(std::to_string(badFaces) + (badFaces == 1 ? " face" : " faces") +
          " of no vertex or of more than 9, which Assimp's OFF reader does not take");
    for (const std::string& e : others) add(e);
    if (!faults.empty()) throw ModelError(source, "OFF: " + faults);
  }

 private:
  std::vector<std::string> errors_;
  std::vector<std::string>* previous_ = nullptr;
};

/// The post-processing, after two checks of what the import gave: the OFF reader's faults that it
/// only logged (ImportErrors), and a face without indices, which Assimp's own validation (asked
/// for at the import) lets through (a PLY whose face data is missing), on
/// which its Triangulate step fails an assertion and aborts the program.
const aiScene* postProcess(Assimp::Importer& importer, const aiScene* scene, unsigned flags,
                           const ImportErrors& errors, const std::string& source) {
  errors.check(scene, source);  // first: a failed import's own message may be a consequence
  if (scene == nullptr) {
    // Assimp catches its own allocation failures and reports them as their what(): a PLY face's
    // list count of 4·10^9 (the header's counts are checked, the lists' are not) said only
    // "std::bad_alloc". The callers say it with the file's size.
    if (std::string_view(importer.GetErrorString()) == "std::bad_alloc") throw std::bad_alloc();
    throw ModelError(source, importer.GetErrorString());
  }
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    if (mesh == nullptr) continue;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 0 || mesh->mFaces[f].mIndices == nullptr)
        throw ModelError(source, "face " + std::to_string(f) + " of mesh " + std::to_string(m) +
                                     " has no vertex indices (does the file end early?)");
  }
  return importer.ApplyPostProcessing(flags);
}

/// How far into a PLY file its header must have ended.
constexpr std::size_t kPlyHeaderLimit = std::size_t{1} << 20;

/// The fewest bytes one value of a PLY property's type takes in a binary file; 0 for a type
/// that is not PLY's.
std::uint64_t plyTypeBytes(std::string_view type) {
  static const std::map<std::string_view, std::uint64_t> kBytes{
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = kBytes.find(type);
  return it == kBytes.end() ? 0 : it->second;
}

/// The words of one header line.
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t at = 0;
  while (at < line.size()) {
    const std::size_t begin = line.find_first_not_of(" \t\r", at);
    if (begin == std::string_view::npos) break;
    const std::size_t stop = std::min(line.find_first_of(" \t\r", begin), line.size());
    out.push_back(line.substr(begin, stop - begin));
    at = stop;
  }
  return out;
}

/// A PLY file's header checked before Assimp reads it (nothing is checked for other formats).
/// start is the file's first bytes, up to kPlyHeaderLimit of them, and size the whole file's.
///  - Assimp 5.2's PLY reader never returns on a header without a line whose first word is
///    "end_header" (found by the model fuzzer): such a header is refused.
///  - Assimp believes the header's counts: a binary file announcing 4·10^9 vertices failed with
///    "std::bad_alloc", an ASCII one ran for minutes and took gigabytes. The counts are checked
///    against the bytes after the header: in binary each element takes at least the sizes of
///    its scalar properties and of its lists' counts; in ASCII each value (a list's count
///    included) at least one character and a separator, the file's last value perhaps without.
void requirePlyHeader(std::string_view start, std::uint64_t size, const std::string& source) {
  const bool ply =
      start.size() >= 3 && (start.substr(0, 3) == "ply" || start.substr(0, 3) == "PLY");
  if (!ply) return;
  // A line whose first word is end_header: followed by a space, a tab, the line's end or the
  // end of the data (Assimp takes no other white space there).
  constexpr std::string_view kEnd = "\nend_header";
  std::size_t headerEnd = std::string_view::npos;
  for (std::size_t at = start.find(kEnd); at != std::string_view::npos;
       at = start.find(kEnd, at + 1)) {
    const std::size_t next = at + kEnd.size();
    if (next == start.size() || std::string_view(" \t\r\n").find(start[next]) != start.npos) {
      headerEnd = at + 1;
      break;
    }
  }
  if (headerEnd == std::string_view::npos)
    throw ModelError(source, "the PLY header does not end (no end_header line in its first " +
                                 std::to_string(start.size()) + " bytes)");

  // The data start after the end_header line's end.
  const std::size_t lineEnd = start.find('\n', headerEnd);
  const std::uint64_t dataStart = lineEnd == std::string_view::npos ? start.size() : lineEnd + 1;
  const std::uint64_t data = size > dataStart ? size - dataStart : 0;
  bool binary = false;
  struct Element {
    std::string_view name;
    std::uint64_t count = 0;
    std::uint64_t bytes = 0;  ///< the fewest bytes one element takes
  };
  std::vector<Element> elements;
  const std::string_view header = start.substr(0, headerEnd);
  for (std::size_t at = 0; at < header.size();) {
    const std::size_t stop = std::min(header.find('\n', at), header.size());
    const std::vector<std::string_view> w = words(header.substr(at, stop - at));
    at = stop + 1;
    if (w.size() >= 2 && w[0] == "format") {
      binary = w[1] != "ascii";
    } else if (w.size() >= 3 && w[0] == "element") {
      std::uint64_t count = 0;
      const auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), count);
      if (ec == std::errc::result_out_of_range)
        count = std::numeric_limits<std::uint64_t>::max();
      else if (ec != std::errc() || end != w[2].data() + w[2].size())
        return;  // not a count: Assimp's to judge
      elements.push_back({w[1], count, 0});
    } else if (w.size() >= 3 && w[0] == "property" && !elements.empty()) {
      // "property TYPE NAME", or "property list COUNT_TYPE ITEM_TYPE NAME" (its items may be
      // none: only the count is certain).
      const std::uint64_t bytes = plyTypeBytes(w[1] == "list" ? w[2] : w[1]);
      if (bytes == 0) return;  // a type PLY does not have: Assimp's to judge
      elements.back().bytes += binary ? bytes : 2;
    }
  }
  // The fewest bytes the counts ask for, at most 2^64 − 1 (a larger sum stops there: no
  // overflow).
  constexpr std::uint64_t kMost = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t needed = 0;
  std::string announced;
  for (const Element& e : elements) {
    const std::uint64_t bytes = e.bytes == 0                ? 0
                                : e.count > kMost / e.bytes ? kMost
                                                            : e.count * e.bytes;
    needed = bytes > kMost - needed ? kMost : needed + bytes;
    announced += (announced.empty() ? "" : ", ") + std::to_string(e.count) + " '" +
                 std::string(e.name) + "'";
  }
  if (!binary && needed > 0 && needed < kMost) --needed;  // the last separator may be missing
  if (needed <= data) return;
  throw ModelError(source, "the PLY header announces " + announced + " (at least " +
                               (needed == kMost ? "2^64" : std::to_string(needed)) + " bytes of " +
                               (binary ? "binary" : "ASCII") + " data), but " +
                               std::to_string(data) + " bytes follow it");
}

/// Assimp's files served from a ModelFileSource: the disk with every file opened kept in the
/// record (each read whole, once, then served from memory), or the replayed set's files only.
class SourceIoSystem final : public Assimp::IOSystem {
 public:
  explicit SourceIoSystem(const ModelFileSource& source) : source_(source) {}

  bool Exists(const char* path) const override {
    if (source_.replay) return source_.replay->files.contains(path);
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
  }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* path, const char* mode) override {
    if (std::strchr(mode, 'w') != nullptr || std::strchr(mode, 'a') != nullptr) return nullptr;
    const std::string* bytes = source_.replay ? find(*source_.replay, path) : record(path);
    if (bytes == nullptr) return nullptr;
    return new Assimp::MemoryIOStream(reinterpret_cast<const std::uint8_t*>(bytes->data()),
                                      bytes->size());
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

 private:
  static const std::string* find(const ModelFileSet& set, const char* path) {
    const auto it = set.files.find(path);
    return it == set.files.end() ? nullptr : &it->second;
  }
  const std::string* record(const char* path) {
    if (const std::string* kept = find(*source_.record, path)) return kept;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return nullptr;
    std::ifstream in(path, std::ios::binary);
    if (!in) return nullptr;
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return nullptr;
    return &(source_.record->files[path] = std::move(bytes));
  }

  ModelFileSource source_;
};

}  // namespace

ModelError::ModelError(std::string file, const std::string& what)
    : std::runtime_error(file + ": " + what), modelFile(std::move(file)), detail(what) {}

bool modelFilesSupported() { return true; }

ModelFile readModelFile(const std::filesystem::path& given, const ModelOptions& options,
                        const ModelFileSource& from) {
  // "a/../b/m.obj" read as "b/m.obj": Assimp's OBJ reader, looking for the file's material
  // library beside it, fails with "File read error" on a path that climbs out of a folder and
  // into another when that library is missing (where it only warns otherwise).
  const std::filesystem::path file = given.lexically_normal();
  const std::string source = file.string();
  if (from.replay) {
    // What the machine that read the files sent: the file itself must be among them.
    const auto it = from.replay->files.find(source);
    if (it == from.replay->files.end())
      throw ModelError(source, "cannot read: not among the model files received (" +
                                   std::to_string(from.replay->files.size()) + ")");
    requirePlyHeader(std::string_view(it->second).substr(0, kPlyHeaderLimit), it->second.size(),
                     source);
  } else {
    // Assimp's own message for a missing file does not say why; the system's reason does.
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec))
      throw ModelError(source, "cannot read: it is a directory");
    // A device or a pipe (/dev/zero, a FIFO) would be read forever or block.
    if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
      throw ModelError(source, "cannot read: it is not a regular file");
    std::FILE* f = std::fopen(source.c_str(), "rb");
    if (f == nullptr) throw ModelError(source, std::string("cannot read: ") + std::strerror(errno));
    std::string start(kPlyHeaderLimit, '\0');
    start.resize(std::fread(start.data(), 1, start.size(), f));
    // The whole file's size: what was read, or where its end is when there is more.
    off_t size = static_cast<off_t>(start.size());
    if (start.size() == kPlyHeaderLimit && ::fseeko(f, 0, SEEK_END) == 0) size = ::ftello(f);
    std::fclose(f);
    requirePlyHeader(start, static_cast<std::uint64_t>(std::max<off_t>(size, 0)), source);
  }
  fromOptions(options.transform, source);  // refused before the file is parsed

  Assimp::Importer importer;
  if (from.record || from.replay) importer.SetIOHandler(new SourceIoSystem(from));  // it owns it
  try {
    const unsigned flags = flagsFor(importer, options);
    const ImportErrors errors;
    const aiScene* scene = importer.ReadFile(source, aiProcess_ValidateDataStructure);
    return toModel(postProcess(importer, scene, flags, errors, source), importer, source, options);
  } catch (const std::bad_alloc&) {
    std::error_code ec;
    const std::uintmax_t size =
        from.replay ? from.replay->files.at(source).size() : std::filesystem::file_size(file, ec);
    throw ModelError(source,
                     "out of memory while reading the file (" + std::to_string(size) + " bytes)");
  }
}

ModelFile readModelFromMemory(std::span<const std::byte> bytes, std::string_view formatHint,
                              const std::string& sourceName, const ModelOptions& options) {
  if (bytes.empty()) throw ModelError(sourceName, "the model is empty (0 bytes)");
  requirePlyHeader(
      {reinterpret_cast<const char*>(bytes.data()), std::min(bytes.size(), kPlyHeaderLimit)},
      bytes.size(), sourceName);
  fromOptions(options.transform, sourceName);
  Assimp::Importer importer;
  const std::string hint(formatHint);
  try {
    const unsigned flags = flagsFor(importer, options);
    const ImportErrors errors;
    const aiScene* scene = importer.ReadFileFromMemory(
        bytes.data(), bytes.size(), aiProcess_ValidateDataStructure, hint.c_str());
    return toModel(postProcess(importer, scene, flags, errors, sourceName), importer, sourceName,
                   options);
  } catch (const std::bad_alloc&) {
    throw ModelError(sourceName, "out of memory while reading the model (" +
                                     std::to_string(bytes.size()) + " bytes)");
  }
}

}  // namespace rt
