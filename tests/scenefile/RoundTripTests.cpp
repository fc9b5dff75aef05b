// Export and re-import: a document written by dumpScene reads back to the same document, bit for
// bit, whether it came from a file or was built in code (a built-in scene).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "SceneCompare.h"
#include "lighting/CourseScenes.h"
#include "reflections/CourseScenes.h"
#include "scenefile/LitDocument.h"
#include "scenefile/SceneFile.h"
#include "shadows/CourseScenes.h"

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
  // EP01: numbers without a short decimal form, extreme magnitudes, negative zero and integers
  // beyond 2^53 are written so that they read back to the same bits.
  SceneDocument doc = baseDocument();
  const double third = 1.0 / 3;
  litScene(doc).add(
      Sphere(Point(0.1, -0.0, 1e-300), third), Color(0.1, 1e300, 0),
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
  std::mt19937_64 random(20240611);
  std::uniform_real_distribution<double> coordinate(-10, 10);
  SceneDocument many = baseDocument();
  for (int i = 0; i < 300; ++i) {
    const Vector d(coordinate(random), coordinate(random), coordinate(random));
    const Point p(coordinate(random), coordinate(random), coordinate(random));
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
