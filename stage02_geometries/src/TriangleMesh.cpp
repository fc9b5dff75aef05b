#include "geometries/TriangleMesh.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "primitives/Checks.h"

namespace rt {

namespace {

[[noreturn]] void reject(const std::string& why) {
  throw std::invalid_argument("TriangleMesh: " + why);
}

std::string str(std::uint64_t n) { return std::to_string(n); }

std::string triangleName(std::size_t t, const TriangleMesh::Indices& i) {
  return "triangles[" + str(t) + "] (" + str(i[0]) + "," + str(i[1]) + "," + str(i[2]) + ")";
}

/// (p1 - p0) x (p2 - p0): the expression of Plane's normalOf, so that a mesh triangle's normal
/// has the bits of a Triangle's (TriangleMeshTests checks it).
Double3 crossOf(const Point& p0, const Point& p1, const Point& p2) {
  return (p1.xyz() - p0.xyz()).cross(p2.xyz() - p0.xyz());
}

}  // namespace

void TriangleMesh::requireFits(std::uint64_t vertexCount, std::uint64_t triangleCount,
                               bool withNormals) {
  const std::string size = str(vertexCount) + " vertices and " + str(triangleCount) + " triangles";
  if (vertexCount > kMaxVertices)
    reject(size + ": more vertices than 32-bit indices can name (at most " + str(kMaxVertices) +
           ")");
  if (triangleCount > kMaxTriangles)
    reject(size + ": more triangles than 32-bit numbers can name (at most " + str(kMaxTriangles) +
           ")");
  // Both counts are below 2^32 here, so the bytes (below 2^32 * 60) cannot overflow.
  const std::uint64_t bytes = bytesFor(vertexCount, triangleCount, withNormals);
  if (bytes > kMaxBytes)
    reject(size + (withNormals ? " with normals" : "") + " need " + str(bytes) +
           " bytes, beyond the limit of " + str(kMaxBytes) + " bytes (16 GiB)");
}

TriangleMesh::TriangleMesh(std::vector<Point> vertices, std::vector<Indices> triangles,
                           std::vector<Double3> normals)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
  const std::size_t vertexCount = vertices_.size();
  if (vertexCount == 0) reject("a mesh needs at least one vertex, got none");
  if (triangles_.empty()) reject("a mesh needs at least one triangle, got none");
  if (!normals.empty() && normals.size() != vertexCount)
    reject("normals has " + str(normals.size()) + " entries for " + str(vertexCount) +
           " vertices (give one normal per vertex, or none for flat shading)");
  requireFits(vertexCount, triangles_.size(), !normals.empty());

  // The messages are built only on failure: the loops run once per vertex and per triangle of
  // meshes of millions of triangles.
  for (std::size_t i = 0; i < vertexCount; ++i) {
    if (!vertices_[i].xyz().isFinite())
      requireFinite(vertices_[i].xyz(), "TriangleMesh", "vertices[" + str(i) + "]");
  }

  normals_.reserve(normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const Double3& n = normals[i];
    if (!n.isFinite()) requireFinite(n, "TriangleMesh", "normals[" + str(i) + "]");
    if (n.isZero()) reject("normals[" + str(i) + "] must not be the zero vector, got " + n.str());
    normals_.push_back(Vector::unchecked(n).normalized());
  }

  // Check every triangle and keep those of non-zero area, compacting the array in place.
  std::size_t kept = 0;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const Indices tri = triangles_[t];
    for (const std::uint32_t index : tri) {
      if (index >= vertexCount)
        reject(triangleName(t, tri) + ": index " + str(index) + " is out of range (the mesh has " +
               str(vertexCount) + " vertices, indexed from 0 to " + str(vertexCount - 1) + ")");
    }
    const Double3 n = crossOf(vertices_[tri[0]], vertices_[tri[1]], vertices_[tri[2]]);
    if (n.isZero()) continue;  // zero area: dropped and counted
    if (!n.isFinite())
      reject(triangleName(t, tri) + " with corners " + vertices_[tri[0]].xyz().str() + ", " +
             vertices_[tri[1]].xyz().str() + ", " + vertices_[tri[2]].xyz().str() +
             ": its normal overflows (coordinates too large)");
    triangles_[kept++] = tri;
  }
  dropped_ = triangles_.size() - kept;
  if (kept == 0)
    reject("every one of the " + str(dropped_) + " triangles has zero area (none is left)");
  triangles_.resize(kept);
}

Vector TriangleMesh::flatNormal(std::size_t t) const noexcept {
  const Indices& i = triangles_[t];
  // Never zero: the constructor dropped the triangles whose cross product is.
  return Vector::unchecked(crossOf(vertices_[i[0]], vertices_[i[1]], vertices_[i[2]])).normalized();
}

Vector TriangleMesh::shadingNormal(std::size_t t, double b1, double b2) const noexcept {
  if (normals_.empty()) return flatNormal(t);
  const Indices& i = triangles_[t];
  const Double3 blend =
      normals_[i[0]].xyz() * (1 - b1 - b2) + normals_[i[1]].xyz() * b1 + normals_[i[2]].xyz() * b2;
  if (blend.isExactlyZero()) return flatNormal(t);
  return Vector::unchecked(blend).normalized();
}

Vector TriangleMesh::normalAt(std::size_t t, const Point& p) const noexcept {
  if (normals_.empty()) return flatNormal(t);
  const Indices& i = triangles_[t];
  const Double3& v0 = vertices_[i[0]].xyz();
  const Double3 e1 = vertices_[i[1]].xyz() - v0;
  const Double3 e2 = vertices_[i[2]].xyz() - v0;
  const Double3 d = p.xyz() - v0;
  const Double3 n = e1.cross(e2);
  const double nn = n.dot(n);  // > 0: the constructor dropped the triangles whose n is zero
  return shadingNormal(t, d.cross(e2).dot(n) / nn, e1.cross(d).dot(n) / nn);
}

std::size_t TriangleMesh::memoryBytes() const {
  return vertices_.capacity() * sizeof(Point) + triangles_.capacity() * sizeof(Indices) +
         normals_.capacity() * sizeof(Vector);
}

}  // namespace rt
