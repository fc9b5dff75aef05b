// Model files through readModelFile: every file is written by the test into a fresh temporary
// directory (OBJ, ASCII and binary PLY, ASCII and binary STL), and the counts, positions and
// normals read back are compared exactly. Bad input: each refusal with its exact message.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "ModelFileFixture.h"
#include "scenefile/ModelFile.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

ModelOptions flat() {
  ModelOptions o;
  o.smooth = false;
  return o;
}

using P = std::tuple<double, double, double>;
P tup(const Point& p) { return {p.x(), p.y(), p.z()}; }
P tup(const Vector& v) { return {v.x(), v.y(), v.z()}; }

/// The triangles of a mesh as their corners' positions (each triangle's corners rotated so the
/// smallest comes first, which keeps its winding), as a set: independent of the vertex order.
std::set<std::vector<P>> cornerSet(const TriangleMesh& m) {
  std::set<std::vector<P>> out;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const auto c = m.corners(t);
    std::vector<P> v{tup(c[0]), tup(c[1]), tup(c[2])};
    while (!(v[0] <= v[1] && v[0] <= v[2])) std::rotate(v.begin(), v.begin() + 1, v.end());
    out.insert(v);
  }
  return out;
}

std::set<P> vertexSet(const TriangleMesh& m) {
  std::set<P> out;
  for (const Point& p : m.vertices()) out.insert(tup(p));
  return out;
}

std::string expectThrow(const fs::path& file, const ModelOptions& o) {
  try {
    readModelFile(file, o);
  } catch (const ModelError& e) {
    EXPECT_EQ(e.modelFile, file.string());
    return e.what();
  }
  ADD_FAILURE() << "no ModelError for " << file;
  return {};
}

class ModelFileTest : public testing::ModelFileFixture {
 protected:
  /// Writes bytes to dir/name and expects reading it (flat) refused with "PATH: " + detail.
  void expectRefused(const std::string& name, const std::string& bytes,
                     const std::string& detail) const {
    const fs::path file = write(name, bytes);
    EXPECT_EQ(expectThrow(file, flat()), file.string() + ": " + detail) << name;
  }
};

// A build without Assimp says how to get it (the other tests are skipped there).
TEST(ModelFileWithoutAssimp, SaysHowToGetAssimp) {
  if (modelFilesSupported()) GTEST_SKIP() << "this build reads model files (it has Assimp)";
  try {
    readModelFile("any.obj", ModelOptions{});
    ADD_FAILURE() << "no ModelError";
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(),
                 "any.obj: reading model files needs Assimp: install libassimp-dev "
                 "(scripts/deps.sh installs it)");
  }
}

// ---- OBJ ----------------------------------------------------------------------------------

TEST_F(ModelFileTest, ObjQuadAndPentagonAreTriangulated) {
  const auto file = write("ngons.obj",
                          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                          "v 0 0 1\nv 2 0 1\nv 3 1 1\nv 1 2 1\nv -1 1 1\n"
                          "f 1 2 3 4\nf 5 6 7 8 9\n");
  const ModelFile m = readModelFile(file, flat());
  ASSERT_EQ(m.groups.size(), 1u);
  const TriangleMesh& mesh = m.groups[0].mesh;
  EXPECT_EQ(mesh.triangleCount(), 5u);  // 2 for the quad, 3 for the pentagon
  EXPECT_EQ(mesh.vertexCount(), 9u);
  EXPECT_FALSE(mesh.hasNormals());
  EXPECT_EQ(m.droppedTriangles, 0u);
  EXPECT_EQ(m.groups[0].material, "");
  EXPECT_EQ(vertexSet(mesh), (std::set<P>{{0, 0, 0},
                                          {1, 0, 0},
                                          {1, 1, 0},
                                          {0, 1, 0},
                                          {0, 0, 1},
                                          {2, 0, 1},
                                          {3, 1, 1},
                                          {1, 2, 1},
                                          {-1, 1, 1}}));
  // Every triangle is counter-clockwise seen from +z, as the faces are.
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
    EXPECT_EQ(tup(mesh.flatNormal(t)), P(0, 0, 1)) << "triangle " << t;
}

TEST_F(ModelFileTest, ObjNegativeIndicesAreRelative) {
  const auto file = write("negative.obj",
                          "v 9 9 9\n"
                          "v 0 0 0\nv 4 0 0\nv 0 2 0\nf -3 -2 -1\n"
                          "v 0 0 5\nf -4 -3 -1\n");
  const ModelFile m = readModelFile(file, flat());
  ASSERT_EQ(m.groups.size(), 1u);
  EXPECT_EQ(cornerSet(m.groups[0].mesh),
            (std::set<std::vector<P>>{{{0, 0, 0}, {4, 0, 0}, {0, 2, 0}},
                                      {{0, 0, 0}, {4, 0, 0}, {0, 0, 5}}}));
  EXPECT_EQ(m.groups[0].mesh.vertexCount(), 4u);  // (9,9,9) is used by no face
}

TEST_F(ModelFileTest, ObjVertexNormalsAreKeptWhenSmooth) {
  const auto file = write("normals.obj",
                          "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                          "vn 0 0 2\nvn 0 1 1\nvn 1 0 1\n"
                          "f 1//1 2//2 3//3\n");
  const ModelFile smooth = readModelFile(file, ModelOptions{});
  const TriangleMesh& mesh = smooth.groups.at(0).mesh;
  ASSERT_TRUE(mesh.hasNormals());
  std::set<std::pair<P, P>> pairs;
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i)
    pairs.insert({tup(mesh.vertices()[i]), tup(mesh.normals()[i])});
  EXPECT_EQ(pairs, (std::set<std::pair<P, P>>{{{0, 0, 0}, tup(Vector(0, 0, 1))},
                                              {{1, 0, 0}, tup(Vector(0, 1, 1).normalized())},
                                              {{0, 1, 0}, tup(Vector(1, 0, 1).normalized())}}));
  // Flat: the file's normals are not kept.
  EXPECT_FALSE(readModelFile(file, flat()).groups.at(0).mesh.hasNormals());
}

TEST_F(ModelFileTest, ObjWithoutNormalsGetsComputedOnesWhenSmooth) {
  const auto file = write("plain.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const TriangleMesh smooth = readModelFile(file, ModelOptions{}).groups.at(0).mesh;
  ASSERT_TRUE(smooth.hasNormals());
  EXPECT_EQ(smooth.vertexCount(), 4u);
  for (const Vector& n : smooth.normals()) EXPECT_EQ(tup(n), P(0, 0, 1));
  EXPECT_FALSE(readModelFile(file, flat()).groups.at(0).mesh.hasNormals());
}

TEST_F(ModelFileTest, ObjMaterialGroupsAreMeshesOfTheirOwn) {
  write("two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  const auto file = write("two.obj",
                          "mtllib two.mtl\n"
                          "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                          "usemtl red\nf 1 2 3\n"
                          "usemtl blue\nf 1 2 4\nf 1 3 4\n");
  const ModelFile m = readModelFile(file, flat());
  ASSERT_EQ(m.groups.size(), 2u);
  EXPECT_EQ(m.groups[0].material, "red");
  EXPECT_EQ(m.groups[0].mesh.triangleCount(), 1u);
  EXPECT_EQ(m.groups[0].mesh.vertexCount(), 3u);
  EXPECT_EQ(m.groups[1].material, "blue");
  EXPECT_EQ(m.groups[1].mesh.triangleCount(), 2u);
  EXPECT_EQ(m.groups[1].mesh.vertexCount(), 4u);
}

TEST_F(ModelFileTest, APathThroughAnotherFolderReadsTheSameObjWithoutItsMaterials) {
  // An OBJ whose material library is missing, named through a folder it is not in
  // (exp/../models/m.obj, as rt export writes a model's path relative to the exported scene):
  // read as models/m.obj (Assimp refused it with "File read error"), its one triangle kept
  const auto file = write("models/m.obj", "mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::filesystem::create_directories(file.parent_path().parent_path() / "exp");
  const ModelFile m =
      readModelFile(file.parent_path().parent_path() / "exp" / ".." / "models" / "m.obj", flat());
  ASSERT_EQ(m.groups.size(), 1u);
  EXPECT_EQ(m.groups[0].mesh.triangleCount(), 1u);
  EXPECT_EQ(m.groups[0].mesh.vertexCount(), 3u);
}

TEST_F(ModelFileTest, DegenerateTrianglesAreDroppedAndCounted) {
  const auto file = write("degenerate.obj",
                          "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\n"
                          "f 1 2 3\nf 1 2 4\n");  // the second lies on the x axis: zero area
  const ModelFile m = readModelFile(file, flat());
  EXPECT_EQ(m.droppedTriangles, 1u);
  EXPECT_EQ(m.groups.at(0).mesh.triangleCount(), 1u);
  // Smooth: the normals computed for it do not make the file fatal either.
  const ModelFile smooth = readModelFile(file, ModelOptions{});
  EXPECT_EQ(smooth.droppedTriangles, 1u);
  const TriangleMesh& mesh = smooth.groups.at(0).mesh;
  ASSERT_EQ(mesh.triangleCount(), 1u);
  ASSERT_TRUE(mesh.hasNormals());
  for (std::uint32_t i : mesh.triangles()[0]) EXPECT_EQ(tup(mesh.normals()[i]), P(0, 0, 1));
}

TEST_F(ModelFileTest, PointsAndLinesAreIgnoredAndCounted) {
  const auto file = write("mixed.obj",
                          "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                          "p 1\np 2\nl 1 2\nf 1 2 3\n");
  const ModelFile m = readModelFile(file, flat());
  EXPECT_EQ(m.ignoredPoints, 2u);
  EXPECT_EQ(m.ignoredLines, 1u);
  EXPECT_EQ(m.groups.at(0).mesh.triangleCount(), 1u);
}

TEST_F(ModelFileTest, TheMemoryFormReadsTheSameMesh) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  const auto* bytes = reinterpret_cast<const std::byte*>(text.data());
  const ModelFile m = readModelFromMemory({bytes, text.size()}, "obj", "mem.obj", flat());
  const ModelFile f = readModelFile(write("same.obj", text), flat());
  EXPECT_EQ(cornerSet(m.groups.at(0).mesh), cornerSet(f.groups.at(0).mesh));
  EXPECT_EQ(m.groups.at(0).mesh.triangleCount(), 2u);
}

// ---- PLY ----------------------------------------------------------------------------------

const std::set<std::vector<P>> kPlyTriangles{{{0, 0, 0}, {2, 0, 0}, {2, 3, 0}},
                                             {{0, 0, 0}, {2, 3, 0}, {0, 3, 0}},
                                             {{0, 0, 0}, {0, 3, 0}, {0, 0, 5}}};

/// The model the PLY and OFF tests write in each format: 5 vertices, a quad (0 1 2 3) and a
/// triangle (0 3 4), read flat as kPlyTriangles.
void expectQuadAndTriangle(const fs::path& file) {
  const ModelFile m = readModelFile(file, flat());
  ASSERT_EQ(m.groups.size(), 1u);
  EXPECT_EQ(m.groups[0].mesh.vertexCount(), 5u);
  EXPECT_EQ(cornerSet(m.groups[0].mesh), kPlyTriangles);
}

TEST_F(ModelFileTest, AsciiPly) {
  const auto file = write("ascii.ply",
                          "ply\nformat ascii 1.0\nelement vertex 5\n"
                          "property float x\nproperty float y\nproperty float z\n"
                          "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n2 0 0\n2 3 0\n0 3 0\n0 0 5\n"
                          "4 0 1 2 3\n3 0 3 4\n");
  expectQuadAndTriangle(file);
}

std::string le32(std::uint32_t v) {
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i)
    s[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
  return s;
}
std::string leFloat(float f) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, 4);
  return le32(bits);
}

TEST_F(ModelFileTest, BinaryLittleEndianPly) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 5\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const float xyz[5][3] = {{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}, {0, 0, 5}};
  for (const auto& v : xyz)
    for (float c : v) bytes += leFloat(c);
  bytes += '\x04';
  for (std::uint32_t i : {0u, 1u, 2u, 3u}) bytes += le32(i);
  bytes += '\x03';
  for (std::uint32_t i : {0u, 3u, 4u}) bytes += le32(i);
  expectQuadAndTriangle(write("binary.ply", bytes));
}

/// A PLY header for 3 vertices and 1 face, in ASCII.
const std::string kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\n"
    "property float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

// The header's counts against the bytes after it: the fewest bytes its elements can take, in
// binary their scalars' and their lists' counts' sizes, in ASCII two a value (a character and a
// separator) less the last separator. One byte short of that is refused, naming the counts.
TEST_F(ModelFileTest, APlyHeaderAnnouncingMoreThanTheFileHoldsIsRefused) {
  const std::string binaryHeader =
      "ply\nformat binary_little_endian 1.0\nelement vertex 5\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  // 5 vertices of 12 bytes, 2 faces of at least their 1-byte count: 62 bytes.
  expectRefused("short.ply", binaryHeader + std::string(61, '\0'),
                "the PLY header announces 5 'vertex', 2 'face' (at least 62 bytes of binary "
                "data), but 61 bytes follow it");
  // 3 vertices of 3 values and 1 face of its count, two bytes a value, the last without its
  // separator: 3·6 + 2 − 1 = 19 bytes.
  expectRefused("short-ascii.ply", kPlyHeader + "0 0 0\n1 0 0\n0 1 0\n",
                "the PLY header announces 3 'vertex', 1 'face' (at least 19 bytes of ASCII "
                "data), but 18 bytes follow it");
  // A binary file announcing 4·10^9 vertices in 12 bytes (Assimp ran out of memory on it), and
  // an ASCII one announcing 4·10^8 (Assimp took gigabytes and minutes): at once, in memory too.
  const std::string huge =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
      std::string(12, '\0');
  expectRefused("huge.ply", huge,
                "the PLY header announces 4000000000 'vertex', 1 'face' (at least 48000000001 "
                "bytes of binary data), but 12 bytes follow it");
  const std::string hugeAscii =
      "ply\nformat ascii 1.0\nelement vertex 400000000\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n";
  try {
    readModelFromMemory({reinterpret_cast<const std::byte*>(hugeAscii.data()), hugeAscii.size()},
                        "ply", "mem.ply", flat());
    ADD_FAILURE() << "no ModelError";
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(),
                 "mem.ply: the PLY header announces 400000000 'vertex', 1 'face' (at least "
                 "2400000001 bytes of ASCII data), but 6 bytes follow it");
  }
  // A count beyond 2^64 and counts whose bytes add up beyond it: the sum stops at 2^64.
  expectRefused("beyond.ply",
                "ply\nformat binary_big_endian 1.0\nelement vertex "
                "99999999999999999999\nproperty double x\nelement face "
                "9223372036854775807\nproperty list uchar int i\nend_header\n",
                "the PLY header announces 18446744073709551615 'vertex', 9223372036854775807 "
                "'face' (at least 2^64 bytes of binary data), but 0 bytes follow it");
}

// A face whose list count is 4·10^9 (the header's element counts are right, so the check above
// passes it): Assimp fails to allocate its indices and reports the failure as "std::bad_alloc",
// its exception's what(); the message says it ran out of memory, with the file's size.
TEST_F(ModelFileTest, APlyFaceListCountBeyondMemoryIsRefusedAsOutOfMemory) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "a sanitizer's allocator may reserve the tens of GB instead of failing";
#else
  const double memory = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) *
                        static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  if (memory > 32.0 * (1u << 30))
    GTEST_SKIP() << "more than 32 GiB of memory: the allocation might succeed and be used";
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uint int vertex_indices\nend_header\n";
  for (const float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) bytes += leFloat(c);
  bytes += le32(4'000'000'000u);
  for (std::uint32_t i : {0u, 1u, 2u}) bytes += le32(i);
  expectRefused(
      "hugelist.ply", bytes,
      "out of memory while reading the file (" + std::to_string(bytes.size()) + " bytes)");
#endif
}

// ---- OFF ----------------------------------------------------------------------------------

TEST_F(ModelFileTest, OffWithCommentsAndBlankLines) {
  const auto file = write("quad.off",
                          "# a unit square and a triangle above it\nOFF\n5 2 0\n"
                          "0 0 0\n2 0 0\n2 3 0\n\n0 3 0\n0 0 5\n4 0 1 2 3\n3 0 3 4\n");
  expectQuadAndTriangle(file);
}

// Assimp's OFF reader logs these faults and returns a model that is not the file's (an index
// out of range read as the last vertex, a face dropped, vertices left at the origin): refused.
TEST_F(ModelFileTest, OffFaultsThatAssimpOnlyLogsAreRefused) {
  const std::string triangle = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n";
  expectRefused("range.off", triangle + "3 0 1 7\n3 9 1 8\n",
                "OFF: 3 vertex indices of its faces out of range (the file has 3 vertices, "
                "numbered 0 to 2)");
  expectRefused("empty-face.off", triangle + "3 0 1 2\n0\n",
                "OFF: 1 face of no vertex or of more than 9, which Assimp's OFF reader does "
                "not take");
  expectRefused("ten.off",
                "OFF\n11 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n-1 1 0\n-1 0 0\n"
                "-1 -1 0\n0 -1 0\n1 -1 0\n2 -1 0\n2 0 0\n3 0 1 2\n"
                "10 0 1 2 3 4 5 6 7 8 9\n",
                "OFF: 1 face of no vertex or of more than 9, which Assimp's OFF reader does "
                "not take");
  expectRefused("cut.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                "OFF: the file has fewer lines than its header announces vertices "
                "and faces");
}

// ---- STL ----------------------------------------------------------------------------------

/// The unit cube's 12 triangles, wound outward, with their facet normals.
struct Facet {
  float n[3];
  float v[3][3];
};
std::vector<Facet> cubeFacets() {
  std::vector<Facet> f;
  auto quad = [&](std::array<float, 3> n, std::array<float, 3> a, std::array<float, 3> b,
                  std::array<float, 3> c, std::array<float, 3> d) {
    f.push_back({{n[0], n[1], n[2]}, {{a[0], a[1], a[2]}, {b[0], b[1], b[2]}, {c[0], c[1], c[2]}}});
    f.push_back({{n[0], n[1], n[2]}, {{a[0], a[1], a[2]}, {c[0], c[1], c[2]}, {d[0], d[1], d[2]}}});
  };
  quad({0, 0, -1}, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0});
  quad({0, 0, 1}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1});
  quad({0, -1, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1});
  quad({0, 1, 0}, {0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0});
  quad({-1, 0, 0}, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0});
  quad({1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1});
  return f;
}

void expectUnitCube(const ModelFile& m, std::size_t vertices) {
  ASSERT_EQ(m.groups.size(), 1u);
  const TriangleMesh& mesh = m.groups[0].mesh;
  EXPECT_EQ(mesh.triangleCount(), 12u);
  EXPECT_EQ(mesh.vertexCount(), vertices);
  std::set<P> corners;
  for (double x : {0, 1})
    for (double y : {0, 1})
      for (double z : {0, 1}) corners.insert({x, y, z});
  EXPECT_EQ(vertexSet(mesh), corners);
  // Outward: each triangle's normal points away from the centre.
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const auto c = mesh.corners(t);
    const Vector n = mesh.flatNormal(t);
    EXPECT_GT(n.dot(c[0] - Point(0.5, 0.5, 0.5)), 0) << "triangle " << t;
  }
}

TEST_F(ModelFileTest, AsciiStlCubeHasEightVerticesWhenFlat) {
  std::string text = "solid cube\n";
  for (const Facet& f : cubeFacets()) {
    text += "facet normal " + std::to_string(f.n[0]) + " " + std::to_string(f.n[1]) + " " +
            std::to_string(f.n[2]) + "\nouter loop\n";
    for (const auto& v : f.v)
      text += "vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
              std::to_string(v[2]) + "\n";
    text += "endloop\nendfacet\n";
  }
  text += "endsolid cube\n";
  const auto file = write("cube.stl", text);
  expectUnitCube(readModelFile(file, flat()), 8);
  // Smooth keeps the facet normals, so a corner is one vertex per face it touches: 3 x 8.
  const ModelFile smooth = readModelFile(file, ModelOptions{});
  expectUnitCube(smooth, 24);
  EXPECT_TRUE(smooth.groups[0].mesh.hasNormals());
}

TEST_F(ModelFileTest, BinaryStlCubeHasEightVerticesWhenFlat) {
  std::string bytes(80, ' ');  // the header: anything but "solid" at the start
  const auto facets = cubeFacets();
  bytes += le32(static_cast<std::uint32_t>(facets.size()));
  for (const Facet& f : facets) {
    for (float c : f.n) bytes += leFloat(c);
    for (const auto& v : f.v)
      for (float c : v) bytes += leFloat(c);
    bytes += std::string(2, '\0');  // the attribute byte count
  }
  expectUnitCube(readModelFile(write("cube-binary.stl", bytes), flat()), 8);
}

// ---- The transform ------------------------------------------------------------------------

TEST_F(ModelFileTest, TheTransformScalesRotatesAndTranslatesExactly) {
  const auto file = write("one.obj", "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  ModelOptions o = flat();
  o.transform.scale = {2, 3, 4};
  o.transform.rotationDegrees = {0, 0, 90};  // x -> y, y -> -x
  o.transform.translation = {1, 2, 3};
  const ModelFile m = readModelFile(file, o);
  EXPECT_EQ(vertexSet(m.groups.at(0).mesh), (std::set<P>{{1, 4, 3}, {-2, 2, 3}, {1, 2, 7}}));
  // Rotations of -270 and 450 degrees are the same exact quarter turn.
  o.transform.rotationDegrees = {0, 0, -270};
  EXPECT_EQ(vertexSet(readModelFile(file, o).groups.at(0).mesh),
            (std::set<P>{{1, 4, 3}, {-2, 2, 3}, {1, 2, 7}}));
  o.transform.rotationDegrees = {90, 0, 0};  // y -> z, z -> -y
  o.transform.translation = {0, 0, 0};
  EXPECT_EQ(vertexSet(readModelFile(file, o).groups.at(0).mesh),
            (std::set<P>{{2, 0, 0}, {0, 0, 3}, {0, -4, 0}}));
}

TEST_F(ModelFileTest, ANonUniformScaleTransformsNormalsByTheInverseTranspose) {
  const auto file = write("tilted.obj",
                          "v 0 0 0\nv 1 -1 0\nv 0 0 1\nvn 1 1 0\n"
                          "f 1//1 3//1 2//1\n");
  ModelOptions o;
  o.transform.scale = {2, 1, 1};
  const TriangleMesh mesh = readModelFile(file, o).groups.at(0).mesh;
  ASSERT_TRUE(mesh.hasNormals());
  // The plane x + y = 0 scaled by 2 in x is x/2 + y = 0: normal (1, 2, 0), normalised.
  for (const Vector& n : mesh.normals()) EXPECT_EQ(tup(n), tup(Vector(1, 2, 0).normalized()));
  EXPECT_EQ(tup(mesh.flatNormal(0)), tup(Vector(1, 2, 0).normalized()));
}

// ---- Bad input ----------------------------------------------------------------------------

TEST_F(ModelFileTest, AMissingFileIsRefusedWithTheSystemsReason) {
  const fs::path file = dir_ / "absent.obj";
  EXPECT_EQ(expectThrow(file, flat()), file.string() + ": cannot read: No such file or directory");
}

TEST_F(ModelFileTest, ADirectoryIsRefused) {
  EXPECT_EQ(expectThrow(dir_, flat()), dir_.string() + ": cannot read: it is a directory");
}

/// What readModelFile(file, options) throws, read in a child process that runs as the user nobody
/// (65534) when this one runs as root (for whom permissions do not stop reading); nullopt when the
/// child cannot become nobody (a container whose root may not change its user).
std::optional<std::string> refusalAsUnprivileged(const fs::path& file, const ModelOptions& o) {
  if (::geteuid() != 0) return expectThrow(file, o);
  int channel[2];
  if (::pipe(channel) != 0) return "pipe: " + std::string(std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(channel[0]);
    if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(3);
    std::string message = "no ModelError";
    try {
      readModelFile(file, o);
    } catch (const ModelError& e) {
      message = e.what();
    }
    const bool written =
        ::write(channel[1], message.data(), message.size()) == static_cast<ssize_t>(message.size());
    ::_exit(written ? 0 : 4);
  }
  ::close(channel[1]);
  std::string message;
  char buffer[512];
  for (ssize_t n; (n = ::read(channel[0], buffer, sizeof buffer)) > 0;)
    message.append(buffer, static_cast<std::size_t>(n));
  ::close(channel[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 3) return std::nullopt;
  return message;
}

TEST_F(ModelFileTest, AnUnreadableFileIsRefusedWithTheSystemsReason) {
  // TC01: a file its reader may not read: the system's reason (as root, read as the user nobody)
  const auto file = write("locked.obj", "v 0 0 0\n");
  fs::permissions(file, fs::perms::none);
  const std::optional<std::string> refusal = refusalAsUnprivileged(file, flat());
  if (!refusal) GTEST_SKIP() << "running as root, and the user nobody is out of reach";
  EXPECT_EQ(*refusal, file.string() + ": cannot read: Permission denied");
}

TEST_F(ModelFileTest, AnUnknownFormatIsRefusedWithAssimpsMessage) {
  const auto file = write("noise.xyz123", "this is no model\n");
  const std::string message = expectThrow(file, flat());
  EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
  EXPECT_EQ(message, file.string() + ": No suitable reader found for the file format of file \"" +
                         file.string() + "\".");
}

TEST_F(ModelFileTest, APlyWithoutItsFaceDataIsRefused) {
  // Assimp reads the missing face as one without indices, on which its Triangulate step would
  // abort the program: refused before it.
  // A blank line in place of the face: the bytes the header's counts ask for are there (19).
  const auto file = write("cut.ply", kPlyHeader + "0 0 0\n1 0 0\n0 1 0\n\n");
  EXPECT_EQ(expectThrow(file, flat()),
            file.string() + ": face 0 of mesh 0 has no vertex indices (does the file end early?)");
}

TEST_F(ModelFileTest, APlyHeaderWithoutItsEndIsRefused) {
  // Assimp's PLY reader would never return on it (the model fuzzer found this).
  const auto file = write("endless.ply", "ply\nformat ascii 1.0\nelement vertex 3\n");
  EXPECT_EQ(
      expectThrow(file, flat()),
      file.string() + ": the PLY header does not end (no end_header line in its first 38 bytes)");
  // end_header must be the first word of a line.
  const std::string text = "PLY\nformat ascii 1.0\n0 end_header\nend_header0\nend_header\v\n";
  try {
    readModelFromMemory({reinterpret_cast<const std::byte*>(text.data()), text.size()}, "ply",
                        "mem.ply", flat());
    ADD_FAILURE() << "no ModelError";
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(),
                 "mem.ply: the PLY header does not end (no end_header line in its first 58 "
                 "bytes)");
  }
}

TEST_F(ModelFileTest, APlyIndexOutOfRangeIsRefusedWithAssimpsMessage) {
  const auto file = write("range.ply", kPlyHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
  EXPECT_EQ(expectThrow(file, flat()),
            file.string() + ": Validation failed: aiMesh::mFaces[0]::mIndices[2] is out of range");
}

TEST_F(ModelFileTest, ABrokenAsciiStlIsRefusedWithAssimpsMessage) {
  const auto file =
      write("cut.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\n");
  const std::string message = expectThrow(file, flat());
  EXPECT_EQ(message.rfind(file.string() + ": Cannot parse string ", 0), 0u) << message;
}

TEST_F(ModelFileTest, AModelWithoutTrianglesIsRefused) {
  const auto file = write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n");
  EXPECT_EQ(expectThrow(file, flat()),
            file.string() + ": the model has no triangles (1 points and 2 lines ignored)");
}

TEST_F(ModelFileTest, AnEmptyModelInMemoryIsRefused) {
  try {
    readModelFromMemory({}, "obj", "empty.obj", flat());
    ADD_FAILURE() << "no ModelError";
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(), "empty.obj: the model is empty (0 bytes)");
  }
}

TEST_F(ModelFileTest, AnObjIndexOutOfRangeIsRefusedWithAssimpsMessage) {
  const auto file = write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  EXPECT_EQ(expectThrow(file, flat()), file.string() + ": OBJ: vertex index out of range");
  const auto zero = write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n");
  EXPECT_EQ(expectThrow(zero, flat()), zero.string() + ": OBJ: Invalid face index.");
}

TEST_F(ModelFileTest, NonFiniteCoordinatesAreRefusedWithTheMeshsMessage) {
  const auto file = write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n");
  const std::string message = expectThrow(file, flat());
  EXPECT_EQ(message.rfind(file.string() + ": TriangleMesh: vertices[", 0), 0u) << message;
  EXPECT_NE(message.find("must be finite"), std::string::npos) << message;
}

TEST_F(ModelFileTest, ADegenerateTransformIsRefused) {
  const auto file = write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ModelOptions o = flat();
  o.transform.scale = {1, 0, 1};
  EXPECT_EQ(expectThrow(file, o),
            file.string() +
                ": the transform is degenerate: scale must be finite and non-zero on every axis, "
                "got " +
                Double3(1, 0, 1).str());
  o.transform.scale = {1, 1, 1};
  o.transform.translation = {0, std::nan(""), 0};
  EXPECT_EQ(expectThrow(file, o).rfind(
                file.string() + ": the transform is degenerate: translation must be finite", 0),
            0u);
}

TEST_F(ModelFileTest, AHeaderAnnouncingMoreThanTheFileHoldsIsRefused) {
  // A PLY header announcing 2^33 vertices and no data: refused, not a crash.
  const auto file = write("huge.ply",
                          "ply\nformat binary_little_endian 1.0\nelement vertex 8589934592\n"
                          "property float x\nproperty float y\nproperty float z\n"
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n");
  EXPECT_EQ(expectThrow(file, flat()),
            file.string() +
                ": the PLY header announces 8589934592 'vertex', 1 'face' (at least 103079215105 "
                "bytes of binary data), but 0 bytes follow it");
}

}  // namespace
}  // namespace rt
