// Export and re-import: a document written by dumpScene reads back to the same document, bit for
// bit, whether it came from a file or was built in code (a built-in scene).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "ModelFileFixture.h"
#include "SceneCompare.h"
#include "geometries/UtahTeapot.h"
#include "lighting/CourseScenes.h"
#include "reflections/CourseScenes.h"
#include "scenefile/LitDocument.h"
#include "scenefile/ModelFile.h"
#include "scenefile/SceneFile.h"
#include "shadows/CourseScenes.h"
#include "support/TestRandom.h"

namespace rt {
namespace {

using testing::Fingerprint;
using testing::sameBits;

std::string examplePath() { return std::string(RT_SCENEFILE_DATA_DIR) + "/example.json"; }

/// A document as a built-in scene makes it: no names, no materials table.
SceneDocument documentOf(const SceneSetup<LitScene>& setup) {
  return litDocument(setup.scene, setup.camera);
}

/// A small valid document built in code, to which tests add what they exercise.
SceneDocument baseDocument() {
  SceneDocument doc = litDocument(LitScene{}, CameraSpec{});
  doc.camera.location = Point(0, 0, 10);
  doc.camera.target = Point(0, 0, 0);
  doc.camera.vpWidth = doc.camera.vpHeight = 2;
  doc.camera.vpDistance = 10;
  doc.camera.nX = doc.camera.nY = 4;
  return doc;
}

TEST(RoundTripTest, ExampleFile) {
  // EP01: a file with every kind of object: parse, dump, parse, dump gives the same text and
  // the same document.
  const SceneDocument first = loadScene(examplePath());
  const std::string dump1 = dumpScene(first);
  const SceneDocument second = parseScene(dump1, "dump1");
  EXPECT_EQ(dumpScene(second), dump1);
  EXPECT_EQ(Fingerprint(second).str(), Fingerprint(first).str());
  // A few fields compared directly, exactly.
  EXPECT_TRUE(sameBits(second.render.minK, 0.001));
  EXPECT_TRUE(sameBits(std::get<Sphere>(litScene(second).geometries[2]).radius(), 50));
  EXPECT_TRUE(sameBits(std::get<PointLight>(litScene(second).lights[1]).kL, 0.0005));
  EXPECT_TRUE(sameBits(std::get<SpotLight>(litScene(second).lights[2]).kQ, 2e-5));
  EXPECT_TRUE(sameBits(litScene(second).appearanceOf(0).material.kD.y, 0.5));
  EXPECT_TRUE(sameBits(litScene(second).ambientLight.kA().x, 0.15));
}

TEST(RoundTripTest, GeometriesThatLookAlikeShareARow) {
  // EP01: a hundred spheres of one look: one row, and no names kept
  std::string text =
      R"({"camera": {"location": [0,0,10], "target": [0,0,0], "vpDistance": 1,
          "vpSize": [1,1], "resolution": [4,4]}, "geometries": [)";
  for (int i = 0; i < 100; ++i)
    text += (i ? "," : "") + std::string(R"({"type": "sphere", "center": [)") + std::to_string(i) +
            R"(,0,0], "radius": 0.1, "emission": [80,255,230],
            "material": {"kD": 0.2, "kS": 0.33, "shininess": 10}})";
  text += "]}";
  const SceneDocument stars = parseScene(text, "stars.json");
  EXPECT_EQ(100u, litScene(stars).geometries.size());
  EXPECT_EQ(1u, litScene(stars).appearances.size());
  EXPECT_TRUE(stars.geometryNames.empty());
  // EP02: by name: the same named material and emission share a row, another emission is
  // another row, and each row remembers the name (so the export writes it by name again)
  const SceneDocument named = parseScene(R"({"camera": {"location": [0,0,10], "target": [0,0,0],
      "vpDistance": 1, "vpSize": [1,1], "resolution": [4,4]},
      "materials": {"glass": {"kT": 0.8}}, "geometries": [
      {"type": "sphere", "center": [0,0,0], "radius": 1, "material": "glass"},
      {"type": "sphere", "center": [3,0,0], "radius": 1, "material": "glass"},
      {"type": "sphere", "center": [6,0,0], "radius": 1, "material": "glass", "emission": [9,9,9]},
      {"type": "sphere", "center": [9,0,0], "radius": 1, "material": {"kT": 0.8}}]})",
                                         "named.json");
  EXPECT_EQ(litScene(named).appearanceIndex, (std::vector<std::uint32_t>{0, 0, 1, 2}));
  ASSERT_NE(materialNameOf(named, 2), nullptr);
  EXPECT_EQ(*materialNameOf(named, 2), "glass");
  EXPECT_EQ(materialNameOf(named, 3), nullptr);
  // BVA01: a material differing in the last bit of one coefficient is another row
  const std::string twoLooks = R"({"camera": {"location": [0,0,10], "target": [0,0,0],
      "vpDistance": 1, "vpSize": [1,1], "resolution": [4,4]}, "geometries": [
      {"type": "sphere", "center": [0,0,0], "radius": 1, "material": {"kD": 0.2}},
      {"type": "sphere", "center": [3,0,0], "radius": 1, "material": {"kD": 0.20000000000000004}}]})";
  EXPECT_EQ(2u, litScene(parseScene(twoLooks, "two.json")).appearances.size());
}

TEST(RoundTripTest, KeepsNamesAndMaterialReferences) {
  // EP01: geometry names and "material by name" survive; inline materials stay inline.
  const SceneDocument doc = parseScene(dumpScene(loadScene(examplePath())), "dump");
  ASSERT_EQ(litScene(doc).geometries.size(), 8u);
  ASSERT_NE(doc.geometryName(0), nullptr);
  EXPECT_EQ(*doc.geometryName(0), "floor");
  ASSERT_NE(doc.geometryName(1), nullptr);
  EXPECT_EQ(*doc.geometryName(1), "back wall");
  EXPECT_EQ(doc.geometryName(3), nullptr);
  ASSERT_NE(materialNameOf(doc, 2), nullptr);
  EXPECT_EQ(*materialNameOf(doc, 2), "glass");
  EXPECT_EQ(materialNameOf(doc, 3), nullptr);
  EXPECT_EQ(namedMaterials(doc).materials.size(), 3u);
}

TEST(RoundTripTest, AwkwardNumbers) {
  // EP01: numbers without a short decimal form, extreme magnitudes (a colour at the files'
  // largest, 10^12), negative zero and integers beyond 2^53 are written so that they read back to
  // the same bits.
  SceneDocument doc = baseDocument();
  const double third = 1.0 / 3;
  litScene(doc).add(
      Sphere(Point(0.1, -0.0, 1e-300), third), Color(0.1, 1e12, 1e-300),
      Material{Double3(third), Double3(0.1, 0.2, 0.3), Double3(0), Double3(-0.0), 7, 1.1, {}, {}});
  litScene(doc).add(Sphere(Point(9007199254740993.0, 1e22, -2.5e-8), 1e-7));
  doc.render.minK = 1e-9;
  const std::string dump1 = dumpScene(doc);
  const SceneDocument back = parseScene(dump1, "dump");
  EXPECT_EQ(Fingerprint(back).str(), Fingerprint(doc).str());
  EXPECT_EQ(dumpScene(back), dump1);
}

TEST(RoundTripTest, GridLinesAndTheirColour) {
  // EP01: grid lines in a colour of their own are written in render, and read back
  SceneDocument doc = baseDocument();
  doc.render.gridLines = 50;
  doc.render.gridColor = Color(0, 0, 255);
  const std::string text = dumpScene(doc);
  EXPECT_NE(text.find("\"gridLines\": 50, \"gridColor\": [0, 0, 255]"), std::string::npos) << text;
  const SceneDocument back = parseScene(text, "dump");
  EXPECT_EQ(back.render.gridLines, 50);
  EXPECT_EQ(back.render.gridColor, Color(0, 0, 255));
  // EP02: lines in the default colour (the course's yellow): the colour is not written
  doc.render.gridColor = Color(255, 255, 0);
  EXPECT_EQ(dumpScene(doc).find("gridColor"), std::string::npos);
  // BV01: no lines (0, the default): nothing is written
  EXPECT_EQ(dumpScene(baseDocument()).find("grid"), std::string::npos);
}

TEST(RoundTripTest, LightBuffersWrittenOnlyWhenOff) {
  // EP01: light buffers off: written in render as false, after the render settings written
  // always, and read back off
  SceneDocument doc = baseDocument();
  doc.render.lightBuffers = false;
  const std::string text = dumpScene(doc);
  EXPECT_NE(text.find("\"render\": {\"maxLevel\": 10, \"minK\": 0.001, \"lightBuffers\": false}\n"),
            std::string::npos)
      << text;
  const SceneDocument back = parseScene(text, "dump");
  EXPECT_FALSE(back.render.lightBuffers);
  EXPECT_EQ(dumpScene(back), text);
  // EP02: on, the default: nothing is written, and the file reads back on
  const std::string onText = dumpScene(baseDocument());
  EXPECT_EQ(onText.find("lightBuffers"), std::string::npos) << onText;
  EXPECT_TRUE(parseScene(onText, "dump").render.lightBuffers);
}

TEST(RoundTripTest, DirectionsComeBackExactly) {
  // EP01: a built-in scene's (1,1,1) normal is stored normalised; the export writes [1, 1, 1],
  // whose normalisation is exactly the stored normal.
  SceneDocument doc = baseDocument();
  litScene(doc).add(Plane(Point(0, 0, 0), Vector(1, 1, 1)));
  const std::string text = dumpScene(doc);
  EXPECT_NE(text.find("\"normal\": [1, 1, 1]"), std::string::npos) << text;
  EXPECT_EQ(Fingerprint(parseScene(text, "dump")).str(), Fingerprint(doc).str());

  // EP02: arbitrary directions (fixed seed): planes, tubes, cylinders, directional and spot
  // lights all come back with the same bits, though a third of unit vectors change by an ulp
  // when normalised again.
  test::TestRandom random(20240611);
  SceneDocument many = baseDocument();
  for (int i = 0; i < 300; ++i) {
    const Vector d(random.inCube(-10, 10));
    const Point p(random.inCube(-10, 10));
    litScene(many).add(Plane(p, d));
    litScene(many).add(Tube(1, Ray(p, d)));
    litScene(many).add(Cylinder(1, Ray(p, d), 2));
    litScene(many).addLight(DirectionalLight(Color(1, 1, 1), d));
    litScene(many).addLight(SpotLight(Color(1, 1, 1), p, d));
  }
  EXPECT_EQ(Fingerprint(parseScene(dumpScene(many), "dump")).str(), Fingerprint(many).str());
}

TEST(RoundTripTest, PlaneThroughThreePointsIsWrittenAsPointAndNormal) {
  // EP01: the three-point form is read into the same Plane as the point-and-normal form the
  // export writes.
  const SceneDocument doc = baseDocument();
  SceneDocument withPlane = doc;
  litScene(withPlane).add(Plane(Point(1, 2, 3), Point(-4, 0.5, 2), Point(0.3, 7, -1)));
  const std::string text = dumpScene(withPlane);
  EXPECT_EQ(text.find("\"points\""), std::string::npos);
  EXPECT_EQ(Fingerprint(parseScene(text, "dump")).str(), Fingerprint(withPlane).str());
}

TEST(RoundTripTest, EveryBuiltInCourseScene) {
  // EP01: every course scene of stages 5-7 (what `rt export` writes) reads back identical.
  for (auto scenes : {lightingScenes(), shadowScenes(), reflectionScenes()}) {
    for (const CourseScene& s : scenes) {
      SCOPED_TRACE(s.name);
      const SceneDocument doc = documentOf(s.make());
      const SceneDocument back = parseScene(dumpScene(doc), s.name);
      EXPECT_EQ(Fingerprint(back).str(), Fingerprint(doc).str());
    }
  }
}

TEST(RoundTripTest, CameraGivenByDirection) {
  // EP01: a camera given by to + up is written that way and comes back the same.
  SceneDocument doc = baseDocument();
  doc.camera.target.reset();
  doc.camera.to = Vector(0, 0, -3);
  doc.camera.up = Vector(0, 2, 0);
  const std::string text = dumpScene(doc);
  EXPECT_NE(text.find("\"to\": [0, 0, -3]"), std::string::npos) << text;
  EXPECT_EQ(Fingerprint(parseScene(text, "dump")).str(), Fingerprint(doc).str());
}

// ---- Meshes ------------------------------------------------------------------------------------

/// A mesh made in code, as a built-in scene makes one: the teapot at detail 2, turned by an
/// angle that is no multiple of 90 degrees (so that its normals are no short decimals).
std::shared_ptr<const TriangleMesh> turnedTeapot() {
  const TriangleMesh teapot = utahTeapot(2);
  const double c = std::cos(0.3), s = std::sin(0.3);
  std::vector<Point> vertices;
  std::vector<Double3> normals;
  for (const Point& p : teapot.vertices())
    vertices.emplace_back(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z() * 1.1);
  for (const Vector& n : teapot.normals())
    normals.emplace_back(c * n.x() - s * n.y(), s * n.x() + c * n.y(), n.z());
  return std::make_shared<const TriangleMesh>(std::move(vertices), teapot.triangles(),
                                              std::move(normals));
}

TEST(RoundTripTest, AMeshMadeInCodeIsWrittenInline) {
  SceneDocument doc = baseDocument();
  litScene(doc).add(Sphere(Point(0, 0, -1), 0.5));
  const std::uint32_t row = litScene(doc).addAppearance(
      Color(200, 0, 0),
      Material{Double3(0.5), Double3(0.5), Double3(0), Double3(0), 60, 1, {}, {}});
  litScene(doc).addMesh(turnedTeapot(), row);
  const std::string dump1 = dumpScene(doc);
  const SceneDocument back = parseScene(dump1, "dump");
  // ============ Equivalence Partitions Tests ==============
  // TC01: every vertex, triangle and normal comes back with the same bits (a normal written as
  // a vector whose normalisation is the stored one), and the look
  ASSERT_EQ(litScene(back).geometries.meshes().size(), 1u);
  EXPECT_EQ(Fingerprint(back).str(), Fingerprint(doc).str());
  // TC02: the mesh follows the shapes, inline; writing it again gives the same text
  EXPECT_NE(dump1.find("    {\n      \"type\": \"mesh\",\n      \"vertices\": [\n"),
            std::string::npos);
  EXPECT_EQ(dump1.find("\"file\""), std::string::npos);
  EXPECT_EQ(dumpScene(back), dump1);
}

TEST(RoundTripTest, AnInlineMeshComesBackAsItWasRead) {
  const std::string text =
      R"({"camera": {"location": [0,0,10], "target": [0,0,0], "vpDistance": 1,
          "vpSize": [1,1], "resolution": [4,4]}, "materials": {"glaze": {"kD": 0.5}},
          "geometries": [
          {"type": "mesh", "vertices": [[-0.0, 0, 0], [0.1, 0, 0], [0, 0.3, 0.7]],
           "triangles": [[0, 1, 2]], "normals": [[1, 2, 3], [0, 0, 1], [0.1, 0.2, 0.3]],
           "rotation": [10, 20, 30], "material": "glaze", "name": "shard"},
          {"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]],
           "shading": "flat", "emission": [1, 2, 3]}]})";
  const SceneDocument first = parseScene(text, "first.json");
  const std::string dump1 = dumpScene(first);
  const SceneDocument second = parseScene(dump1, "second.json");
  // ============ Equivalence Partitions Tests ==============
  // TC01: the placed vertices and the normals, the names and the named material, bit for bit
  EXPECT_EQ(Fingerprint(second).str(), Fingerprint(first).str());
  EXPECT_EQ(dumpScene(second), dump1);
  // TC02: the transform is in the vertices now, not written again
  EXPECT_EQ(dump1.find("\"rotation\""), std::string::npos);
  EXPECT_NE(dump1.find("\"name\": \"shard\""), std::string::npos);
  EXPECT_NE(dump1.find("\"material\": \"glaze\""), std::string::npos);
}

using MeshFileRoundTripTest = testing::ModelFileFixture;

TEST_F(MeshFileRoundTripTest, AModelFilesEntryIsWrittenAgainWithItsPathMoved) {
  write("a/models/two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  write("a/models/two.obj",
        "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\n"
        "usemtl red\nf 1 2 3\nusemtl blue\nf 1 2 4\nf 1 3 4 5\n");
  const std::string scene =
      write("a/scene.json",
            R"({"camera": {"location": [0,0,10], "target": [0,0,0], "vpDistance": 1,
          "vpSize": [1,1], "resolution": [4,4]}, "materials": {"glaze": {"kD": 0.5}},
          "geometries": [
          {"type": "mesh", "file": "models/two.obj", "scale": [1, 2, 3], "rotation": [0, 45, 0],
           "translation": [0.1, 0, 0], "shading": "smooth", "materials": {"blue": "glaze"},
           "emission": [5, 5, 5], "material": {"kR": 0.25}, "name": "pair"},
          {"type": "mesh", "file": "models/two.obj", "shading": "flat",
           "materials": {"red": {"kT": 0.5}, "blue": "glaze"}}]})");
  const SceneDocument first = loadScene(scene);
  // ============ Equivalence Partitions Tests ==============
  // TC01: written for a file in another folder, the path is relative to that folder; the
  // transform, the shading and the groups' materials are kept, and the entry's own material
  // only where a group uses it
  const std::string dump = dumpScene(first, dir_ / "b");
  const nlohmann::json j = nlohmann::json::parse(dump);
  ASSERT_EQ(j["geometries"].size(), 2u);
  const nlohmann::json& pair = j["geometries"][0];
  EXPECT_EQ(pair["file"], "../a/models/two.obj");
  EXPECT_EQ(pair["scale"], nlohmann::json::parse("[1, 2, 3]"));
  EXPECT_EQ(pair["rotation"], nlohmann::json::parse("[0, 45, 0]"));
  EXPECT_EQ(pair["translation"], nlohmann::json::parse("[0.1, 0, 0]"));
  EXPECT_FALSE(pair.contains("shading"));
  EXPECT_EQ(pair["materials"], nlohmann::json::parse(R"({"blue": "glaze"})"));
  EXPECT_EQ(pair["material"], nlohmann::json::parse(R"({"kR": 0.25})"));
  EXPECT_EQ(pair["name"], "pair");
  const nlohmann::json& flat = j["geometries"][1];
  EXPECT_EQ(flat["shading"], "flat");
  EXPECT_EQ(flat["materials"], nlohmann::json::parse(R"({"red": {"kT": 0.5}, "blue": "glaze"})"));
  EXPECT_FALSE(flat.contains("material"));
  // TC02: read from there, the same meshes, bit for bit (the model read again)
  const SceneDocument second = loadScene(write("b/scene.json", dump));
  EXPECT_EQ(litScene(second).geometries.meshes().size(), 4u);
  EXPECT_EQ(Fingerprint(second).str(), Fingerprint(first).str());
  EXPECT_EQ(dumpScene(second, dir_ / "b"), dump);
  // TC03: written for the scene's own folder, the path as the file gave it
  EXPECT_NE(dumpScene(first, dir_ / "a").find("\"file\": \"models/two.obj\""), std::string::npos);
  // =============== Boundary Values Tests ==================
  // TC11: an absolute path is written as it was given, wherever the export goes
  const std::string absolute = (dir_ / "a/models/two.obj").string();
  const SceneDocument fixed = parseScene(
      R"({"camera": {"location": [0,0,10], "target": [0,0,0], "vpDistance": 1,
          "vpSize": [1,1], "resolution": [4,4]}, "geometries": [
          {"type": "mesh", "file": ")" +
          absolute + R"("}]})",
      "anywhere.json");
  EXPECT_NE(dumpScene(fixed, dir_ / "b").find("\"file\": \"" + absolute + "\""), std::string::npos);
}

TEST(ToJsonTest, RejectsDocumentsThatCannotBeWritten) {
  // EP01: a camera with neither target nor direction.
  SceneDocument noDirection = baseDocument();
  noDirection.camera.target.reset();
  EXPECT_THROW((void)toJson(noDirection), std::logic_error);
  // EP02: a geometry naming a material the document does not have.
  SceneDocument unknownName = baseDocument();
  litScene(unknownName).add(Sphere(Point(0, 0, 0), 1));
  namedMaterials(unknownName).rowNames.push_back("glass");
  EXPECT_THROW((void)toJson(unknownName), std::logic_error);
  // EP03: a geometry naming a material but carrying another one.
  SceneDocument mismatch = unknownName;
  namedMaterials(mismatch).materials["glass"] =
      Material{Double3(0), Double3(0), Double3(0.5), Double3(0), 0, 1.5, {}, {}};
  EXPECT_THROW((void)toJson(mismatch), std::logic_error);
  // EP04: a name for a geometry that does not exist.
  SceneDocument tooManyNames = baseDocument();
  tooManyNames.geometryNames.emplace(0, "ghost");
  EXPECT_THROW((void)toJson(tooManyNames), std::logic_error);
  // EP05: a shape without a row of the appearance table.
  SceneDocument noRow = baseDocument();
  litScene(noRow).geometries.add(Sphere(Point(0, 0, 0), 1));
  EXPECT_THROW((void)toJson(noRow), std::logic_error);
}

TEST(DumpSceneTest, Layout) {
  // EP01: two-space indentation, short values on one line, a final newline, the documented key
  // order.
  SceneDocument doc = baseDocument();
  litScene(doc).add(Sphere(Point(0, 0, -1), 0.5));
  doc.render.tracer = "whitted";  // (a document without one writes no tracer key)
  EXPECT_EQ(dumpScene(doc),
            "{\n"
            "  \"camera\": {\n"
            "    \"location\": [0, 0, 10],\n"
            "    \"target\": [0, 0, 0],\n"
            "    \"up\": [0, 1, 0],\n"
            "    \"vpDistance\": 10,\n"
            "    \"vpSize\": [2, 2],\n"
            "    \"resolution\": [4, 4]\n"
            "  },\n"
            "  \"background\": [0, 0, 0],\n"
            "  \"ambient\": {\"color\": [0, 0, 0], \"kA\": 1},\n"
            "  \"lights\": [],\n"
            "  \"geometries\": [\n"
            "    {\"type\": \"sphere\", \"center\": [0, 0, -1], \"radius\": 0.5}\n"
            "  ],\n"
            "  \"render\": {\"tracer\": \"whitted\", \"maxLevel\": 10, \"minK\": 0.001}\n"
            "}\n");
}

}  // namespace
}  // namespace rt
