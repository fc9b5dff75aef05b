// Stage 2, beyond the course: Newell's teapot data (its counts, numbers and symmetries) and its
// tessellation (the course's 992 triangles, the count at other details, the bounding box, the
// normals, determinism, the refused details).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>

#include "geometries/Triangle.h"
#include "geometries/UtahTeapot.h"

namespace rt {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using Data = UtahTeapotData;

/// Control point P(i, j) of a patch (i the row, j the column).
const Double3& controlPoint(std::size_t patch, int i, int j) {
  return Data::kControlPoints[Data::kPatches[patch][4 * i + j] - 1];
}

/// The same doubles, component by component: exact, but 0 and -0 count as equal (the mirrored
/// patches' zeros are -0 where the data's are 0), unlike test::sameBits.
bool sameDoubles(const Double3& a, const Double3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

struct Box {
  Double3 lo{INFINITY}, hi{-INFINITY};
};
Box boxOf(const std::vector<Point>& points) {
  Box b;
  for (const Point& p : points) {
    const Double3& q = p.xyz();
    b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y), std::min(b.lo.z, q.z)};
    b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y), std::max(b.hi.z, q.z)};
  }
  return b;
}

TEST(UtahTeapotTests, data) {
  // TC01: 32 patches of 16 numbers, every number in 1..306; every point is used but the four
  // the publication lists without a patch (205, 206, 216, 223)
  ASSERT_EQ(Data::kPatches.size(), 32u);
  ASSERT_EQ(Data::kControlPoints.size(), 306u);
  std::set<int> unused;
  for (int k = 1; k <= 306; ++k) unused.insert(k);
  for (const auto& patch : Data::kPatches) {
    for (const std::uint16_t k : patch) {
      EXPECT_GE(k, 1);
      EXPECT_LE(k, 306);
      unused.erase(k);
    }
  }
  EXPECT_EQ(unused, (std::set<int>{205, 206, 216, 223}));
  // TC02: the control points' box: x from the handle's -3 to the spout's 3.525, y within ±2,
  // z from the bottom's 0 to the knob's 3.15
  std::vector<Point> points;
  for (const Double3& p : Data::kControlPoints) points.emplace_back(p);
  const Box box = boxOf(points);
  EXPECT_TRUE(sameDoubles(box.lo, Double3(-3, -2, 0)));
  EXPECT_TRUE(sameDoubles(box.hi, Double3(3.525, 2, 3.15)));
}

TEST(UtahTeapotTests, dataSymmetries) {
  // The symmetries check the numbers against each other, each copy written out separately.
  // TC01: the rim (0-3), body (4-11) and lid (20-27) go round the z axis in quarter turns
  // clockwise seen from above, (x, y) -> (y, -x); the bottom (28-31) counterclockwise
  const auto clockwise = [](const Double3& p) { return Double3(p.y, -p.x, p.z); };
  const auto counterclockwise = [](const Double3& p) { return Double3(-p.y, p.x, p.z); };
  struct Ring {
    std::size_t first, count;
    std::function<Double3(const Double3&)> turn;
  };
  for (const Ring& ring :
       {Ring{0, 4, clockwise}, Ring{4, 4, clockwise}, Ring{8, 4, clockwise}, Ring{20, 4, clockwise},
        Ring{24, 4, clockwise}, Ring{28, 4, counterclockwise}}) {
    for (std::size_t k = 0; k < ring.count; ++k) {
      const std::size_t patch = ring.first + k;
      const std::size_t next = ring.first + (k + 1) % ring.count;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          EXPECT_TRUE(sameDoubles(controlPoint(next, i, j), ring.turn(controlPoint(patch, i, j))))
              << "patch " << patch << " P(" << i << "," << j << ")";
    }
  }
  // TC02: the handle (12-15) and spout (16-19) patches come in pairs mirrored in y = 0, the
  // columns reversed: P'(i, j) = mirror(P(i, 3 - j))
  for (const std::size_t patch : {12u, 14u, 16u, 18u}) {
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        const Double3& p = controlPoint(patch, i, 3 - j);
        EXPECT_TRUE(sameDoubles(controlPoint(patch + 1, i, j), Double3(p.x, -p.y, p.z)))
            << "patch " << patch + 1 << " P(" << i << "," << j << ")";
      }
    }
  }
}

TEST(UtahTeapotTests, triangleCount) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the course's teapot: detail 4 gives 992 triangles, the 32 at the poles dropped, over
  // 32·25 = 800 vertices
  const TriangleMesh course = utahTeapot(4);
  EXPECT_EQ(course.triangleCount(), 992u);
  EXPECT_EQ(course.droppedTriangles(), 32u);
  EXPECT_EQ(course.vertexCount(), 800u);
  EXPECT_TRUE(course.hasNormals());
  // TC02: 64·d² − 8·d at other details, 8·d dropped, 32·(d + 1)² vertices
  for (const int d : {2, 3, 5, 8, 16}) {
    const TriangleMesh mesh = utahTeapot(d);
    const auto n = static_cast<std::size_t>(d);
    EXPECT_EQ(mesh.triangleCount(), 64 * n * n - 8 * n) << "detail " << d;
    EXPECT_EQ(mesh.triangleCount(), utahTeapotTriangleCount(d)) << "detail " << d;
    EXPECT_EQ(mesh.droppedTriangles(), 8 * n) << "detail " << d;
    EXPECT_EQ(mesh.vertexCount(), 32 * (n + 1) * (n + 1)) << "detail " << d;
  }
  static_assert(utahTeapotTriangleCount(4) == 992);
  static_assert(utahTeapotTriangleCount(125) == 999'000);
  static_assert(utahTeapotTriangleCount(kUtahTeapotMaxDetail) == 4'192'256);
  // =============== Boundary Values Tests ==================
  // TC11: detail 1: the spout's two tip patches have their four corners on one line, so 4
  // triangles more go: 52
  const TriangleMesh coarsest = utahTeapot(1);
  EXPECT_EQ(coarsest.triangleCount(), 52u);
  EXPECT_EQ(coarsest.triangleCount(), utahTeapotTriangleCount(1));
  EXPECT_EQ(coarsest.droppedTriangles(), 12u);
  // TC12: the largest detail, 256: 4,192,256 triangles (about 150 MB)
  const TriangleMesh finest = utahTeapot(kUtahTeapotMaxDetail);
  EXPECT_EQ(finest.triangleCount(), 4'192'256u);
  EXPECT_EQ(finest.vertexCount(), 2'113'568u);
}

TEST(UtahTeapotTests, refusedDetails) {
  // TC11: 0, negative numbers and 257, one above the limit, are refused naming the detail and
  // the limit
  for (const int d : {0, -1, INT_MIN, kUtahTeapotMaxDetail + 1, INT_MAX}) {
    EXPECT_THAT([d] { utahTeapot(d); },
                ThrowsMessage<std::invalid_argument>(HasSubstr(
                    "utahTeapot: detail must be a whole number from 1 to 256 (quads per patch "
                    "side), got " +
                    std::to_string(d))));
  }
}

TEST(UtahTeapotTests, boundingBox) {
  // TC01: detail 4. The corners of the patches are control points, reproduced exactly (their
  // Bernstein weights are 1 and 0): the handle's -3, the body's ±2, the bottom's 0 and the
  // knob's 3.15 are reached at such corners. The largest x is inside a patch: the spout's tip
  // column (3.3, 3.525, 3.45, 3.2) at v = 1/2, weights (1, 3, 3, 1)/8, is 3.428125; 3.525 and
  // 3.45 are not binary fractions, so that sum is exact only to rounding: within 4 ulps.
  const Box box = boxOf(utahTeapot(4).vertices());
  EXPECT_TRUE(sameDoubles(box.lo, Double3(-3, -2, 0)));
  EXPECT_EQ(box.hi.y, 2.0);
  EXPECT_EQ(box.hi.z, 3.15);
  EXPECT_DOUBLE_EQ(box.hi.x, 3.428125);
  // TC02: finer details approach the spout's true extreme, 3.43407...: below it, above the
  // detail-4 value
  const double fine = boxOf(utahTeapot(64).vertices()).hi.x;
  EXPECT_GT(fine, 3.434);
  EXPECT_LT(fine, 3.4341);
}

TEST(UtahTeapotTests, normals) {
  for (const int d : {4, 7}) {
    const TriangleMesh mesh = utahTeapot(d);
    // TC01: every vertex normal is finite and of unit length (to rounding)
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
      const Vector& n = mesh.normals()[i];
      ASSERT_TRUE(n.xyz().isFinite()) << "vertex " << i;
      EXPECT_NEAR(n.length(), 1.0, 1e-15) << "vertex " << i;
    }
    // TC02: the winding agrees with the normals: every triangle's flat normal is on the side of
    // its shading normal at its centre, and it has the bits of a Triangle of its corners
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      EXPECT_GT(mesh.flatNormal(t).dot(mesh.shadingNormal(t, 1.0 / 3, 1.0 / 3)), 0.0)
          << "detail " << d << " triangle " << t;
      const std::array<Point, 3> c = mesh.corners(t);
      EXPECT_TRUE(
          sameDoubles(mesh.flatNormal(t).xyz(), Triangle(c[0], c[1], c[2]).normal(c[0]).xyz()))
          << "detail " << d << " triangle " << t;
    }
  }
  // TC03: outward: at the middle of each body patch (4-11) the normal points away from the z
  // axis; the rim's lip (0-3) faces up at its middle, the bottom (28-31) down
  const TriangleMesh mesh = utahTeapot(4);
  const auto middle = [&](std::size_t patch) { return patch * 25 + 2 * 5 + 2; };
  for (std::size_t patch = 4; patch < 12; ++patch) {
    const Double3& p = mesh.vertices()[middle(patch)].xyz();
    const Double3& n = mesh.normals()[middle(patch)].xyz();
    EXPECT_GT(n.x * p.x + n.y * p.y, 0.0) << "patch " << patch;
  }
  for (std::size_t patch = 0; patch < 4; ++patch)
    EXPECT_GT(mesh.normals()[middle(patch)].z(), 0.99) << "patch " << patch;
  for (std::size_t patch = 28; patch < 32; ++patch)
    EXPECT_LT(mesh.normals()[middle(patch)].z(), -0.9) << "patch " << patch;
  // =============== Boundary Values Tests ==================
  // TC11: at the poles, where ∂P/∂u vanishes, the limit normal: +z on the knob, -z under the
  // bottom, at each of the 5 pole samples of the lid's (20-23) and bottom's (28-31) patches
  for (std::size_t j = 0; j < 5; ++j) {
    for (std::size_t patch = 20; patch < 24; ++patch)
      EXPECT_NEAR(mesh.normals()[patch * 25 + j].z(), 1.0, 1e-15) << "patch " << patch;
    for (std::size_t patch = 28; patch < 32; ++patch)
      EXPECT_NEAR(mesh.normals()[patch * 25 + j].z(), -1.0, 1e-15) << "patch " << patch;
  }
}

TEST(UtahTeapotTests, deterministic) {
  // TC01: two tessellations at the same detail are the same bits
  const TriangleMesh a = utahTeapot(6);
  const TriangleMesh b = utahTeapot(6);
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  EXPECT_EQ(a.triangles(), b.triangles());
  for (std::size_t i = 0; i < a.vertexCount(); ++i) {
    EXPECT_TRUE(sameDoubles(a.vertices()[i].xyz(), b.vertices()[i].xyz())) << "vertex " << i;
    EXPECT_TRUE(sameDoubles(a.normals()[i].xyz(), b.normals()[i].xyz())) << "normal " << i;
  }
}

}  // namespace
}  // namespace rt
