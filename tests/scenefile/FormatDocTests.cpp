// The documented format: the complete example of docs/scene-format.md loads, and every key of
// the loader's tables is documented with its default.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "scenefile/LitDocument.h"
#include "scenefile/SceneFile.h"

namespace rt {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << "cannot open " << path;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string EXAMPLE = std::string(RT_SCENEFILE_DATA_DIR) + "/example.json";
const std::string FORMAT_DOC = std::string(RT_SOURCE_DIR) + "/docs/scene-format.md";

TEST(ExampleSceneTest, Loads) {
  // EP01: the complete example: every object type, read with the values it gives.
  const SceneDocument doc = loadScene(EXAMPLE);
  EXPECT_EQ(litScene(doc).name, "example");
  EXPECT_EQ(litScene(doc).lights.size(), 3u);
  EXPECT_EQ(namedMaterials(doc).materials.size(), 3u);
  ASSERT_EQ(litScene(doc).geometries.size(), 8u);
  EXPECT_TRUE(std::holds_alternative<Plane>(litScene(doc).geometries[0]));
  EXPECT_TRUE(std::holds_alternative<Plane>(litScene(doc).geometries[1]));
  EXPECT_TRUE(std::holds_alternative<Sphere>(litScene(doc).geometries[2]));
  EXPECT_TRUE(std::holds_alternative<Triangle>(litScene(doc).geometries[4]));
  EXPECT_TRUE(std::holds_alternative<Polygon>(litScene(doc).geometries[5]));
  EXPECT_TRUE(std::holds_alternative<Tube>(litScene(doc).geometries[6]));
  EXPECT_TRUE(std::holds_alternative<Cylinder>(litScene(doc).geometries[7]));
  EXPECT_EQ(litScene(doc).appearances[2].material.ior, 1.5);
  EXPECT_EQ(litScene(doc).appearances[2].material.kT, Double3(0.6));
  EXPECT_EQ(doc.camera.nX, 500);
  EXPECT_EQ(doc.render.tracer, "whitted");
}

TEST(ExampleSceneTest, IsTheDocumentedExample) {
  // EP01: docs/scene-format.md shows exactly tests/scenefile/data/example.json.
  const std::string doc = readFile(FORMAT_DOC);
  const std::string example = readFile(EXAMPLE);
  EXPECT_NE(doc.find("```json\n" + example + "```"), std::string::npos)
      << "the example in docs/scene-format.md differs from " << EXAMPLE;
}

TEST(FormatDocTest, EveryKeyIsDocumentedWithItsDefault) {
  // EP01: every key of the format has a row "| `key` | ... |" in the doc that states "required"
  // or its default, and the stage that gives it a meaning (its label: stage05, mini1).
  const std::string doc = readFile(FORMAT_DOC);
  std::vector<std::string> rows;
  std::istringstream lines(doc);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("| `", 0) == 0) rows.push_back(line);
  for (const SceneKeyInfo& k : sceneFormatKeys()) {
    SCOPED_TRACE(k.object + "." + k.key);
    const std::string stated = k.required ? "required" : "`" + k.defaultText + "`";
    const std::string stage = "| " + k.stage.substr(0, k.stage.find('_')) + " |";
    bool found = false;
    for (const std::string& row : rows)
      found =
          found || (row.rfind("| `" + k.key + "` |", 0) == 0 &&
                    row.find(stated) != std::string::npos && row.find(stage) != std::string::npos);
    EXPECT_TRUE(found) << "no row for `" << k.key << "` stating " << stated << " and " << stage;
  }
}

}  // namespace
}  // namespace rt
