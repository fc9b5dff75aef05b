/// @file ModelFile.cpp
/// readModelFile through Assimp. Assimp does the parsing, its validation of what it read (an
/// index out of range is refused there) and three post-processing steps
/// (Triangulate, JoinIdenticalVertices, and GenSmoothNormals when smooth shading is asked: it
/// leaves alone a mesh that has normals), after RemoveComponent drops what the mesh does not
/// keep (see flagsFor); this file walks the node tree, applies the node
/// transforms and the caller's transform in double precision, joins the meshes of one material
/// and hands the arrays to TriangleMesh, which validates them.
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <new>
#include <string>
#include <system_error>
#include <utility>

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "scenefile/ModelFile.h"

namespace rt {

namespace {

/// A 3x3 matrix and a translation: p' = m·p + t. Rows of m.
struct Affine {
  std::array<Double3, 3> m{Double3(1, 0, 0), Double3(0, 1, 0), Double3(0, 0, 1)};
  Double3 t{0, 0, 0};

  Double3 linear(const Double3& v) const {
    return {m[0].x * v.x + m[0].y * v.y + m[0].z * v.z, m[1].x * v.x + m[1].y * v.y + m[1].z * v.z,
            m[2].x * v.x + m[2].y * v.y + m[2].z * v.z};
  }
  Double3 apply(const Double3& p) const { return linear(p) + t; }

  /// this·o (o applied first).
  Affine after(const Affine& o) const {
    Affine r;
    for (int i = 0; i < 3; ++i) {
      const Double3& a = m[i];
      r.m[i] = {a.x * o.m[0].x + a.y * o.m[1].x + a.z * o.m[2].x,
                a.x * o.m[0].y + a.y * o.m[1].y + a.z * o.m[2].y,
                a.x * o.m[0].z + a.y * o.m[1].z + a.z * o.m[2].z};
    }
    r.t = apply(o.t);
    return r;
  }

  double determinant() const {
    const Double3 &a = m[0], &b = m[1], &c = m[2];
    return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
           a.z * (b.x * c.y - b.y * c.x);
  }

  /// The cofactor matrix times the sign of the determinant: the inverse transpose up to a
  /// positive factor, which the normalisation of the normals removes (and no division).
  Affine normalMatrix() const {
    const Double3 &a = m[0], &b = m[1], &c = m[2];
    Affine r;
    r.m[0] = {b.y * c.z - b.z * c.y, b.z * c.x - b.x * c.z, b.x * c.y - b.y * c.x};
    r.m[1] = {a.z * c.y - a.y * c.z, a.x * c.z - a.z * c.x, a.y * c.x - a.x * c.y};
    r.m[2] = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    if (determinant() < 0)
      for (Double3& row : r.m) row = -row;
    return r;
  }
};

/// Sine and cosine of an angle in degrees, exact at multiples of 90 degrees.
std::pair<double, double> sinCosDegrees(double degrees) {
  const double turn = std::fmod(degrees, 360.0);
  const double quarter = turn / 90.0;
  if (quarter == std::floor(quarter)) {
    switch ((static_cast<int>(quarter) % 4 + 4) % 4) {
      case 0:
        return {0.0, 1.0};
      case 1:
        return {1.0, 0.0};
      case 2:
        return {0.0, -1.0};
      default:
        return {-1.0, 0.0};
    }
  }
  const double radians = turn * (3.14159265358979323846 / 180.0);
  return {std::sin(radians), std::cos(radians)};
}

Affine fromOptions(const ModelTransform& tr, const std::string& source) {
  const auto refuse = [&](const std::string& what) {
    throw ModelError(source, "the transform is degenerate: " + what);
  };
  if (!tr.scale.isFinite() || tr.scale.x == 0 || tr.scale.y == 0 || tr.scale.z == 0)
    refuse("scale must be finite and non-zero on every axis, got " + tr.scale.str());
  if (!tr.rotationDegrees.isFinite())
    refuse("rotation must be finite, got " + tr.rotationDegrees.str());
  if (!tr.translation.isFinite()) refuse("translation must be finite, got " + tr.translation.str());
  Affine scale;
  scale.m = {Double3(tr.scale.x, 0, 0), Double3(0, tr.scale.y, 0), Double3(0, 0, tr.scale.z)};
  const auto [sx, cx] = sinCosDegrees(tr.rotationDegrees.x);
  const auto [sy, cy] = sinCosDegrees(tr.rotationDegrees.y);
  const auto [sz, cz] = sinCosDegrees(tr.rotationDegrees.z);
  Affine rx, ry, rz;
  rx.m = {Double3(1, 0, 0), Double3(0, cx, -sx), Double3(0, sx, cx)};
  ry.m = {Double3(cy, 0, sy), Double3(0, 1, 0), Double3(-sy, 0, cy)};
  rz.m = {Double3(cz, -sz, 0), Double3(sz, cz, 0), Double3(0, 0, 1)};
  Affine r = rz.after(ry.after(rx.after(scale)));
  r.t = tr.translation;
  return r;
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
        const Affine& place = g.transforms[k];
        const Affine normalPlace = place.normalMatrix();
        const auto offset = static_cast<std::uint32_t>(vertices.size());
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
          const aiVector3D& p = mesh.mVertices[v];
          vertices.emplace_back(place.apply(Double3(p.x, p.y, p.z)));
          if (withNormals) {
            const aiVector3D& n = mesh.mNormals[v];
            normals.push_back(normalPlace.linear(Double3(n.x, n.y, n.z)));
          }
        }
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

}  // namespace

ModelError::ModelError(std::string file, const std::string& what)
    : std::runtime_error(file + ": " + what), modelFile(std::move(file)), detail(what) {}

bool modelFilesSupported() { return true; }

ModelFile readModelFile(const std::filesystem::path& file, const ModelOptions& options) {
  const std::string source = file.string();
  // Assimp's own message for a missing file does not say why; the system's reason does.
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw ModelError(source, "cannot read: it is a directory");
  std::FILE* f = std::fopen(source.c_str(), "rb");
  if (f == nullptr) throw ModelError(source, std::string("cannot read: ") + std::strerror(errno));
  std::string start(kPlyHeaderLimit, '\0');
  start.resize(std::fread(start.data(), 1, start.size(), f));
  std::fclose(f);
  requirePlyHeaderEnds(start, source);
  fromOptions(options.transform, source);  // refused before the file is parsed

  Assimp::Importer importer;
  try {
    const unsigned flags = flagsFor(importer, options);
    const aiScene* scene = importer.ReadFile(source, aiProcess_ValidateDataStructure);
    return toModel(postProcess(importer, scene, flags, source), importer, source, options);
  } catch (const std::bad_alloc&) {
    throw ModelError(source, "out of memory while reading the file (" +
                                 std::to_string(std::filesystem::file_size(file, ec)) + " bytes)");
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
