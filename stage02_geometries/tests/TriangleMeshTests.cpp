// Stage 2, beyond the course: TriangleMesh's validation, its dropped triangles, its size limits
// and its flat and shading normals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geometries/Triangle.h"
#include "geometries/TriangleMesh.h"

#include "ExpectVector.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::sameBits;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using test::expectVector;
using Indices = TriangleMesh::Indices;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A tetrahedron: the unit corner at the origin and the three axis points, wound outward.
std::vector<Point> tetraVertices() {
  return {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
}
std::vector<Indices> tetraTriangles() { return {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}; }

/// The message the constructor refuses with (a failure when it accepts).
std::string messageOf(std::vector<Point> v, std::vector<Indices> t, std::vector<Double3> n = {}) {
  try {
    TriangleMesh mesh(std::move(v), std::move(t), std::move(n));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "the mesh was accepted";
  return {};
}

TEST(TriangleMeshTests, constructor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a closed mesh without normals: every vertex and triangle kept in order, none dropped
  const TriangleMesh tetra(tetraVertices(), tetraTriangles());
  EXPECT_EQ(tetra.vertexCount(), 4u);
  EXPECT_EQ(tetra.triangleCount(), 4u);
  EXPECT_EQ(tetra.droppedTriangles(), 0u);
  EXPECT_FALSE(tetra.hasNormals());
  EXPECT_EQ(tetra.vertices(), tetraVertices());
  EXPECT_EQ(tetra.triangles(), tetraTriangles());
  // TC02: normals of any length are stored normalised: (0,0,2) -> (0,0,1), (3,4,0) -> (0.6,0.8,0)
  const TriangleMesh smooth(tetraVertices(), tetraTriangles(),
                            {{0, 0, 2}, {3, 4, 0}, {0, 0.5, 0}, {-5, 0, 0}});
  ASSERT_TRUE(smooth.hasNormals());
  EXPECT_EQ(smooth.normals()[0].xyz().z, 1.0);
  EXPECT_EQ(smooth.normals()[1].xyz().x, 0.6);
  EXPECT_EQ(smooth.normals()[1].xyz().y, 0.8);
  EXPECT_EQ(smooth.normals()[2].xyz().y, 1.0);
  EXPECT_EQ(smooth.normals()[3].xyz().x, -1.0);
  // TC03: zero-area triangles are dropped and counted, the others keep their order: a repeated
  // index (0,0,1) and three points on one line (0,1,4) with (2,0,0) on the x axis
  std::vector<Point> withLine = tetraVertices();
  withLine.emplace_back(2, 0, 0);
  const TriangleMesh dropped(withLine, {{0, 2, 1}, {0, 0, 1}, {0, 1, 3}, {0, 1, 4}, {1, 2, 3}});
  EXPECT_EQ(dropped.droppedTriangles(), 2u);
  EXPECT_EQ(dropped.triangles(), (std::vector<Indices>{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}}));
  // TC04: a vertex no triangle uses is allowed and kept
  EXPECT_EQ(dropped.vertexCount(), 5u);

  // =============== Boundary Values Tests ==================
  // TC11: no vertices, no triangles
  EXPECT_THAT(messageOf({}, {{0, 1, 2}}), HasSubstr("at least one vertex, got none"));
  EXPECT_THAT(messageOf(tetraVertices(), {}), HasSubstr("at least one triangle, got none"));
  // TC12: the index equal to the vertex count is out of range, named with its triangle; the
  // index one below it is the last valid one
  EXPECT_EQ(messageOf(tetraVertices(), {{0, 2, 1}, {0, 1, 4}}),
            "TriangleMesh: triangles[1] (0,1,4): index 4 is out of range (the mesh has 4 "
            "vertices, indexed from 0 to 3)");
  EXPECT_NO_THROW(TriangleMesh(tetraVertices(), {{0, 1, 3}}));
  EXPECT_THAT(messageOf(tetraVertices(), {{0xFFFFFFFFu, 1, 2}}),
              HasSubstr("index 4294967295 is out of range"));
  // TC13: a non-finite coordinate names its vertex: infinite, NaN
  std::vector<Point> infinite = tetraVertices();
  infinite[2] = Point(0, kInf, 0);
  EXPECT_EQ(messageOf(infinite, tetraTriangles()),
            "TriangleMesh: vertices[2] must be finite, got (0,inf,0)");
  std::vector<Point> notANumber = tetraVertices();
  notANumber[3] = Point(kNaN, 0, 1);
  EXPECT_THAT(messageOf(notANumber, tetraTriangles()), HasSubstr("vertices[3] must be finite"));
  // TC14: a normals array one too short or one too long
  EXPECT_EQ(messageOf(tetraVertices(), tetraTriangles(), {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}),
            "TriangleMesh: normals has 3 entries for 4 vertices (give one normal per vertex, or "
            "none for flat shading)");
  EXPECT_THAT(messageOf(tetraVertices(), tetraTriangles(), std::vector<Double3>(5, {0, 0, 1})),
              HasSubstr("normals has 5 entries for 4 vertices"));
  // TC15: a zero normal, exact or in the course's sense (every component below 2^-40), is
  // refused naming its vertex; a normal just above the threshold is a direction like any other
  EXPECT_EQ(
      messageOf(tetraVertices(), tetraTriangles(), {{0, 0, 1}, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}}),
      "TriangleMesh: normals[1] must not be the zero vector, got (0,0,0)");
  EXPECT_THAT(messageOf(tetraVertices(), tetraTriangles(),
                        {{0, 0, 1}, {0, 0, 1}, {0, 0x1p-41, 0}, {1, 0, 0}}),
              HasSubstr("normals[2] must not be the zero vector"));
  const TriangleMesh tiny(tetraVertices(), tetraTriangles(),
                          {{0, 0, 1}, {0, 0, 1}, {0, 0x1p-40, 0}, {1, 0, 0}});
  EXPECT_EQ(tiny.normals()[2].xyz().y, 1.0);
  // TC16: a non-finite normal names its vertex
  EXPECT_EQ(
      messageOf(tetraVertices(), tetraTriangles(), {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {kNaN, 0, 0}}),
      "TriangleMesh: normals[3] must be finite, got (nan,0,0)");
  // TC17: every triangle of zero area: nothing would be left
  EXPECT_EQ(messageOf(tetraVertices(), {{0, 0, 1}, {2, 2, 2}}),
            "TriangleMesh: every one of the 2 triangles has zero area (none is left)");
  // TC18: the area threshold is the Triangle constructor's: a cross product of 2^-40 is kept
  // (and a Triangle accepts it), one of 2^-41 is dropped (and a Triangle refuses it)
  const std::vector<Point> sliver = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 0x1p-40, 0),
                                     Point(0, 0x1p-41, 0)};
  const TriangleMesh kept(sliver, {{0, 1, 2}, {0, 1, 3}});
  EXPECT_EQ(kept.triangleCount(), 1u);
  EXPECT_EQ(kept.droppedTriangles(), 1u);
  EXPECT_NO_THROW(Triangle(sliver[0], sliver[1], sliver[2]));
  EXPECT_THROW(Triangle(sliver[0], sliver[1], sliver[3]), std::invalid_argument);
  // TC19: coordinates so large that the normal overflows are refused, naming the triangle
  EXPECT_THAT(messageOf({Point(0, 0, 0), Point(1e200, 0, 0), Point(0, 1e200, 0)}, {{0, 1, 2}}),
              AllOf(HasSubstr("triangles[0] (0,1,2) with corners (0,0,0), (1e+200,0,0), "
                              "(0,1e+200,0)"),
                    HasSubstr("its normal overflows")));
}

TEST(TriangleMeshTests, requireFits) {
  using M = TriangleMesh;
  // ============ Equivalence Partitions Tests ==============
  // TC01: the bytes of a mesh: 24 per vertex, 24 more with normals, 12 per triangle
  EXPECT_EQ(M::bytesFor(2, 1, false), 60u);
  EXPECT_EQ(M::bytesFor(2, 1, true), 108u);
  // TC02: a million triangles with normals fit
  EXPECT_NO_THROW(M::requireFits(500'000, 1'000'000, true));

  // =============== Boundary Values Tests ==================
  // TC11: 2^32 - 1 vertices is the most 32-bit indices can name (refused here for its bytes,
  // 103 GB); one more is refused for the count
  EXPECT_THAT([] { M::requireFits(M::kMaxVertices, 1, false); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("beyond the limit")));
  EXPECT_THAT([] { M::requireFits(M::kMaxVertices + 1, 1, false); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("4294967296 vertices and 1 triangles: more vertices than 32-bit "
                            "indices can name (at most 4294967295)")));
  // TC12: one triangle more than 32-bit numbers can name
  EXPECT_THAT([] { M::requireFits(3, M::kMaxTriangles + 1, false); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("more triangles than 32-bit numbers can name")));
  // TC13: the byte limit, 2^34: 1 vertex with normals (48 bytes) and 1,431,655,761 triangles
  // take 17,179,869,180 bytes, the most below it (a mesh's bytes are a multiple of 12, 2^34 is
  // not); one triangle more is 12 bytes beyond it
  EXPECT_NO_THROW(M::requireFits(1, 1'431'655'761, true));
  EXPECT_THAT([] { M::requireFits(1, 1'431'655'762, true); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("TriangleMesh: 1 vertices and 1431655762 triangles with normals need "
                            "17179869192 bytes, beyond the limit of 17179869184 bytes (16 GiB)")));
  // TC14: counts whose bytes would overflow 64 bits are refused by the counts, not wrapped
  EXPECT_THROW(M::requireFits(std::uint64_t{1} << 62, std::uint64_t{1} << 62, true),
               std::invalid_argument);
}

TEST(TriangleMeshTests, corners) {
  // TC01: the corners of a triangle in the order of its indices
  const TriangleMesh tetra(tetraVertices(), tetraTriangles());
  const std::array<Point, 3> c = tetra.corners(3);
  EXPECT_EQ(c[0], Point(1, 0, 0));
  EXPECT_EQ(c[1], Point(0, 1, 0));
  EXPECT_EQ(c[2], Point(0, 0, 1));
}

TEST(TriangleMeshTests, flatNormal) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the winding decides the side: (0,2,1) faces -z, (1,2,3) faces (1,1,1)/sqrt(3)
  const TriangleMesh tetra(tetraVertices(), tetraTriangles());
  expectVector(tetra.flatNormal(0), 0, 0, -1, 0);
  const double k = 1 / std::sqrt(3.0);
  expectVector(tetra.flatNormal(3), k, k, k);
  // TC02: the same bits as a Triangle of the same three points, on points in general position
  const std::vector<Point> v = {Point(0.1, -2.3, 4.7), Point(3.3, 0.25, -1.9),
                                Point(-0.7, 1.1, 0.3), Point(1e-3, 7e2, -5)};
  const std::vector<Indices> t = {{0, 1, 2}, {2, 1, 0}, {3, 0, 2}, {1, 3, 2}};
  const TriangleMesh general(v, t);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Triangle triangle(v[t[i][0]], v[t[i][1]], v[t[i][2]]);
    EXPECT_TRUE(sameBits(general.flatNormal(i), triangle.normal(v[t[i][0]]))) << "triangle " << i;
  }
  // =============== Boundary Values Tests ==================
  // TC11: a sliver just above the area threshold still gets its exact unit normal
  const TriangleMesh sliver({Point(0, 0, 0), Point(1, 0, 0), Point(0, 0x1p-40, 0)}, {{0, 1, 2}});
  expectVector(sliver.flatNormal(0), 0, 0, 1, 0);
}

TEST(TriangleMeshTests, shadingNormal) {
  const Double3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const TriangleMesh flat(tetraVertices(), tetraTriangles());
  const TriangleMesh smooth(tetraVertices(), tetraTriangles(), {z, x, y, z});
  // ============ Equivalence Partitions Tests ==============
  // TC01: without vertex normals it is the flat normal, bit for bit, wherever asked
  EXPECT_TRUE(sameBits(flat.shadingNormal(3, 0.2, 0.3), flat.flatNormal(3)));
  // TC02: at the corners, (b1,b2) = (0,0), (1,0), (0,1), the vertex normals exactly;
  // triangle 3 is (1,2,3) with normals x, y, z
  expectVector(smooth.shadingNormal(3, 0, 0), 1, 0, 0, 0);
  expectVector(smooth.shadingNormal(3, 1, 0), 0, 1, 0, 0);
  expectVector(smooth.shadingNormal(3, 0, 1), 0, 0, 1, 0);
  // TC03: halfway along the edge from x to y: normalize(0.5·x + 0.5·y) = (1,1,0)/sqrt(2)
  const Vector half = smooth.shadingNormal(3, 0.5, 0);
  EXPECT_DOUBLE_EQ(half.x(), std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(half.y(), std::sqrt(0.5));
  EXPECT_EQ(half.z(), 0.0);
  // TC04: at the centroid: (1,1,1)/sqrt(3), unit length
  const double k = 1 / std::sqrt(3.0);
  const Vector centre = smooth.shadingNormal(3, 1.0 / 3, 1.0 / 3);
  expectVector(centre, k, k, k, 1e-15);
  EXPECT_NEAR(centre.length(), 1.0, 1e-15);
  // =============== Boundary Values Tests ==================
  // TC11: opposite vertex normals blend to the exact zero vector halfway: the flat normal
  const TriangleMesh opposite(tetraVertices(), tetraTriangles(), {z, -z, y, z});
  // triangle 1 is (0,1,3): normals z and -z at its first two corners
  EXPECT_TRUE(sameBits(opposite.shadingNormal(1, 0.5, 0), opposite.flatNormal(1)));
}

TEST(TriangleMeshTests, normalAt) {
  const Double3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const TriangleMesh flat(tetraVertices(), tetraTriangles());
  const TriangleMesh smooth(tetraVertices(), tetraTriangles(), {z, x, y, z});
  // Triangle 3 is (1,2,3): corners (1,0,0), (0,1,0), (0,0,1) with normals x, y, z.
  const Point v1(1, 0, 0), v2(0, 1, 0), v3(0, 0, 1);
  // ============ Equivalence Partitions Tests ==============
  // TC01: without vertex normals it is the flat normal, bit for bit, inside the triangle and at
  // a corner
  EXPECT_TRUE(sameBits(flat.normalAt(3, Point(0.2, 0.3, 0.5)), flat.flatNormal(3)));
  EXPECT_TRUE(sameBits(flat.normalAt(0, Point(0, 0, 0)), flat.flatNormal(0)));
  // TC02: at each corner the barycentric coordinates are exactly (0,0), (1,0), (0,1) (the
  // sub-triangle's cross product is 0 or n itself), so the normal is that vertex's, exactly
  EXPECT_TRUE(sameBits(smooth.normalAt(3, v1), smooth.normals()[1]));
  EXPECT_TRUE(sameBits(smooth.normalAt(3, v2), smooth.normals()[2]));
  EXPECT_TRUE(sameBits(smooth.normalAt(3, v3), smooth.normals()[3]));
  // TC03: at the centroid the three normals blend equally: (1,1,1)/sqrt(3), unit length
  const double k = 1 / std::sqrt(3.0);
  const Vector centre = smooth.normalAt(3, Point(1.0 / 3, 1.0 / 3, 1.0 / 3));
  expectVector(centre, k, k, k, 1e-15);
  EXPECT_NEAR(centre.length(), 1.0, 1e-15);
  // TC04: on an edge, the midpoint of v1 v2: only their normals blend, (1,1,0)/sqrt(2); a point
  // a quarter of the way from v2 to v3: normalize(0.75·y + 0.25·z) = (0,3,1)/sqrt(10)
  const Vector edge = smooth.normalAt(3, Point(0.5, 0.5, 0));
  expectVector(edge, std::sqrt(0.5), std::sqrt(0.5), 0, 1e-15);
  EXPECT_EQ(edge.z(), 0.0);
  expectVector(smooth.normalAt(3, Point(0, 0.75, 0.25)), 0, 3 / std::sqrt(10.0),
               1 / std::sqrt(10.0), 1e-15);
  // TC05: a triangle in general position: the point (1 - b1 - b2)·v0 + b1·v1 + b2·v2 gets the
  // normal shadingNormal gives for (b1, b2), to rounding
  const std::vector<Point> v = {Point(0.1, -2.3, 4.7), Point(3.3, 0.25, -1.9),
                                Point(-0.7, 1.1, 0.3)};
  const TriangleMesh general(v, {{0, 1, 2}}, {{0.3, -1, 0.2}, {1, 0.5, 0.5}, {-0.2, 0.1, 1}});
  const double b1 = 0.3, b2 = 0.45;
  const Point p(v[0].xyz() * (1 - b1 - b2) + v[1].xyz() * b1 + v[2].xyz() * b2);
  const Vector expected = general.shadingNormal(0, b1, b2);
  expectVector(general.normalAt(0, p), expected.x(), expected.y(), expected.z(), 1e-14);
  // TC06: a hit point a little off the plane (rounding) is read as its projection on the plane:
  // the same normal to rounding
  const Point off(p.xyz() + general.flatNormal(0).xyz() * 1e-9);
  expectVector(general.normalAt(0, off), expected.x(), expected.y(), expected.z(), 1e-14);
  // =============== Boundary Values Tests ==================
  // TC11: opposite vertex normals blend to the exact zero vector at the middle of their edge:
  // the flat normal. Triangle 1 is (0,1,3): normals z and -z at (0,0,0) and (1,0,0)
  const TriangleMesh opposite(tetraVertices(), tetraTriangles(), {z, -z, y, z});
  EXPECT_TRUE(sameBits(opposite.normalAt(1, Point(0.5, 0, 0)), opposite.flatNormal(1)));
  // TC12: a vertex normal pointing away from the flat normal is kept, not flipped: triangle 0,
  // (0,2,1), faces -z, but its smooth normal at (0,0,0) is the given +z
  EXPECT_TRUE(sameBits(smooth.normalAt(0, Point(0, 0, 0)), smooth.normals()[0]));
  EXPECT_EQ(smooth.flatNormal(0).z(), -1.0);
}

TEST(TriangleMeshTests, memoryBytes) {
  // TC01: at least the arrays' bytes; exactly them for arrays built to size (4 vertices with
  // normals, 4 triangles: 4·48 + 4·12 = 240)
  const TriangleMesh smooth(tetraVertices(), tetraTriangles(), std::vector<Double3>(4, {0, 0, 1}));
  EXPECT_EQ(smooth.memoryBytes(), 240u);
  EXPECT_EQ(TriangleMesh::bytesFor(4, 4, true), 240u);
}

}  // namespace
}  // namespace rt
