// The scene file's `mesh` geometry (mini 2's part of the format): inline meshes read exactly,
// placed by the transform, shaded smooth or flat; model files found beside the scene file, their
// material groups given materials; the refusals and warnings with their exact messages. The
// bad inline values are in BadInputTests.cpp; here, what needs files (written by each test into
// a fresh temporary directory) or a look at the document.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ModelFileFixture.h"
#include "scenefile/LitDocument.h"
#include "scenefile/MeshDocument.h"
#include "scenefile/ModelFile.h"
#include "scenefile/SceneFile.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

/// Lines 1-2 of every scene of this file; the geometries follow from line 3.
const std::string kHead =
    "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], \"vpDistance\": 10, "
    "\"vpSize\": [4, 4], \"resolution\": [8, 8]},\n"
    " \"materials\": {\"glaze\": {\"kD\": 0.5, \"kS\": 0.5, \"shininess\": 60}},\n";

/// A scene file's text with the given geometries (one a line from line 4).
std::string sceneWith(const std::vector<std::string>& geometries) {
  std::string text = kHead + " \"geometries\": [\n";
  for (std::size_t i = 0; i < geometries.size(); ++i)
    text += "  " + geometries[i] + (i + 1 < geometries.size() ? ",\n" : "\n");
  return text + "]}\n";
}

/// A unit square's inline mesh, two triangles, with extra keys.
std::string square(const std::string& extra = "") {
  return R"({"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], )"
         R"("triangles": [[0, 1, 2], [0, 2, 3]])" +
         (extra.empty() ? "" : ", " + extra) + "}";
}

const TriangleMesh& meshOf(const SceneDocument& doc, std::uint32_t k) {
  return *litScene(doc).geometries.meshes()[k].mesh;
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

/// The message of the SceneError that reading text (as dir/name) gives; "(no error)" when none.
std::string errorOf(const std::string& text, const std::string& source = "x.json") {
  try {
    (void)parseScene(text, source);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// ---- Inline meshes ----------------------------------------------------------------------------

TEST(MeshEntryTest, AnInlineMeshIsReadExactly) {
  const SceneDocument doc = parseScene(
      sceneWith({square(R"("normals": [[0, 0, 2], [0, 0, 1], [0, 1, 1], [0, 0, 1]], )"
                        R"("emission": [9, 0, 0], "material": "glaze", "name": "tile")"),
                 R"({"type": "sphere", "center": [0, 0, -5], "radius": 1, "emission": [9, 0, 0],)"
                 R"( "material": "glaze", "name": "ball"})"}),
      "x.json");
  const LitScene& scene = litScene(doc);
  // ============ Equivalence Partitions Tests ==============
  // TC01: one mesh of the given vertices and triangles; the shapes are the sphere only
  ASSERT_EQ(scene.geometries.meshes().size(), 1u);
  ASSERT_EQ(scene.geometries.size(), 1u);
  EXPECT_EQ(scene.geometries.primitiveCount(), 3u);
  const TriangleMesh& m = meshOf(doc, 0);
  ASSERT_EQ(m.vertexCount(), 4u);
  EXPECT_EQ(m.vertices()[2].xyz().x, 1.0);
  EXPECT_EQ(m.vertices()[2].xyz().y, 1.0);
  EXPECT_EQ(m.triangles(), (std::vector<TriangleMesh::Indices>{{0, 1, 2}, {0, 2, 3}}));
  // TC02: the normals normalised (smooth, the default)
  ASSERT_TRUE(m.hasNormals());
  EXPECT_EQ(m.normals()[0].xyz().z, 1.0);
  EXPECT_EQ(m.normals()[2].xyz().y, 1 / std::sqrt(2.0));
  // TC03: the mesh and the sphere look the same, so they share one row of the table, which
  // remembers the material's name
  EXPECT_EQ(scene.meshAppearance, std::vector<std::uint32_t>{scene.appearanceIndex[0]});
  ASSERT_NE(materialNameOfRow(doc, scene.meshAppearance[0]), nullptr);
  EXPECT_EQ(*materialNameOfRow(doc, scene.meshAppearance[0]), "glaze");
  // TC04: the mesh's name is its entry's; the shape after it is shape 0, with its own name
  ASSERT_NE(meshName(doc, 0), nullptr);
  EXPECT_EQ(*meshName(doc, 0), "tile");
  ASSERT_NE(doc.geometryName(0), nullptr);
  EXPECT_EQ(*doc.geometryName(0), "ball");
  EXPECT_EQ(meshEntries(doc).entries.size(), 1u);
  EXPECT_FALSE(meshEntries(doc).entries[0].model.has_value());
  EXPECT_EQ(doc.warnings, std::vector<std::string>{});
}

TEST(MeshEntryTest, TheTransformScalesThenRotatesThenTranslates) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: (1,0,0) scaled by (2,1,1) is (2,0,0), turned 90 degrees about z (0,2,0), moved by
  // (1,2,3) (1,4,3); exactly, since a quarter turn's sine and cosine are exact
  const SceneDocument doc = parseScene(
      sceneWith(
          {square(R"("normals": [[1, 0, 0], [1, 0, 0], [1, 0, 0], [1, 0, 0]], )"
                  R"("scale": [2, 1, 1], "rotation": [0, 0, 90], "translation": [1, 2, 3])")}),
      "x.json");
  const TriangleMesh& m = meshOf(doc, 0);
  const Double3 p = m.vertices()[1].xyz();
  EXPECT_EQ(bits(p.x), bits(1.0));
  EXPECT_EQ(bits(p.y), bits(4.0));
  EXPECT_EQ(bits(p.z), bits(3.0));
  // TC02: the normal (1,0,0) is turned to (0,1,0) (the scale along it changes only its length)
  const Double3 n = m.normals()[1].xyz();
  EXPECT_EQ(n.x, 0.0);
  EXPECT_EQ(bits(n.y), bits(1.0));
  EXPECT_EQ(n.z, 0.0);
  // TC03: one number scales every axis
  const SceneDocument scaled = parseScene(sceneWith({square(R"("scale": 3)")}), "x.json");
  EXPECT_EQ(meshOf(scaled, 0).vertices()[2].xyz().y, 3.0);
  EXPECT_EQ(meshOf(scaled, 0).vertices()[2].xyz().z, 0.0);
  // =============== Boundary Values Tests ==================
  // TC11: the identity (every default) leaves the coordinates' bits alone: -0 stays -0
  const SceneDocument negativeZero =
      parseScene(sceneWith({R"({"type": "mesh", "vertices": [[-0.0, 0, 0], [1, 0, 0], [0, 1, 0]], )"
                            R"("triangles": [[0, 1, 2]]})"}),
                 "x.json");
  EXPECT_EQ(bits(meshOf(negativeZero, 0).vertices()[0].xyz().x), bits(-0.0));
}

TEST(MeshEntryTest, FlatShadingDropsTheNormals) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: "flat" with normals given: none kept (each triangle shows its own normal)
  const SceneDocument flat =
      parseScene(sceneWith({square(R"("normals": [[0, 0, 1], [0, 0, 1], [0, 0, 1], [0, 0, 1]], )"
                                   R"("shading": "flat")")}),
                 "x.json");
  EXPECT_FALSE(meshOf(flat, 0).hasNormals());
  // TC02: smooth without normals: flat too, as an inline mesh has no normals to interpolate
  EXPECT_FALSE(meshOf(parseScene(sceneWith({square()}), "x.json"), 0).hasNormals());
}

TEST(MeshEntryTest, TrianglesOfZeroAreaAreDroppedWithAWarning) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: one of three triangles has its corners on a line: dropped, counted at 'triangles'
  const SceneDocument doc = parseScene(
      sceneWith({R"({"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [2, 0, 0]], )"
                 R"("triangles": [[0, 1, 2], [0, 1, 3], [0, 2, 1]]})"}),
      "x.json");
  EXPECT_EQ(meshOf(doc, 0).triangleCount(), 2u);
  EXPECT_EQ(doc.warnings,
            std::vector<std::string>{
                "x.json:4:91: geometries[0].triangles: 1 triangle of zero area dropped (of 3)"});
}

TEST(MeshEntryTest, AShapeAfterAMeshIsWarnedAboutAtItsElement) {
  // The glass square of two triangles wound against each other (stage 7's warning), after a
  // mesh: the triangles are shapes 0 and 1 but elements 1 and 2 of "geometries".
  const std::string glass = R"("material": {"kT": 0.9, "ior": 1.5})";
  const SceneDocument doc = parseScene(
      sceneWith(
          {square(),
           R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], )" + glass + "}",
           R"({"type": "triangle", "vertices": [[1, 0, 0], [0, 1, 0], [1, 1, 0]], )" + glass +
               "}"}),
      "x.json");
  // ============ Equivalence Partitions Tests ==============
  // TC01: the warning is at the second triangle's line (5) and names the elements
  ASSERT_EQ(doc.warnings.size(), 1u);
  EXPECT_EQ(doc.warnings[0].rfind("x.json:6:3: geometries[2]: mixed winding in a glass surface "
                                  "of 2 faces (an inline material, ior 1.5): geometries[2] is "
                                  "wound against geometries[1] ",
                                  0),
            0u)
      << doc.warnings[0];
}

// ---- Model files ------------------------------------------------------------------------------

class MeshFileTest : public testing::ModelFileFixture {
 protected:
  /// The error that loading dir/scene.json with the geometries gives; "(no error)" when none.
  std::string loadError(const std::vector<std::string>& geometries) const {
    const std::string path = write("scene.json", sceneWith(geometries));
    try {
      (void)loadScene(path);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

const std::string kTwoGroups =
    "mtllib two.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "usemtl red\nf 1 2 3\n"
    "usemtl blue\nf 1 2 4\nf 1 3 4\n";

TEST_F(MeshFileTest, AModelFileIsFoundBesideTheSceneFile) {
  write("models/two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  write("models/two.obj", kTwoGroups);
  const std::string path =
      write("scene.json",
            sceneWith({R"({"type": "mesh", "file": "models/two.obj", "shading": "flat", )"
                       R"("translation": [0, 0, 5], "material": "glaze", "name": "pair"})"}));
  // The current directory is elsewhere: the path is the scene file's folder's.
  const SceneDocument doc = loadScene(path);
  const LitScene& scene = litScene(doc);
  // ============ Equivalence Partitions Tests ==============
  // TC01: one mesh per material group, in the file's order, moved by the translation
  ASSERT_EQ(scene.geometries.meshes().size(), 2u);
  EXPECT_EQ(meshOf(doc, 0).triangleCount(), 1u);
  EXPECT_EQ(meshOf(doc, 1).triangleCount(), 2u);
  EXPECT_EQ(meshOf(doc, 1).vertices()[0].xyz().z, 5.0);
  EXPECT_FALSE(meshOf(doc, 0).hasNormals());
  // TC02: both groups have the entry's look (one row), and the entry's name
  EXPECT_EQ(scene.meshAppearance[0], scene.meshAppearance[1]);
  EXPECT_EQ(*materialNameOfRow(doc, scene.meshAppearance[0]), "glaze");
  EXPECT_EQ(*meshName(doc, 1), "pair");
  // TC03: the document remembers the entry: the file as given, where it was read, the groups
  ASSERT_EQ(meshEntries(doc).entries.size(), 1u);
  const MeshEntry& e = meshEntries(doc).entries[0];
  EXPECT_EQ(e.firstMesh, 0u);
  EXPECT_EQ(e.meshCount, 2u);
  ASSERT_TRUE(e.model.has_value());
  EXPECT_EQ(e.model->file, "models/two.obj");
  EXPECT_EQ(e.model->absolute, fs::absolute(dir_ / "models/two.obj").lexically_normal());
  EXPECT_FALSE(e.model->smooth);
  EXPECT_EQ(e.model->groups, (std::vector<std::string>{"red", "blue"}));
  EXPECT_EQ(e.model->mapped, (std::vector<bool>{false, false}));
  EXPECT_EQ(e.model->transform.translation.z, 5.0);
}

TEST_F(MeshFileTest, MaterialGroupsTakeTheMaterialsGiven) {
  write("models/two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  write("models/two.obj", kTwoGroups);
  const std::string path =
      write("scene.json",
            sceneWith({R"({"type": "mesh", "file": "models/two.obj", "emission": [5, 0, 0], )"
                       R"("materials": {"blue": "glaze"}, "material": {"kR": 0.5}})"}));
  const SceneDocument doc = loadScene(path);
  const LitScene& scene = litScene(doc);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the group given a material has it (by name); the other has the entry's material;
  // both the entry's emission
  const Appearance& red = scene.appearances[scene.meshAppearance[0]];
  const Appearance& blue = scene.appearances[scene.meshAppearance[1]];
  EXPECT_EQ(red.material.kR, Double3(0.5));
  EXPECT_EQ(materialNameOfRow(doc, scene.meshAppearance[0]), nullptr);
  EXPECT_EQ(blue.material.kS, Double3(0.5));
  EXPECT_EQ(*materialNameOfRow(doc, scene.meshAppearance[1]), "glaze");
  EXPECT_EQ(red.emission.rgb().x, 5.0);
  EXPECT_EQ(blue.emission.rgb().x, 5.0);
  EXPECT_EQ(meshEntries(doc).entries[0].model->mapped, (std::vector<bool>{false, true}));
  // TC02: a group's material may be a material object too
  write("scene.json", sceneWith({R"({"type": "mesh", "file": "models/two.obj", )"
                                 R"("materials": {"red": {"kT": 0.25}, "blue": "glaze"}})"}));
  const SceneDocument both = loadScene(path);
  EXPECT_EQ(litScene(both).appearances[litScene(both).meshAppearance[0]].material.kT,
            Double3(0.25));
  // TC03: every group given its material: the entry's own makes no row of the table
  EXPECT_EQ(litScene(both).appearances.size(), 2u);
}

TEST_F(MeshFileTest, AnUnknownGroupIsRefusedNamingTheKnownOnes) {
  write("models/two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  write("models/two.obj", kTwoGroups);
  const std::string model = (dir_ / "models/two.obj").string();
  // ============ Equivalence Partitions Tests ==============
  // TC01: a misspelt group: the nearest named, the groups listed, at the key
  EXPECT_EQ(
      loadError({R"({"type": "mesh", "file": "models/two.obj", "materials": {"bleu": "glaze"}})"}),
      (dir_ / "scene.json").string() +
          ":4:60: geometries[0].materials.bleu: no material group 'bleu' in " + model +
          "; did you mean 'blue'? (its groups: red, blue)");
  // TC02: a group's value that is no material: the material's own message
  EXPECT_EQ(
      loadError({R"({"type": "mesh", "file": "models/two.obj", "materials": {"red": "glas"}})"}),
      (dir_ / "scene.json").string() +
          ":4:67: geometries[0].materials.red: expected the name of a "
          "material in \"materials\" (glaze), got \"glas\"");
  // TC03: a model without named groups
  write("models/one.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(
      loadError({R"({"type": "mesh", "file": "models/one.obj", "materials": {"red": "glaze"}})"}),
      (dir_ / "scene.json").string() +
          ":4:60: geometries[0].materials.red: no material group 'red' in " +
          (dir_ / "models/one.obj").string() + " (it names none)");
}

TEST_F(MeshFileTest, BadModelFilesAreRefusedNamingSceneEntryAndModel) {
  const std::string scene = (dir_ / "scene.json").string();
  const std::string models = (dir_ / "models").string();
  // ============ Equivalence Partitions Tests ==============
  // TC01: a missing model file: the system's reason, at the entry's 'file'
  EXPECT_EQ(loadError({R"({"type": "mesh", "file": "models/none.obj"})"}),
            scene + ":4:28: geometries[0].file: " + models +
                "/none.obj: cannot read: No such file or directory");
  // TC02: a file Assimp cannot parse: its message
  write("models/range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  EXPECT_EQ(loadError({R"({"type": "mesh", "file": "models/range.obj"})"}),
            scene + ":4:28: geometries[0].file: " + models +
                "/range.obj: OBJ: vertex index out of range");
  // TC03: a model without triangles
  write("models/lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\n");
  EXPECT_EQ(loadError({R"({"type": "mesh", "file": "models/lines.obj"})"}),
            scene + ":4:28: geometries[0].file: " + models +
                "/lines.obj: the model has no triangles (0 points and 1 lines ignored)");
  // TC04: coordinates the scale makes infinite: the mesh's message
  write("models/far.obj", "v 0 0 0\nv 1e30 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(loadError({R"({"type": "mesh", "file": "models/far.obj", "scale": 1e300})"})
                .rfind(scene + ":4:28: geometries[0].file: " + models +
                           "/far.obj: TriangleMesh: vertices[1] must be finite",
                       0),
            0u);
  // TC05: a directory, and a device, are no model files
  EXPECT_EQ(loadError({R"({"type": "mesh", "file": "models"})"}),
            scene + ":4:28: geometries[0].file: " + models + ": cannot read: it is a directory");
  EXPECT_EQ(loadError({R"({"type": "mesh", "file": "/dev/zero"})"}),
            scene + ":4:28: geometries[0].file: /dev/zero: cannot read: it is not a regular file");
}

TEST_F(MeshFileTest, DroppedTrianglesAndIgnoredLinesAreWarnedAbout) {
  write("models/mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nl 1 3\n");
  const SceneDocument doc = loadScene(
      write("scene.json", sceneWith({R"({"type": "mesh", "file": "models/mixed.obj"})"})));
  // ============ Equivalence Partitions Tests ==============
  // TC01: the zero-area triangle dropped and the line ignored, in one warning at 'file'
  EXPECT_EQ(meshOf(doc, 0).triangleCount(), 1u);
  EXPECT_EQ(doc.warnings, std::vector<std::string>{
                              (dir_ / "scene.json").string() +
                              ":4:28: geometries[0].file: " + (dir_ / "models/mixed.obj").string() +
                              ": 1 triangle of zero area dropped, 1 line ignored (a mesh is "
                              "its triangles)"});
}

TEST(MeshWithoutAssimpTest, AModelFileSaysHowToGetAssimp) {
  if (modelFilesSupported()) GTEST_SKIP() << "this build reads model files";
  // TC01: a file mesh names what to install; an inline mesh is read all the same
  EXPECT_EQ(errorOf(sceneWith({R"({"type": "mesh", "file": "m.obj"})"})),
            "x.json:4:28: geometries[0].file: m.obj: reading model files needs Assimp: install "
            "libassimp-dev (scripts/deps.sh installs it)");
  EXPECT_EQ(errorOf(sceneWith({square()})), "(no error)");
}

}  // namespace
}  // namespace rt
