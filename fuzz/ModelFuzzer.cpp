// libFuzzer target: readModelFromMemory on arbitrary bytes. The reader's contract is that any
// input gives meshes or a ModelError; anything else (another exception, a sanitizer report, a
// hang, an allocation beyond -rss_limit_mb) is a bug, in the reader or in Assimp below it.
// The format is guessed from the first bytes, as a file's extension would name it: "ply" for
// PLY, "solid" for ASCII STL, a line starting "v " or "f " for OBJ, else binary STL.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>

#include "scenefile/ModelFile.h"

namespace {
std::string_view formatOf(std::string_view text) {
  if (text.starts_with("ply")) return "ply";
  if (text.starts_with("solid")) return "stl";
  if (text.starts_with("v ") || text.starts_with("f ") || text.find("\nv ") != text.npos ||
      text.find("\nf ") != text.npos)
    return "obj";
  return "stl";
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  rt::ModelOptions options;
  options.smooth = size % 2 == 0;  // both paths: normals kept or computed, and none
  try {
    const rt::ModelFile model = rt::readModelFromMemory(bytes, formatOf(text), "fuzz", options);
    // Accepted: TriangleMesh's promises hold (a failure aborts, so libFuzzer keeps the input).
    for (const rt::ModelGroup& g : model.groups)
      for (std::size_t t = 0; t < g.mesh.triangleCount(); ++t)
        for (std::uint32_t i : g.mesh.triangles()[t])
          if (i >= g.mesh.vertexCount()) std::abort();
  } catch (const rt::ModelError&) {
    return 0;  // rejected with a message: fine
  }
  return 0;
}
