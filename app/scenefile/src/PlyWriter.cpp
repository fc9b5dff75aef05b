// binaryPly (scenefile/ModelFile.h): a mesh as a binary little-endian PLY file, written byte by
// byte so that the file is the same on every machine.
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "scenefile/ModelFile.h"

namespace rt {

namespace {

void appendLittleEndian(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFFu);
}

}  // namespace

std::string binaryPly(const TriangleMesh& mesh, const std::string& comment) {
  if (comment.find_first_of("\r\n") != std::string::npos)
    throw std::invalid_argument("binaryPly: the comment must be one line, got '" + comment + "'");
  std::string out = "ply\nformat binary_little_endian 1.0\n";
  if (!comment.empty()) out += "comment " + comment + "\n";
  out += "element vertex " + std::to_string(mesh.vertexCount()) +
         "\nproperty float x\nproperty float y\nproperty float z\n"
         "element face " +
         std::to_string(mesh.triangleCount()) +
         "\nproperty list uchar uint vertex_indices\nend_header\n";
  out.reserve(out.size() + 12 * mesh.vertexCount() + 13 * mesh.triangleCount());
  for (const Point& p : mesh.vertices())
    for (double c : {p.x(), p.y(), p.z()})
      appendLittleEndian(out, std::bit_cast<std::uint32_t>(static_cast<float>(c)));
  for (const TriangleMesh::Indices& t : mesh.triangles()) {
    out += '\x03';
    for (std::uint32_t i : t) appendLittleEndian(out, i);
  }
  return out;
}

}  // namespace rt
