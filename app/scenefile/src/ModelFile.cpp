/// @file ModelFile.cpp
/// readModelFile through Assimp. Assimp does the parsing, its validation of what it read (an
/// index out of range is refused there) and three post-processing steps
/// (Triangulate, JoinIdenticalVertices, and GenSmoothNormals when smooth shading is asked: it
/// leaves alone a mesh that has normals), after RemoveComponent drops what the mesh does not
/// keep (see flagsFor); this file walks the node tree, applies the node
/// transforms and the caller's transform in double precision, joins the meshes of one material
/// and hands the arrays to TriangleMesh, which validates them.
#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include <assimp/MemoryIOWrapper.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>

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

/// The post-processing, after a check of what the import gave: Assimp's own validation (asked for
/// at the import) lets through a face without indices (a PLY whose face data is missing), on
/// which its Triangulate step fails an assertion and aborts the program.
const aiScene* postProcess(Assimp::Importer& importer, const aiScene* scene, unsigned flags,
                           const std::string& source) {
  if (scene == nullptr) throw ModelError(source, importer.GetErrorString());
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

/// Assimp 5.2's PLY reader never returns on a header without a line whose first word is
/// "end_header"
/// (found by the model fuzzer): such a file is refused before Assimp sees it. start is the
/// file's first bytes, up to kPlyHeaderLimit of them.
void requirePlyHeaderEnds(std::string_view start, const std::string& source) {
  const bool ply =
      start.size() >= 3 && (start.substr(0, 3) == "ply" || start.substr(0, 3) == "PLY");
  if (!ply) return;
  // A line whose first word is end_header: followed by a space, a tab, the line's end or the
  // end of the data (Assimp takes no other white space there).
  constexpr std::string_view kEnd = "\nend_header";
  for (std::size_t at = start.find(kEnd); at != std::string_view::npos;
       at = start.find(kEnd, at + 1)) {
    const std::size_t next = at + kEnd.size();
    if (next == start.size() || std::string_view(" \t\r\n").find(start[next]) != start.npos) return;
  }
  throw ModelError(source, "the PLY header does not end (no end_header line in its first " +
                               std::to_string(start.size()) + " bytes)");
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
    requirePlyHeaderEnds(std::string_view(it->second).substr(0, kPlyHeaderLimit), source);
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
    std::fclose(f);
    requirePlyHeaderEnds(start, source);
  }
  fromOptions(options.transform, source);  // refused before the file is parsed

  Assimp::Importer importer;
  if (from.record || from.replay) importer.SetIOHandler(new SourceIoSystem(from));  // it owns it
  try {
    const unsigned flags = flagsFor(importer, options);
    const aiScene* scene = importer.ReadFile(source, aiProcess_ValidateDataStructure);
    return toModel(postProcess(importer, scene, flags, source), importer, source, options);
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
  requirePlyHeaderEnds(
      {reinterpret_cast<const char*>(bytes.data()), std::min(bytes.size(), kPlyHeaderLimit)},
      sourceName);
  fromOptions(options.transform, sourceName);
  Assimp::Importer importer;
  const std::string hint(formatHint);
  try {
    const unsigned flags = flagsFor(importer, options);
    const aiScene* scene = importer.ReadFileFromMemory(
        bytes.data(), bytes.size(), aiProcess_ValidateDataStructure, hint.c_str());
    return toModel(postProcess(importer, scene, flags, sourceName), importer, sourceName, options);
  } catch (const std::bad_alloc&) {
    throw ModelError(sourceName, "out of memory while reading the model (" +
                                     std::to_string(bytes.size()) + " bytes)");
  }
}

}  // namespace rt
