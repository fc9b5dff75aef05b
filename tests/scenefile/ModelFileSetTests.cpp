// Model files recorded on one machine and replayed on another (what rt-mpi's rank 0 sends):
// the set holds every file a reading opened with its exact bytes, and replaying it gives the
// same meshes bit for bit with the disk gone; a file missing from the set is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "ModelFileFixture.h"
#include "scenefile/LitDocument.h"
#include "scenefile/ModelFile.h"
#include "scenefile/SceneFile.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

using ModelFileSetTest = testing::ModelFileFixture;

const std::string kMtl = "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n";
const std::string kObj =
    "mtllib two.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1.5\n"
    "usemtl red\nf 1 2 3\n"
    "usemtl blue\nf 1 2 4\nf 1 3 4\n";

void expectSameMeshes(const ModelFile& a, const ModelFile& b) {
  ASSERT_EQ(a.groups.size(), b.groups.size());
  for (std::size_t g = 0; g < a.groups.size(); ++g) {
    EXPECT_EQ(a.groups[g].material, b.groups[g].material);
    const TriangleMesh &x = a.groups[g].mesh, &y = b.groups[g].mesh;
    ASSERT_EQ(x.vertexCount(), y.vertexCount());
    ASSERT_EQ(x.triangleCount(), y.triangleCount());
    for (std::size_t v = 0; v < x.vertexCount(); ++v) EXPECT_EQ(x.vertices()[v], y.vertices()[v]);
    ASSERT_EQ(x.hasNormals(), y.hasNormals());
    for (std::size_t v = 0; x.hasNormals() && v < x.vertexCount(); ++v)
      EXPECT_EQ(x.normals()[v], y.normals()[v]);
    for (std::size_t t = 0; t < x.triangleCount(); ++t)
      EXPECT_EQ(x.triangles()[t], y.triangles()[t]);
  }
}

TEST_F(ModelFileSetTest, RecordingKeepsTheModelAndItsMaterialLibraryByteForByte) {
  write("two.mtl", kMtl);
  const fs::path obj = write("two.obj", kObj);
  ModelFileSet set;
  const ModelFile read = readModelFile(obj, ModelOptions{}, {.record = &set});
  EXPECT_EQ(read.groups.size(), 2u);
  ASSERT_EQ(set.files.size(), 2u);
  EXPECT_EQ(set.files.at(obj.string()), kObj);
  EXPECT_EQ(set.files.at((dir_ / "two.mtl").string()), kMtl);
  EXPECT_EQ(set.bytes(), kObj.size() + kMtl.size());
}

TEST_F(ModelFileSetTest, ReplayingGivesTheSameMeshesBitForBitWithTheFilesGone) {
  write("two.mtl", kMtl);
  const fs::path obj = write("two.obj", kObj);
  ModelFileSet set;
  const ModelFile recorded = readModelFile(obj, ModelOptions{}, {.record = &set});
  fs::remove_all(dir_);
  const ModelFile replayed = readModelFile(obj, ModelOptions{}, {.replay = &set});
  expectSameMeshes(recorded, replayed);
  EXPECT_EQ(replayed.groups.at(1).material, "blue");
}

TEST_F(ModelFileSetTest, AFileMissingFromTheReplayedSetIsRefused) {
  const ModelFileSet empty;
  const fs::path obj = dir_ / "two.obj";
  try {
    readModelFile(obj, ModelOptions{}, {.replay = &empty});
    FAIL() << "read a file the set does not hold";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()),
              obj.string() + ": cannot read: not among the model files received (0)");
  }
}

TEST_F(ModelFileSetTest, ASceneParsedFromAReplayedSetNeedsNoDisk) {
  const fs::path obj = write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string scene =
      "{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], \"vpDistance\": 10, "
      "\"vpSize\": [4, 4], \"resolution\": [8, 8]},\n"
      " \"geometries\": [{\"type\": \"mesh\", \"file\": \"tri.obj\"}]}\n";
  const std::string source = (dir_ / "scene.json").string();
  ModelFileSet set;
  const SceneDocument recorded = parseScene(scene, source, {.record = &set});
  ASSERT_EQ(set.files.size(), 1u);
  EXPECT_EQ(set.files.begin()->first, obj.string());
  fs::remove_all(dir_);
  const SceneDocument replayed = parseScene(scene, source, {.replay = &set});
  ASSERT_EQ(litScene(replayed).geometries.meshes().size(), 1u);
  const TriangleMesh& a = *litScene(recorded).geometries.meshes()[0].mesh;
  const TriangleMesh& b = *litScene(replayed).geometries.meshes()[0].mesh;
  ASSERT_EQ(b.vertexCount(), 3u);
  for (std::size_t v = 0; v < 3; ++v) EXPECT_EQ(a.vertices()[v], b.vertices()[v]);
  EXPECT_THROW(parseScene(scene, source), SceneError);  // from the disk: the model is gone
}

}  // namespace
}  // namespace rt
