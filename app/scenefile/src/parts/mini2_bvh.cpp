// The scene format's mini-project-2 part: the acceleration structure and the threads, and the
// `mesh` geometry, a triangle mesh read from a model file or given inline. A mesh's triangles are
// primitives of the accelerations one by one (intersections/Primitives.h), which is what makes a
// mesh of thousands of triangles practical, so the key is this stage's.
#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../Format.h"
#include "../ModelTransform.h"
#include "../Writers.h"
#include "Lighting.h"
#include "bvh/Acceleration.h"
#include "common/Integers.h"
#include "common/NearestName.h"
#include "parallel/TilePool.h"
#include "scenefile/LitDocument.h"
#include "scenefile/MeshDocument.h"
#include "scenefile/ModelFile.h"

namespace rt::scenefile {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view SHADINGS[] = {"smooth", "flat"};

// ---------------------------------------------------------------------------------------------
// Reading

/// A mesh entry's own keys (kept in GeometryFields::typeFields).
struct MeshFields {
  std::optional<std::string> file;
  std::optional<std::vector<Point>> vertices;
  std::optional<std::vector<TriangleMesh::Indices>> triangles;
  std::optional<std::vector<Double3>> normals;
  ModelTransform transform;
  bool smooth = true;
};

MeshFields& meshOf(GeometryFields& f) {
  if (!f.typeFields.has_value()) f.typeFields = MeshFields{};
  return std::any_cast<MeshFields&>(f.typeFields);
}

/// "1 triangle", "3 triangles"; "3 vertices" with the plural given.
std::string counted(std::size_t n, const std::string& thing, const std::string& things = "") {
  return std::to_string(n) + " " + (n == 1 ? thing : things.empty() ? thing + "s" : things);
}

/// [x,y,z] of finite numbers; "expected WHAT" otherwise.
Double3 readTriple(const Node& n, std::string_view what) {
  if (!n.json().is_array() || n.json().size() != 3) n.expected(what);
  std::array<double, 3> v{};
  std::size_t i = 0;
  n.forEachElement([&](const Node& e) { v[i++] = readNumber(e); });
  return {v[0], v[1], v[2]};
}

/// A number for every axis, or [x,y,z]; none of them zero (the mesh would be flattened away).
Double3 readScale(const Node& n) {
  constexpr std::string_view what = "a scale: a non-zero number or [x,y,z] of non-zero numbers";
  const Double3 s = n.json().is_number() ? Double3(readNumber(n)) : readTriple(n, what);
  if (s.x == 0 || s.y == 0 || s.z == 0) n.expected(what);
  return s;
}

constexpr const char* EITHER_FORM = "give either 'file' or 'vertices' and 'triangles', not both";

void readVertices(const Node& n, MeshFields& m) {
  if (m.file) n.failAtKey(EITHER_FORM);
  m.vertices = readPoints(n, 3, SIZE_MAX);
}

void readTriangles(const Node& n, MeshFields& m) {
  if (m.file) n.failAtKey(EITHER_FORM);
  if (!m.vertices) n.failAtKey("'triangles' index the mesh's 'vertices', which are not given");
  const std::size_t count = m.vertices->size();
  const int last = static_cast<int>(std::min<std::size_t>(count - 1, INT_MAX));
  if (!n.json().is_array() || n.json().empty())
    n.expected("an array of at least one triangle [i,j,k] of vertex indices");
  std::vector<TriangleMesh::Indices> triangles;
  triangles.reserve(n.json().size());
  n.forEachElement([&](const Node& t) {
    if (!t.json().is_array() || t.json().size() != 3)
      t.expected("a triangle [i,j,k] of vertex indices");
    TriangleMesh::Indices corners{};
    std::size_t c = 0;
    t.forEachElement([&](const Node& i) {
      const std::optional<int> index = integerIn(i.json(), 0, last);
      if (!index)
        i.expected("a vertex index from 0 to " + std::to_string(last) + " (the mesh has " +
                   counted(count, "vertex", "vertices") + ")");
      corners[c++] = static_cast<std::uint32_t>(*index);
    });
    triangles.push_back(corners);
  });
  m.triangles = std::move(triangles);
}

void readNormals(const Node& n, MeshFields& m) {
  if (!m.vertices)
    n.failAtKey("'normals' are one per vertex of an inline mesh's 'vertices', which are not given");
  const std::size_t count = m.vertices->size();
  if (!n.json().is_array() || n.json().size() != count)
    n.expected("an array of " + std::to_string(count) + " normals [x,y,z], one per vertex");
  std::vector<Double3> normals;
  normals.reserve(count);
  n.forEachElement([&](const Node& e) { normals.push_back(readDirection(e).xyz()); });
  m.normals = std::move(normals);
}

void attachMesh(SceneFormat& format) {
  using F = GeometryFields;
  constexpr std::string_view MESH = "geometry mesh";
  format.attach<F>(MESH, "file", [](const Node& n, F& f) {
    const std::string file = readString(n);
    if (file.empty()) n.expected("a model file's path");
    meshOf(f).file = file;
  });
  format.attach<F>(MESH, "vertices", [](const Node& n, F& f) { readVertices(n, meshOf(f)); });
  format.attach<F>(MESH, "triangles", [](const Node& n, F& f) { readTriangles(n, meshOf(f)); });
  format.attach<F>(MESH, "normals", [](const Node& n, F& f) { readNormals(n, meshOf(f)); });
  format.attach<F>(MESH, "scale",
                   [](const Node& n, F& f) { meshOf(f).transform.scale = readScale(n); });
  format.attach<F>(MESH, "rotation", [](const Node& n, F& f) {
    meshOf(f).transform.rotationDegrees = readTriple(n, "a rotation [x,y,z] in degrees");
  });
  format.attach<F>(MESH, "translation", [](const Node& n, F& f) {
    meshOf(f).transform.translation = readTriple(n, "a translation [x,y,z]");
  });
  format.attach<F>(MESH, "shading", [](const Node& n, F& f) {
    meshOf(f).smooth = readChoice(n, "a shading", SHADINGS) == "smooth";
  });
  // The values are read with the model file's groups, when the entry is built.
  format.attach<F>(MESH, "materials", [](const Node& n, F&) {
    if (!n.json().is_object())
      n.expected("an object of the model file's material groups and their materials");
  });
}

/// Adds a mesh that looks like row `row` to the document's scene; returns its index.
std::uint32_t addMesh(const Node& n, TriangleMesh mesh, std::uint32_t row) {
  try {
    return litScene(n.context().doc)
        .addMesh(std::make_shared<const TriangleMesh>(std::move(mesh)), row);
  } catch (const std::length_error& e) {
    n.fail(e.what());
  }
}

void buildInlineMesh(const Node& n, GeometryFields& f, MeshFields& m) {
  if (!m.triangles) n.fail("missing required key 'triangles' (required with 'vertices')");
  if (n.find("materials"))
    n.member("materials")
        .failAtKey(
            "'materials' is for the material groups of a model file; an inline mesh "
            "is one group: give it 'material'");
  std::vector<Point> vertices = std::move(*m.vertices);
  // Flat shading: no normals, even when given (as a model file's are dropped).
  std::vector<Double3> normals =
      m.smooth && m.normals ? std::move(*m.normals) : std::vector<Double3>{};
  try {
    affineOf(m.transform).place(vertices, normals);
  } catch (const std::invalid_argument& e) {
    n.fail(e.what());
  }
  std::optional<TriangleMesh> mesh;
  try {
    mesh.emplace(std::move(vertices), std::move(*m.triangles), std::move(normals));
  } catch (const std::invalid_argument& e) {
    n.fail(e.what());
  }
  SceneDocument& doc = n.context().doc;
  if (const std::size_t dropped = mesh->droppedTriangles())
    doc.warnings.push_back(n.member("triangles")
                               .message(counted(dropped, "triangle") +
                                        " of zero area dropped (of " +
                                        std::to_string(dropped + mesh->triangleCount()) + ")"));
  const std::uint32_t k = addMesh(n, std::move(*mesh), appearanceRowOf(n, f));
  doc.part<MeshEntries>().entries.push_back({k, 1, std::move(f.name), std::nullopt});
}

/// Refuses a name of "materials" that is no material group of the model file.
void checkGroupNames(const Node& materials, const ModelFile& model, const std::string& file) {
  std::vector<std::string_view> groups;
  for (const ModelGroup& g : model.groups)
    if (!g.material.empty() && std::find(groups.begin(), groups.end(), g.material) == groups.end())
      groups.push_back(g.material);
  materials.forEachMember([&](std::string_view group, const Node& value) {
    if (std::find(groups.begin(), groups.end(), group) != groups.end()) return;
    const std::string known = groups.empty() ? "it names none" : "its groups: " + joinNames(groups);
    value.failAtKey("no material group '" + std::string(group) + "' in " + file +
                    didYouMean(group, groups) + " (" + known + ")");
  });
}

void buildModelMesh(const Node& n, GeometryFields& f, MeshFields& m) {
  const Node fileNode = n.member("file");
  const fs::path given(*m.file);
  // Relative to the scene file's folder, so that a scene and its models move together.
  const fs::path path =
      given.is_absolute() ? given : fs::path(n.context().source).parent_path() / given;
  ModelFile model = [&] {
    try {
      return readModelFile(path, {m.smooth, m.transform}, n.context().models);
    } catch (const ModelError& e) {
      fileNode.fail(e.what());
    }
  }();
  std::optional<Node> materials;
  if (n.find("materials")) {
    materials.emplace(n.member("materials"));
    checkGroupNames(*materials, model, path.string());
  }

  MeshEntry entry{0, 0, std::move(f.name), MeshEntry::ModelSource{}};
  MeshEntry::ModelSource& source = *entry.model;
  source.file = *m.file;
  source.absolute = fs::absolute(path).lexically_normal();
  source.transform = m.transform;
  source.smooth = m.smooth;
  // The entry's own look is made a row only when a group uses it.
  std::optional<std::uint32_t> entryRow;
  for (std::size_t i = 0; i < model.groups.size(); ++i) {
    ModelGroup& g = model.groups[i];
    const bool mapped = materials && !g.material.empty() && materials->find(g.material);
    if (!mapped && !entryRow) entryRow = appearanceRowOf(n, f);
    const std::uint32_t row =
        mapped ? appearanceRowWith(materials->member(g.material), f) : *entryRow;
    const std::uint32_t k = addMesh(n, std::move(g.mesh), row);
    if (i == 0) entry.firstMesh = k;
    ++entry.meshCount;
    source.groups.push_back(std::move(g.material));
    source.mapped.push_back(mapped);
  }

  std::vector<std::string> notes;
  if (model.droppedTriangles)
    notes.push_back(counted(model.droppedTriangles, "triangle") + " of zero area dropped");
  std::vector<std::string> ignored;
  if (model.ignoredPoints) ignored.push_back(counted(model.ignoredPoints, "point"));
  if (model.ignoredLines) ignored.push_back(counted(model.ignoredLines, "line"));
  if (!ignored.empty())
    notes.push_back(ignored.front() + (ignored.size() > 1 ? " and " + ignored.back() : "") +
                    " ignored (a mesh is its triangles)");
  SceneDocument& doc = n.context().doc;
  if (!notes.empty())
    doc.warnings.push_back(
        fileNode.message(path.string() + ": " +
                         joinNames(std::vector<std::string_view>(notes.begin(), notes.end()))));
  doc.part<MeshEntries>().entries.push_back(std::move(entry));
}

void buildMesh(const Node& n, GeometryFields& f) {
  MeshFields& m = meshOf(f);
  if (m.file) return buildModelMesh(n, f, m);
  if (m.vertices) return buildInlineMesh(n, f, m);
  n.fail("missing required key 'file' (or give 'vertices' and 'triangles')");
}

// ---------------------------------------------------------------------------------------------
// Writing

/// A mesh as an inline entry: its vertices and normals exactly (a normal as a vector that
/// TriangleMesh's normalisation turns into the stored one), its triangles, its look.
Json inlineMeshJson(const SceneDocument& doc, std::uint32_t k) {
  const LitScene& scene = litScene(doc);
  const TriangleMesh& mesh = *scene.geometries.meshes()[k].mesh;
  Json g = {{"type", "mesh"}};
  Json& vertices = g["vertices"] = Json::array();
  for (const Point& p : mesh.vertices()) vertices.push_back(jsonTriple(p.xyz()));
  Json& triangles = g["triangles"] = Json::array();
  for (const TriangleMesh::Indices& t : mesh.triangles())
    triangles.push_back(Json::array({t[0], t[1], t[2]}));
  if (mesh.hasNormals()) {
    Json& normals = g["normals"] = Json::array();
    for (const Vector& v : mesh.normals()) normals.push_back(direction(v));
  }
  writeAppearance(doc, scene.meshAppearance[k], g, "mesh " + std::to_string(k));
  return g;
}

/// The model file's path as the written file should name it: an absolute path as it was given,
/// a relative one rewritten relative to folder (the folder of the file being written).
std::string modelPathFrom(const MeshEntry::ModelSource& source, const fs::path& folder) {
  if (fs::path(source.file).is_absolute()) return source.file;
  const fs::path base =
      (folder.empty() ? fs::current_path() : fs::absolute(folder)).lexically_normal();
  const fs::path relative = source.absolute.lexically_relative(base);
  return (relative.empty() ? source.absolute : relative).generic_string();
}

/// A model file's entry as it was read: the file, its transform and shading, the entry's look
/// and the groups' materials.
Json modelEntryJson(const SceneDocument& doc, const MeshEntry& e, const fs::path& folder) {
  const LitScene& scene = litScene(doc);
  const MeshEntry::ModelSource& source = *e.model;
  if (e.firstMesh + std::uint64_t{e.meshCount} > scene.geometries.meshes().size() ||
      source.groups.size() != e.meshCount || source.mapped.size() != e.meshCount)
    throw std::logic_error("toJson: the entry of model file " + source.file + " names meshes " +
                           std::to_string(e.firstMesh) + " to " +
                           std::to_string(e.firstMesh + e.meshCount) + " but the scene has " +
                           std::to_string(scene.geometries.meshes().size()));
  Json g = {{"type", "mesh"}, {"file", modelPathFrom(source, folder)}};
  const ModelTransform none;
  if (!same(source.transform.scale, none.scale)) g["scale"] = coefficient(source.transform.scale);
  if (!same(source.transform.rotationDegrees, none.rotationDegrees))
    g["rotation"] = jsonTriple(source.transform.rotationDegrees);
  if (!same(source.transform.translation, none.translation))
    g["translation"] = jsonTriple(source.transform.translation);
  if (!source.smooth) g["shading"] = "flat";
  Json materials = Json::object();
  std::optional<std::uint32_t> entryRow;
  for (std::uint32_t i = 0; i < e.meshCount; ++i) {
    const std::uint32_t k = e.firstMesh + i;
    const std::uint32_t row = scene.meshAppearance[k];
    if (!source.mapped[i]) {
      if (!entryRow) entryRow = row;
      continue;
    }
    Json look = Json::object();
    writeAppearance(doc, row, look, "mesh " + std::to_string(k));
    materials[source.groups[i]] = look.contains("material") ? look["material"] : Json::object();
  }
  writeAppearance(doc, entryRow.value_or(scene.meshAppearance[e.firstMesh]), g,
                  "mesh " + std::to_string(e.firstMesh));
  // Every group has a material of "materials": the entry's own was used by none.
  if (!entryRow) g.erase("material");
  if (!materials.empty()) g["materials"] = std::move(materials);
  return g;
}

void writeMeshes(const SceneDocument& doc, const fs::path& folder, Json& geometries) {
  const std::vector<MeshEntry>& entries = meshEntries(doc).entries;
  const auto count = static_cast<std::uint32_t>(litScene(doc).geometries.meshes().size());
  std::size_t next = 0;  // the entries are in the order of their meshes
  for (std::uint32_t k = 0; k < count;) {
    const MeshEntry* e =
        next < entries.size() && entries[next].firstMesh == k ? &entries[next++] : nullptr;
    Json g = e && e->model ? modelEntryJson(doc, *e, folder) : inlineMeshJson(doc, k);
    if (e && !e->name.empty()) g["name"] = e->name;
    orderKeys(g, {"geometry mesh", "geometry"});
    geometries.push_back(std::move(g));
    k += e ? e->meshCount : 1;
  }
}

}  // namespace

void registerFormat_mini2_bvh(SceneFormat& format) {
  using R = RenderSettings;
  format.attach<R>("render", "accel", [](const Node& n, R& r) {
    r.accel = readChoice(n, "an acceleration", ACCELERATION_NAMES);
  });
  format.attach<R>("render", "lightBuffers",
                   [](const Node& n, R& r) { r.lightBuffers = readBoolean(n); });
  format.attach<R>("render", "threads", [](const Node& n, R& r) {
    r.threads = readInteger(n, 0, RenderOptions::MAX_THREADS);
  });
  format.writeDocument.push_back([](const SceneDocument& doc, Json& j) {
    const RenderSettings d;
    Json& render = j["render"];
    if (doc.render.accel != d.accel) render["accel"] = doc.render.accel;
    if (doc.render.lightBuffers != d.lightBuffers) render["lightBuffers"] = doc.render.lightBuffers;
    if (doc.render.threads != d.threads) render["threads"] = doc.render.threads;
  });
  attachMesh(format);
  format.addGeometryType("mesh", buildMesh);
  format.writeMoreGeometries.push_back(writeMeshes);
}

}  // namespace rt::scenefile
