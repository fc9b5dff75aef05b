// The reader's warning about glass shapes whose faces are wound both ways (the format's stage-7
// part): refraction needs outward normals, and a polygon's normal follows its winding. Each case
// is a file whose geometries sit one per line from line 5, at column 5.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "scenefile/SceneFile.h"

namespace rt {
namespace {

using Points = std::vector<std::array<double, 3>>;

struct Face {
  Face(Points v, std::string m = "\"glass\"", std::string n = "")
      : vertices(std::move(v)), material(std::move(m)), name(std::move(n)) {}
  Points vertices;
  std::string material;  ///< a material's name in quotes, or a material object
  std::string name;
};

std::string number(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

/// A scene file of faces (triangles for three vertices, polygons otherwise), one per line from
/// line 5, column 5, with the materials given.
std::string sceneText(const std::vector<Face>& faces,
                      const std::string& materials = R"("glass": {"kT": 0.9, "ior": 1.5})") {
  std::string text =
      "{\n"
      "  \"camera\": {\"location\": [3, 4, 5], \"target\": [0, 0, 0], \"vpDistance\": 10, "
      "\"vpSize\": [4, 4], \"resolution\": [8, 8]},\n"
      "  \"materials\": {" +
      materials +
      "},\n"
      "  \"geometries\": [\n";
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Face& f = faces[i];
    text += std::string("    {\"type\": \"") + (f.vertices.size() == 3 ? "triangle" : "polygon") +
            "\", \"vertices\": [";
    for (std::size_t k = 0; k < f.vertices.size(); ++k) {
      const auto& v = f.vertices[k];
      text += (k ? ", [" : "[") + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) + "]";
    }
    text += "], \"material\": " + f.material;
    if (!f.name.empty()) text += ", \"name\": \"" + f.name + "\"";
    text += i + 1 < faces.size() ? "},\n" : "}\n";
  }
  return text + "  ]\n}\n";
}

std::vector<std::string> warningsOf(
    const std::vector<Face>& faces,
    const std::string& materials = R"("glass": {"kT": 0.9, "ior": 1.5})") {
  return parseScene(sceneText(faces, materials), "glass.json").warnings;
}

Face reversed(Face f) {
  std::reverse(f.vertices.begin(), f.vertices.end());
  return f;
}

/// The unit cube's six faces, each wound counter-clockwise seen from outside (normal outwards):
/// bottom, top, front (y = 0), back, left (x = 0), right.
std::vector<Face> cube() {
  return {{{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, "\"glass\"", "bottom"},
          {{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, "\"glass\"", "top"},
          {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}},
          {{{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}},
          {{{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}},
          {{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}}};
}

/// The octahedron |x| + |y| + |z| = 1: eight triangles, wound outwards, in the order of the
/// signs (x, y, z) = (+,+,+), (+,+,-), (+,-,+), ... (-,-,-).
std::vector<Face> octahedron() {
  std::vector<Face> faces;
  for (int i = 0; i < 8; ++i) {
    const double sx = i & 4 ? -1 : 1, sy = i & 2 ? -1 : 1, sz = i & 1 ? -1 : 1;
    Face f{{{sx, 0, 0}, {0, sy, 0}, {0, 0, sz}}};
    // (x, y, z) is counter-clockwise from outside when sx·sy·sz > 0
    if (sx * sy * sz < 0) std::swap(f.vertices[1], f.vertices[2]);
    faces.push_back(f);
  }
  return faces;
}

/// The warning about a closed glass shape of n faces, at the line of geometry `first`:
/// "GEOMETRIES point inwards, those of ... outwards" is `normals`, `those` what to reverse.
std::string closedShapeWarning(int first, int n, const std::string& normals,
                               const std::string& those) {
  return "glass.json:" + std::to_string(5 + first) + ":5: geometries[" + std::to_string(first) +
         "]: mixed winding in a closed glass shape of " + std::to_string(n) +
         " faces (material 'glass', ior 1.5): " + normals +
         " (an edge shared by two faces runs the same way in both); refraction needs outward "
         "normals: reverse the order of the vertices of " +
         those;
}

/// The warning about an open surface of two faces, the second wound against the first.
std::string openSurfaceWarning(const std::string& material) {
  return "glass.json:6:5: geometries[1]: mixed winding in a glass surface of 2 faces (" + material +
         "): geometries[1] is wound against geometries[0] (an edge shared by two faces runs the "
         "same way in both); refraction needs outward normals: reverse the order of the "
         "vertices of one side";
}

TEST(WindingWarningTest, closedShapes) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a glass cube wound outwards: no warning
  EXPECT_EQ(warningsOf(cube()), std::vector<std::string>{});
  // TC02: its top reversed: one warning, at the top's place, naming it and the others
  std::vector<Face> faces = cube();
  faces[1] = reversed(faces[1]);
  EXPECT_EQ(warningsOf(faces),
            std::vector<std::string>{closedShapeWarning(
                1, 6,
                "the normal of geometries[1] ('top') points inwards, those of geometries[0] "
                "('bottom'), geometries[2], geometries[3], geometries[4], geometries[5] outwards",
                "that face")});
  // TC03: four of its faces reversed: the two left outwards are the ones to keep (the volume
  // decides, not the count)
  faces = cube();
  for (int i : {0, 1, 2, 3}) faces[i] = reversed(faces[i]);
  EXPECT_EQ(warningsOf(faces),
            std::vector<std::string>{closedShapeWarning(
                0, 6,
                "the normals of geometries[0] ('bottom'), geometries[1] ('top'), geometries[2], "
                "geometries[3] point inwards, those of geometries[4], geometries[5] outwards",
                "those faces")});
  // TC04: every face wound inwards: consistent, so no warning (only mixed winding is reported)
  faces = cube();
  for (Face& f : faces) f = reversed(f);
  EXPECT_EQ(warningsOf(faces), std::vector<std::string>{});
  // TC05: triangles: an octahedron with its fourth face reversed
  faces = octahedron();
  EXPECT_EQ(warningsOf(faces), std::vector<std::string>{});
  faces[3] = reversed(faces[3]);
  // =============== Boundary Values Tests ==================
  // TC11: seven faces to list: six, then "and 1 more"
  EXPECT_EQ(warningsOf(faces),
            std::vector<std::string>{closedShapeWarning(
                3, 8,
                "the normal of geometries[3] points inwards, those of geometries[0], "
                "geometries[1], geometries[2], geometries[4], geometries[5], geometries[6] and 1 "
                "more outwards",
                "that face")});
}

TEST(WindingWarningTest, openSurfacesAndOtherMaterials) {
  // A square of two triangles sharing the edge (1,0,0)-(0,1,0).
  const Face lower{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const Face upper{{{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  // ============ Equivalence Partitions Tests ==============
  // TC01: wound the same way: no warning
  EXPECT_EQ(warningsOf({lower, upper}), std::vector<std::string>{});
  // TC02: wound both ways: an open surface, the second face named against the first
  EXPECT_EQ(warningsOf({lower, reversed(upper)}),
            std::vector<std::string>{openSurfaceWarning("material 'glass', ior 1.5")});
  // TC03: an inline material is said so
  Face a = lower, b = reversed(upper);
  a.material = b.material = R"({"kT": 0.5, "ior": 1.33})";
  EXPECT_EQ(warningsOf({a, b}),
            std::vector<std::string>{openSurfaceWarning("an inline material, ior 1.33")});
  // TC04: no refraction: ior 1 (the course's straight-through glass), or no transparency
  std::vector<Face> faces = cube();
  faces[1] = reversed(faces[1]);
  EXPECT_EQ(warningsOf(faces, R"("glass": {"kT": 0.9, "ior": 1})"), std::vector<std::string>{});
  EXPECT_EQ(warningsOf(faces, R"("glass": {"kD": 0.9, "ior": 1.5})"), std::vector<std::string>{});
  // TC05: the reversed face is of another material: not a face of the glass shape, and the
  // five glass faces left are an open surface wound one way
  faces[1].material = R"({"kT": 0.9, "ior": 1.5, "kD": 0.1})";
  EXPECT_EQ(warningsOf(faces), std::vector<std::string>{});
  // TC06: spheres and planes are not faces; a document made in code has no warnings
  EXPECT_EQ(parseScene(R"({"camera": {"location": [0, 0, 9], "target": [0, 0, 0],
      "vpDistance": 1, "vpSize": [1, 1], "resolution": [2, 2]},
      "geometries": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                      "material": {"kT": 1, "ior": 1.5}}]})",
                       "s.json")
                .warnings,
            std::vector<std::string>{});
  EXPECT_EQ(SceneDocument().warnings, std::vector<std::string>{});
}

}  // namespace
}  // namespace rt
