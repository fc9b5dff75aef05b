// make-model teapot DETAIL FILE.ply: the Utah teapot tessellated by stage 2 (utahTeapot(DETAIL),
// in Newell's coordinates, z up), written as a binary PLY without normals (binaryPly), so that a
// scene that loads it shows both a reader's smooth normals and its flat faces. The file is the
// same for the same DETAIL on every machine.
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <string_view>

#include "camera/AtomicFile.h"
#include "common/Integers.h"
#include "geometries/UtahTeapot.h"
#include "scenefile/ModelFile.h"

namespace {

constexpr const char* USAGE =
    "Usage: make-model teapot DETAIL FILE.ply\n"
    "Writes the Utah teapot at DETAIL (quads per patch side, 1 to 256; 4 is the course's 992\n"
    "triangles) as a binary PLY file without normals.\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 || std::string_view(argv[1]) != "teapot") {
    std::fputs(USAGE, stderr);
    return 2;
  }
  const std::optional<int> detail = rt::integerInText(argv[2], 1, rt::kUtahTeapotMaxDetail);
  if (!detail) {
    std::fprintf(stderr, "make-model: DETAIL must be %s, got '%s'\n",
                 rt::integerDescription(1, rt::kUtahTeapotMaxDetail).c_str(), argv[2]);
    return 2;
  }
  try {
    const rt::TriangleMesh teapot = rt::utahTeapot(*detail);
    // The positions only: a model file without normals (the reader's smooth shading makes them).
    const rt::TriangleMesh positions(teapot.vertices(), teapot.triangles());
    rt::writeFileAtomically(argv[3],
                            rt::binaryPly(positions,
                                          "the Utah teapot (Martin Newell's 1975 patch data) at "
                                          "detail " +
                                              std::to_string(*detail) +
                                              ", tessellated by the rt project's utahTeapot"));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make-model: %s\n", e.what());
    return 1;
  }
  return 0;
}
