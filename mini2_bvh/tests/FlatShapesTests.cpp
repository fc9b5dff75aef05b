// mini2: FlatShapes, the triangles' and polygons' records that the hierarchies' leaves and the
// light buffers test rays against. Its roots are stage 3's intersectRoots, bit for bit, with each
// instruction set (Scalar, SSE2, and AVX2 where the processor has it), on random rays of every
// kind (aimed inside, at vertices, at edges and just beside them, from points of the shapes,
// parallel to the plane, along edges) against triangles and polygons of every kind (slivers,
// far from the origin, slightly non-planar quads, nearly straight vertices, 5 to 8 vertices);
// awayFromPlane answers early only where planeT is NaN; the edges' lines (edgeDistanceRange,
// shortestEdge) on shapes worked out by hand; the records themselves.
// Not here: the closest hits of a BVH whose leaves use FlatShapes against the linear scan, which
// EquivalenceTests checks (TC02, TC03, TC04: triangles and rectangles among the other shapes;
// TC06: coplanar rectangles with exact ties).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bvh/FlatShapes.h"

#include "RandomScenes.h"

namespace rt {
namespace {

using Simd = FlatShapes::Simd;
using test::Random;

const char* simdName(Simd simd) {
  return simd == Simd::Avx2 ? "Avx2" : simd == Simd::Sse2 ? "Sse2" : "Scalar";
}

/// A double's bits, for messages: 0x3ff0000000000000 (1).
std::string bits(double x) {
  std::ostringstream os;
  os << "0x" << std::hex << std::bit_cast<std::uint64_t>(x) << " (" << std::hexfloat << x << ")";
  return os.str();
}

std::string hex(const Double3& p) {
  std::ostringstream os;
  os << std::hexfloat << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return os.str();
}

std::string describe(const Roots& roots) {
  std::string s = std::to_string(roots.size()) + " roots";
  for (const double t : roots) s += " " + bits(t);
  return s;
}

/// The same count and the same bits of every root.
::testing::AssertionResult sameRoots(const Roots& expected, const Roots& got) {
  bool same = expected.size() == got.size();
  for (int i = 0; same && i < expected.size(); ++i)
    same = std::bit_cast<std::uint64_t>(expected[i]) == std::bit_cast<std::uint64_t>(got[i]);
  if (same) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "stage 3: " << describe(expected) << ", FlatShapes: " << describe(got);
}

/// A triangle's or a polygon's vertices.
std::span<const Point> verticesOf(const Geometry& g) {
  if (const auto* t = std::get_if<Triangle>(&g)) return t->vertices();
  return std::get<Polygon>(g).vertices();
}

/// Two unit vectors u, v spanning a random plane, and its normal u × v.
struct Frame {
  Double3 u, v, n;
};

Frame randomFrame(Random& random) {
  const Double3 n = random.direction();
  const Double3 a = std::abs(n.x) < 0.5 ? Double3(1, 0, 0) : Double3(0, 1, 0);
  const Double3 c = n.cross(a);
  const Double3 u = c / std::sqrt(c.lengthSquared());
  return {u, n.cross(u), n};
}

/// The point at (a, b) of the plane through o spanned by f.u and f.v.
Double3 at(const Double3& o, const Frame& f, double a, double b) { return o + f.u * a + f.v * b; }

/// A vector with a on axis i and b on axis j (i != j).
Double3 onAxes(int i, int j, double a, double b) {
  double c[3] = {0, 0, 0};
  c[i] = a;
  c[j] = b;
  return Double3(c[0], c[1], c[2]);
}

/// The vertices in the other order (the other winding) half of the time.
std::vector<Point> anyWinding(Random& random, std::vector<Point> vertices) {
  if (random.chance(0.5)) std::reverse(vertices.begin(), vertices.end());
  return vertices;
}

/// Convex vertices on an ellipse of radii (ra, rb) around o in the frame's plane, n of them, at
/// angles spread so that every turn is well away from straight.
std::vector<Point> onEllipse(Random& random, const Double3& o, const Frame& f, double ra, double rb,
                             int n) {
  std::vector<Point> vertices;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * std::numbers::pi * (k + random.uniform(0.1, 0.9)) / n;
    vertices.emplace_back(at(o, f, ra * std::cos(angle), rb * std::sin(angle)));
  }
  return anyWinding(random, std::move(vertices));
}

/// Flat shapes of every kind stage 2 accepts (kind % 9; its constructors refuse concave
/// polygons, so there are none, and the few random shapes refused are left out):
/// 0 a random triangle; 1 a triangle far from the origin (coordinates up to 2·10^5, sizes 0.01
/// to 10); 2 a sliver (its apex 10^-5 to 10^-11 of its base above the base, anywhere along
/// it); 3 an axis-aligned rectangle on integers (exactly flat, sometimes at 10^6); 4 a tilted
/// rectangle on integers; 5 a convex quad in a random plane, half of them with the fourth vertex
/// 5·10^-13 off the plane of the first three (within stage 2's 2^-40); 6 a quad with a nearly
/// straight vertex (turning by 10^-6 to 3·10^-12); 7 a polygon of 5 to 8 vertices (some with a
/// nearly straight vertex); 8 a triangle given as a Polygon of three vertices.
Geometry randomFlatShape(Random& random, int kind) {
  const Aabb box(Double3(-20), Double3(20));
  const Double3 c = random.inBox(box);
  const double s = random.uniform(0.5, 5);
  const Frame f = randomFrame(random);
  switch (kind % 9) {
    case 0:
      return random.triangleAround(c, s);
    case 1: {
      const Double3 far = c * std::pow(10.0, random.uniform(1, 4));
      return random.triangleAround(far, std::pow(10.0, random.uniform(-2, 1)));
    }
    case 2: {
      const double h = s * std::pow(10.0, -random.uniform(5, 11));
      const double w = random.chance(0.3) ? 0.5 : random.uniform(-0.5, 1.5);
      return Triangle(Point(c), Point(at(c, f, s, 0)), Point(at(c, f, s * w, h)));
    }
    case 3: {
      const double reach = random.chance(0.3) ? 1e6 : 20;
      const Double3 q = random.inCube(-reach, reach);
      const Double3 p(std::round(q.x), std::round(q.y), std::round(q.z));
      const int i = random.integer(0, 2), j = (i + random.integer(1, 2)) % 3;
      const double a = random.integer(1, 4), b = random.integer(1, 4);
      return Polygon(
          anyWinding(random, {Point(p), Point(p + onAxes(i, j, a, 0)),
                              Point(p + onAxes(i, j, a, b)), Point(p + onAxes(i, j, 0, b))}));
    }
    case 4: {  // p, p + u, p + u + v, p + v with u·v = −abk + abk = 0
      const Double3 p(std::round(c.x), std::round(c.y), std::round(c.z));
      const double a = random.integer(1, 3), b = random.integer(-2, 2);
      const double k = random.integer(-1, 1), h = random.integer(1, 2);
      const Double3 u(a, b, 0), v(-b * k, a * k, h);
      return Polygon(anyWinding(random, {Point(p), Point(p + u), Point(p + u + v), Point(p + v)}));
    }
    case 5: {
      std::vector<Point> v = onEllipse(random, c, f, s, s * random.uniform(0.3, 1), 4);
      if (random.chance(0.5)) v[3] = Point(v[3].xyz() + f.n * (5e-13 * random.sign()));
      return Polygon(std::move(v));
    }
    case 6: {
      const double e = std::pow(10.0, -random.uniform(6, 11.5));
      return Polygon(anyWinding(random, {Point(at(c, f, 0, 0)), Point(at(c, f, s, -e * s)),
                                         Point(at(c, f, 2 * s, 0)), Point(at(c, f, s, s))}));
    }
    case 7: {
      if (random.chance(0.3)) {
        const double e = std::pow(10.0, -random.uniform(6, 11.5));
        return Polygon(anyWinding(
            random, {Point(at(c, f, 0, 0)), Point(at(c, f, s, -e * s)), Point(at(c, f, 2 * s, 0)),
                     Point(at(c, f, 2 * s, 2 * s)), Point(at(c, f, 0, 2 * s))}));
      }
      const double rb = s * random.uniform(0.3, 1);
      return Polygon(onEllipse(random, c, f, s, rb, random.integer(5, 8)));
    }
    default:
      return Polygon(random.cornersAround(c, s));
  }
}

/// Shapes as a scene holds them: flat shapes of every kind with a sphere or a plane among them
/// now and then, and the flat ones' numbers listed as Bvh::makeFlatShapes lists them.
struct FlatScene {
  std::vector<Geometry> shapes;
  std::vector<std::uint32_t> flat;
  int rejected = 0;  ///< shapes stage 2 refused (then none is added for that kind this time)
};

FlatScene randomFlatScene(std::uint64_t seed, int count) {
  Random random(seed);
  FlatScene scene;
  for (int i = 0; i < count; ++i) {
    if (i % 7 == 3) scene.shapes.emplace_back(Sphere(Point(random.direction() * 10), 1));
    if (i % 11 == 5) scene.shapes.emplace_back(Plane(Point(0, 0, 1), Vector(random.direction())));
    try {
      scene.shapes.push_back(randomFlatShape(random, i));
    } catch (const std::invalid_argument&) {
      ++scene.rejected;
    }
  }
  for (std::uint32_t i = 0; i < scene.shapes.size(); ++i)
    if (FlatShapes::isFlat(scene.shapes[i])) scene.flat.push_back(i);
  return scene;
}

/// A ray, unless dir is one that Vector refuses (every component within 2^-40 of 0).
std::optional<Ray> rayAlong(const Double3& head, const Double3& dir) {
  if (dir.isZero()) return std::nullopt;
  return Ray(Point(head), Vector(dir));
}

/// Random rays at a flat shape of centroid c and size `size` (kind % 11): 0 from around it to a
/// point inside it; 1 to a vertex; 2 to a point of an edge (its middle a third of the time);
/// 3 to a point of the plane just beside an edge (10^-6 to 10^-16 of the size, inside or
/// outside); 4 from a point of the shape (or 10^-15 of the size off it), any direction; 5
/// parallel to the plane, or tilted off it by 0, 2^-41, 2^-40, 2^-39 or 10^-10 (alignZero's
/// threshold); 6 along an edge's line (from before its first vertex, or from the vertex), or
/// crossing the plane on the edge from just above it; 7 anywhere around, any direction; 8 from
/// a point of integers to a half-integer point of an edge (exactly on the edges of the integer
/// rectangles); 9 from 10^2 to 10^6 sizes away (large head coordinates) to a point inside it,
/// or in its plane beyond a vertex (outwards from the centroid by 10^-9 to 10^-15 of the size);
/// 10 to a point of the plane beside an edge, inside or outside, placed so that the edge's
/// s = dir·(a × b) is 2^-40·|a × b| within ±3·10^-4 of it: stage 3's threshold, where the
/// decision rests on the rounding of s, a sum that cancels nearly to 0 (s is linear in the
/// distance to the edge's line: its ratio at 10^-6 of the size gives the distance). Summing s in
/// another order changes dozens of these decisions; |a × b|², which does not cancel, is rounded
/// 10^12 times finer than this window, and no ray finds its order.
std::optional<Ray> randomRay(Random& random, int kind, std::span<const Point> vs, const Double3& n,
                             const Double3& c, double size) {
  const auto vertex = [&](std::size_t j) { return vs[j % vs.size()].xyz(); };
  const std::size_t j = static_cast<std::size_t>(random.integer(0, int(vs.size()) - 1));
  const auto pointIn = [&] {
    Double3 sum;
    double total = 0;
    for (const Point& v : vs) {
      const double w = random.uniform(0, 1);
      sum = sum + v.xyz() * w;
      total += w;
    }
    return sum / total;
  };
  const auto edgePoint = [&](double w) { return vertex(j) + (vertex(j + 1) - vertex(j)) * w; };
  const Double3 toAround = random.direction();
  const Double3 around = c + toAround * (size * random.uniform(0.5, 3));
  switch (kind % 11) {
    case 0:
      return rayAlong(around, pointIn() - around);
    case 1:
      return rayAlong(around, vertex(j) - around);
    case 2:
      return rayAlong(around, edgePoint(random.chance(0.3) ? 0.5 : random.uniform(0, 1)) - around);
    case 3: {
      const Double3 across = (vertex(j + 1) - vertex(j)).cross(n);
      const double small = size * std::pow(10.0, -random.uniform(6, 16));
      const double shift = small * random.sign() / std::sqrt(across.lengthSquared());
      return rayAlong(around, edgePoint(random.uniform(0, 1)) + across * shift - around);
    }
    case 4: {
      Double3 head = pointIn();
      if (random.chance(0.3)) head = head + n * (size * 1e-15 * random.integer(-3, 3));
      return rayAlong(head, random.direction());
    }
    case 5: {
      const Double3 toHead = random.direction();
      Double3 head = c + toHead * (size * random.uniform(0, 2));
      if (random.chance(0.3)) head = head - n * n.dot(head - c);  // in the plane
      const double tilts[] = {0, 0x1p-41, 0x1p-40, 0x1p-39, 1e-10};
      const double magnitude = tilts[random.integer(0, 4)];
      const double tilt = magnitude * random.sign();
      return rayAlong(head, n.cross(random.direction()) + n * tilt);
    }
    case 6: {
      const Double3 edge = vertex(j + 1) - vertex(j);
      switch (random.integer(0, 2)) {
        case 0:
          return rayAlong(vertex(j) - edge * random.uniform(0.1, 1), edge);
        case 1:
          return rayAlong(vertex(j), random.chance(0.5) ? edge : edge * -1.0);
        default: {
          const Double3 head = edgePoint(random.uniform(-0.5, 1.5)) + n * (size * 1e-3);
          return rayAlong(head, edgePoint(random.uniform(0, 1)) - head);
        }
      }
    }
    case 7: {
      const Double3 head = random.inBox(c - Double3(3 * size), c + Double3(3 * size));
      return rayAlong(head, random.direction());
    }
    case 8: {
      const Double3 head(std::round(around.x), std::round(around.y), std::round(around.z));
      const Double3 mid = edgePoint(0.5) * 2;
      const Double3 target =
          Double3(std::round(mid.x) / 2, std::round(mid.y) / 2, std::round(mid.z) / 2);
      return rayAlong(head, target - head);
    }
    case 9: {
      const Double3 toHead = random.direction();
      const Double3 head = c + toHead * (size * std::pow(10.0, random.uniform(2, 6)));
      const Double3 target =
          random.chance(0.5) ? pointIn()
                             : vertex(j) + (vertex(j) - c) * std::pow(10.0, -random.uniform(9, 15));
      return rayAlong(head, target - head);
    }
    default: {
      const Double3 a = vertex(j) - around, b = vertex(j + 1) - around, cross = a.cross(b);
      const Double3 across = (vertex(j + 1) - vertex(j)).cross(n);
      const Double3 unit = across / std::sqrt(across.lengthSquared());
      const Double3 on = edgePoint(random.uniform(0.1, 0.9));
      const auto ratio = [&](double shift) {
        const Double3 d = on + unit * shift - around;
        return d.dot(cross) / std::sqrt(d.lengthSquared() * cross.lengthSquared());
      };
      const double probe = size * 1e-6;
      const double jitter = 1 + random.uniform(-3e-4, 3e-4);
      const double shift = std::abs(0x1p-40 * probe / ratio(probe)) * jitter * random.sign();
      return rayAlong(around, on + unit * shift - around);
    }
  }
}

/// Every flat shape of a random scene against random rays of every kind: FlatShapes with `simd`
/// gives stage 3's roots, bit for bit. Both outcomes must be common: hits, and rays that cross
/// the plane (planeT > 0) but pass beside the shape.
void expectStage3Roots(Simd simd) {
  const FlatScene scene = randomFlatScene(2024, 2700);
  // Nearly all of them accepted: 2514 flat shapes from this seed on every compiler and standard
  // library (the numbers of support/TestRandom.h, drawn one per statement), so a count that
  // differs says the scene does, here or on another platform.
  ASSERT_EQ(scene.flat.size(), 2514u) << scene.rejected << " shapes refused by stage 2";
  const FlatShapes flats(Primitives(std::span<const Geometry>(scene.shapes)), scene.flat, simd);
  ASSERT_EQ(flats.size(), scene.flat.size());
  EXPECT_EQ(flats.simd(), simd);
  Random random(77);
  int checked = 0, hits = 0, beside = 0, failures = 0;
  int kindHits[11] = {}, kindBeside[11] = {};
  for (std::uint32_t k = 0; k < flats.size(); ++k) {
    const Geometry& g = scene.shapes[scene.flat[k]];
    const std::span<const Point> vs = verticesOf(g);
    const FlatShape& f = flats.record(k);
    Double3 c;
    for (const Point& v : vs) c = c + v.xyz();
    c = c / static_cast<double>(vs.size());
    double size = 0;
    for (const Point& v : vs) size = std::max(size, std::sqrt((v.xyz() - c).lengthSquared()));
    for (int i = 0; i < 55; ++i) {
      const int kind = i % 11;
      const std::optional<Ray> ray = randomRay(random, kind, vs, f.n, c, size);
      if (!ray) continue;
      const Roots expected = intersectRoots(g, *ray);
      const Roots got = flats.roots(k, *ray);
      ++checked;
      if (!expected.empty()) {
        ++hits, ++kindHits[kind];
      } else if (alignZero(planeT(f.q, f.n, *ray)) > 0) {
        ++beside, ++kindBeside[kind];
      }
      const ::testing::AssertionResult same = sameRoots(expected, got);
      if (!same && ++failures <= 5) {
        std::string shape;
        for (const Point& v : vs) shape += " " + hex(v.xyz());
        ADD_FAILURE() << simdName(simd) << ": " << same.message() << "\n  shape " << scene.flat[k]
                      << " (" << vs.size() << " vertices):" << shape << "\n  ray head "
                      << hex(ray->head().xyz()) << " direction " << hex(ray->direction().xyz())
                      << " (kind " << kind << ")";
      }
    }
  }
  ::testing::Test::RecordProperty("flatShapes", static_cast<int>(flats.size()));
  ::testing::Test::RecordProperty("rays", checked);
  EXPECT_EQ(failures, 0) << "of " << checked << " rays";
  EXPECT_GT(checked, 130000);
  EXPECT_GT(hits, checked / 6);
  EXPECT_GT(beside, checked / 3);
  // The rays beside edges, at half-integer edge points, from far away and at the threshold
  // decide both ways; those at vertices, edge points and along edges mostly miss (an edge's s
  // within the threshold).
  for (const int kind : {3, 8, 9, 10}) {
    EXPECT_GT(kindHits[kind], 2000) << "kind " << kind;
    EXPECT_GT(kindBeside[kind], 2000) << "kind " << kind;
  }
  for (const int kind : {1, 2, 6}) EXPECT_GT(kindBeside[kind], 2000) << "kind " << kind;
}

TEST(FlatShapesTests, sameRootsAsStage3Scalar) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: stage 3's loop for every shape: 2500+ shapes of every kind, 55 rays of 11 kinds each
  expectStage3Roots(Simd::Scalar);
}

TEST(FlatShapesTests, sameRootsAsStage3Sse2) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: two edges per SSE2 vector for 3 and 4 vertices (stage 3's loop beyond), the same rays
  expectStage3Roots(Simd::Sse2);
}

TEST(FlatShapesTests, sameRootsAsStage3Avx2) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: four edges per AVX2 vector, the same rays; only on a processor with AVX2
  if (FlatShapes::bestSimd() != Simd::Avx2)
    GTEST_SKIP() << "this processor (or build) has no AVX2: FlatShapes' AVX2 path not tested";
  expectStage3Roots(Simd::Avx2);
}

/// The instruction sets this processor runs: Scalar, Sse2, and Avx2 where bestSimd says so.
std::vector<Simd> runnableSimds() {
  std::vector<Simd> simds{Simd::Scalar, Simd::Sse2};
  if (FlatShapes::bestSimd() == Simd::Avx2) simds.push_back(Simd::Avx2);
  return simds;
}

/// The vertices starting from vertex r, in the other order first when reversed.
std::vector<Point> rotated(std::vector<Point> vertices, std::size_t r, bool reversed) {
  if (reversed) std::reverse(vertices.begin(), vertices.end());
  std::rotate(vertices.begin(), vertices.begin() + static_cast<std::ptrdiff_t>(r), vertices.end());
  return vertices;
}

TEST(FlatShapesTests, thresholdTiesAsStage3) {
  // Shapes in the plane x = 1 with the edge (1, −1, 0)–(1, 1, 0), and rays from the origin along
  // (1, 0, dz), which meet the plane at t = 1, at (1, 0, dz). For that edge, from the head,
  // a = (1, −1, 0), b = (1, 1, 0) (or the other way round), c = a × b = (0, 0, ±2), |c|² = 4 and
  // s = dir·c = ±2·dz, all exact: dz = 2^-40 makes s² = 2^-78 = 2^-80·|c|², stage 3's threshold
  // itself (within it: a miss); one ulp more is a hit at t = 1 (the other edges' s are 2 or
  // more, of the same sign); one ulp less, 0 (through the edge) and negative dz are misses.
  // Every winding and every first vertex, so that the edge takes every lane; a triangle both as
  // a Triangle and as a Polygon; a pentagon (stage 3's loop). Scalar, Sse2, and Avx2 where the
  // processor has it (sameRootsAsStage3Avx2 reports the skip).
  const std::vector<Point> square{Point(1, -1, 0), Point(1, 1, 0), Point(1, 1, 2), Point(1, -1, 2)};
  const std::vector<Point> triangle{Point(1, -1, 0), Point(1, 1, 0), Point(1, 0, 2)};
  const std::vector<Point> pentagon{Point(1, -1, 0), Point(1, 1, 0), Point(1, 2, 1), Point(1, 0, 3),
                                    Point(1, -2, 1)};
  std::vector<Geometry> shapes;
  for (const std::vector<Point>* vs : {&square, &triangle, &pentagon})
    for (std::size_t r = 0; r < vs->size(); ++r)
      for (const bool reversed : {false, true}) {
        const std::vector<Point> v = rotated(*vs, r, reversed);
        if (v.size() == 3) shapes.emplace_back(Triangle(v[0], v[1], v[2]));
        shapes.emplace_back(Polygon(v));
      }
  ASSERT_EQ(shapes.size(), 8u + 12 + 10);
  std::vector<std::uint32_t> all(shapes.size());
  for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  const double threshold = 0x1p-40;
  struct Case {
    double dz;
    bool hit;
  };
  const Case cases[] = {
      // =============== Boundary Values Tests ==================
      {threshold, false},                        // TC11: s² exactly at the threshold: a miss
      {std::nextafter(threshold, 1.0), true},    // TC12: one ulp beyond it: a hit at t = 1
      {std::nextafter(threshold, 0.0), false},   // TC13: one ulp within it: a miss
      {0, false},                                // TC14: exactly through the edge: s = 0, a miss
      {-threshold, false},                       // TC15: outside, at the threshold: a miss
      {-std::nextafter(threshold, 1.0), false},  // TC16: outside, beyond it: signs differ, a miss
      // ============ Equivalence Partitions Tests ==============
      {0x1p-30, true},    // TC01: well inside the edge: a hit at t = 1
      {-0x1p-30, false},  // TC02: well outside it: a miss
  };
  for (const Simd simd : runnableSimds()) {
    const FlatShapes flats(Primitives(std::span<const Geometry>(shapes)), all, simd);
    for (const Case& c : cases) {
      const Ray ray = Ray::withUnitDirection(Point(0, 0, 0), Vector(1, 0, c.dz));
      for (std::uint32_t k = 0; k < flats.size(); ++k) {
        const Roots expected = intersectRoots(shapes[k], ray);
        ASSERT_EQ(expected.size(), c.hit ? 1 : 0) << "stage 3, shape " << k << " dz " << bits(c.dz);
        if (c.hit) {
          ASSERT_EQ(expected[0], 1);
        }
        EXPECT_TRUE(sameRoots(expected, flats.roots(k, ray)))
            << simdName(simd) << ", shape " << k << " (" << verticesOf(shapes[k]).size()
            << " vertices), dz " << bits(c.dz);
      }
    }
  }
}

TEST(FlatShapesTests, awayFromPlaneOnlyWherePlaneTIsNaN) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: random planes (points up to 100 from the origin, unit normals), heads at 10^-16 to
  // 100 from the plane on either side (or on it), directions anywhere or within 10^-9 to 10^-16
  // of parallel: wherever awayFromPlane says yes, stage 3's planeT is NaN; and it says yes for
  // about half of them
  Random random(5);
  int away = 0, towards = 0;
  const Aabb box(Double3(-100), Double3(100));
  for (int i = 0; i < 40000; ++i) {
    const Double3 q = random.inBox(box);
    const Double3 n = random.direction();
    const Double3 along = n.cross(random.direction());
    double h = std::pow(10.0, random.uniform(-16, 2));
    h *= random.sign();
    if (i % 10 == 0) h = 0;
    const Double3 head = q + along * random.uniform(0, 10) + n * h;
    Double3 dir = random.direction();
    if (i % 3 == 0) {
      const double tilt = std::pow(10.0, -random.uniform(9, 16));
      dir = along + n * (tilt * random.sign());
    }
    if (dir.isZero()) continue;
    const Ray ray{Point(head), Vector(dir)};
    if (FlatShapes::awayFromPlane(q, n, ray)) {
      ++away;
      EXPECT_TRUE(std::isnan(planeT(q, n, ray)))
          << "plane " << hex(q) << " " << hex(n) << " ray " << hex(head) << " " << hex(dir);
    } else if (std::abs(h) >= 1e-6 && std::abs(n.dot(ray.direction().xyz())) >= 1e-3 &&
               (n.dot(ray.direction().xyz()) > 0) != (h > 0)) {
      // TC02: a head well off the plane, heading towards it: not away, and a root ahead
      ++towards;
      EXPECT_GT(planeT(q, n, ray), 0);
    }
  }
  EXPECT_GT(away, 15000);
  EXPECT_GT(towards, 4000);
  // TC03: the plane z = 0: from z = 1 upwards, away (planeT NaN); from z = 1 downwards, not away,
  // t = 1; from z = −1 downwards away, upwards not (t = 1); the same with an oblique direction
  const Double3 q(0, 0, 0), n(0, 0, 1);
  const auto rayZ = [](double z, const Double3& dir) {
    return Ray(Point(0.5, 0.5, z), Vector(dir));
  };
  EXPECT_TRUE(FlatShapes::awayFromPlane(q, n, rayZ(1, Double3(0, 0, 1))));
  EXPECT_TRUE(std::isnan(planeT(q, n, rayZ(1, Double3(0, 0, 1)))));
  EXPECT_FALSE(FlatShapes::awayFromPlane(q, n, rayZ(1, Double3(0, 0, -1))));
  EXPECT_EQ(planeT(q, n, rayZ(1, Double3(0, 0, -1))), 1);
  EXPECT_TRUE(FlatShapes::awayFromPlane(q, n, rayZ(-1, Double3(0, 0, -1))));
  EXPECT_FALSE(FlatShapes::awayFromPlane(q, n, rayZ(-1, Double3(0, 0, 1))));
  EXPECT_EQ(planeT(q, n, rayZ(-1, Double3(0, 0, 1))), 1);
  EXPECT_TRUE(FlatShapes::awayFromPlane(q, n, rayZ(2, Double3(3, -4, 1))));
  EXPECT_FALSE(FlatShapes::awayFromPlane(q, n, rayZ(2, Double3(3, -4, -1))));
  // =============== Boundary Values Tests ==================
  // TC11: a head exactly on the plane: not away, up or down (planeT's roundoff test answers)
  EXPECT_FALSE(FlatShapes::awayFromPlane(q, n, rayZ(0, Double3(0, 0, 1))));
  EXPECT_FALSE(FlatShapes::awayFromPlane(q, n, rayZ(0, Double3(0, 0, -1))));
  // TC12: a direction exactly parallel to the plane, above and below it: not away
  EXPECT_FALSE(FlatShapes::awayFromPlane(q, n, rayZ(1, Double3(1, 0, 0))));
  EXPECT_FALSE(FlatShapes::awayFromPlane(q, n, rayZ(-1, Double3(0, 1, 0))));
  // TC13: the smallest steps: the head 2^-1074 above, going up by 2^-60 (alignZero makes planeT
  // NaN): away; going down by as little: not away
  const Ray up =
      Ray::withUnitDirection(Point(0, 0, 0x1p-1074), Vector::unchecked(Double3(1, 0, 0x1p-60)));
  const Ray down =
      Ray::withUnitDirection(Point(0, 0, 0x1p-1074), Vector::unchecked(Double3(1, 0, -0x1p-60)));
  EXPECT_TRUE(FlatShapes::awayFromPlane(q, n, up));
  EXPECT_TRUE(std::isnan(planeT(q, n, up)));
  EXPECT_FALSE(FlatShapes::awayFromPlane(q, n, down));
}

/// The record of shapes[0], built as the hierarchies build it.
FlatShape recordOf(const Geometry& g) {
  const std::vector<Geometry> shapes{g};
  const std::uint32_t first = 0;
  return FlatShapes(Primitives(std::span<const Geometry>(shapes)), std::span(&first, 1)).record(0);
}

TEST(FlatShapesTests, edgeDistanceRange) {
  // ============ Equivalence Partitions Tests ==============
  // The right triangle (0,0,0), (2,0,0), (0,2,0), wound about +z. Its edges' inward normals:
  // edge 0 (along x) (0, 1, 0) with ef 0, edge 1 (the hypotenuse) (−a, −a, 0) with a = 1/√2
  // rounded and ef = −2a, edge 2 (along y) (1, 0, 0) with ef 0; lane 3 repeats edge 0. So at
  // (x, y, 0) the distances are y, √2 − (x + y)/√2 and x.
  const FlatShape t = recordOf(Triangle(Point(0, 0, 0), Point(2, 0, 0), Point(0, 2, 0)));
  EXPECT_EQ(t.n.z, 1);
  EXPECT_EQ(t.ex[0], 0);
  EXPECT_EQ(t.ey[0], 1);
  EXPECT_EQ(t.ez[0], 0);
  EXPECT_EQ(t.ef[0], 0);
  EXPECT_DOUBLE_EQ(t.ex[1], -1 / std::sqrt(2.0));
  EXPECT_EQ(t.ey[1], t.ex[1]);
  EXPECT_EQ(t.ez[1], 0);
  EXPECT_EQ(t.ef[1], 2 * t.ex[1]);
  EXPECT_EQ(t.ex[2], 1);
  EXPECT_EQ(t.ey[2], 0);
  EXPECT_EQ(t.ez[2], 0);
  EXPECT_EQ(t.ef[2], 0);
  EXPECT_EQ(t.ex[3], t.ex[0]);
  EXPECT_EQ(t.ey[3], t.ey[0]);
  EXPECT_EQ(t.ez[3], t.ez[0]);
  EXPECT_EQ(t.ef[3], t.ef[0]);
  using Range = std::array<double, 2>;
  // TC01: the centroid (2/3, 2/3): 2/3 from the legs, √2/3 from the hypotenuse
  const Range centroid = edgeDistanceRange(t, Double3(2.0 / 3, 2.0 / 3, 0));
  EXPECT_NEAR(centroid[0], std::sqrt(2.0) / 3, 1e-15);
  EXPECT_EQ(centroid[1], 2.0 / 3);
  // TC02: (1, −1), outside edge 0 by 1: −1 and √2 (= −ef[1] exactly: −a − (−a) cancels)
  const Range outside = edgeDistanceRange(t, Double3(1, -1, 0));
  EXPECT_EQ(outside[0], -1);
  EXPECT_EQ(outside[1], -t.ef[1]);
  EXPECT_DOUBLE_EQ(outside[1], std::sqrt(2.0));
  // TC03: (0.5, 0.25), inside: 0.25 from edge 0, 0.5 from edge 2
  const Range inside = edgeDistanceRange(t, Double3(0.5, 0.25, 0));
  EXPECT_EQ(inside[0], 0.25);
  EXPECT_NEAR(inside[1], std::sqrt(2.0) - 0.75 / std::sqrt(2.0), 1e-15);
  // The square (1,0,0), (1,2,0), (1,2,2), (1,0,2) in the plane x = 1, wound about +x: its edges'
  // inward normals (0,0,1), (0,−1,0), (0,0,−1), (0,1,0), ef 0, −2, −2, 0: at (1, y, z) the
  // distances are z, 2 − y, 2 − z and y, all exact
  const FlatShape s =
      recordOf(Polygon({Point(1, 0, 0), Point(1, 2, 0), Point(1, 2, 2), Point(1, 0, 2)}));
  const double sx[] = {0, 0, 0, 0}, sy[] = {0, -1, 0, 1}, sz[] = {1, 0, -1, 0},
               sf[] = {0, -2, -2, 0};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(s.ex[k], sx[k]) << k;
    EXPECT_EQ(s.ey[k], sy[k]) << k;
    EXPECT_EQ(s.ez[k], sz[k]) << k;
    EXPECT_EQ(s.ef[k], sf[k]) << k;
  }
  // TC04: the centre (1, 1, 1): 1 from every edge
  EXPECT_EQ(edgeDistanceRange(s, Double3(1, 1, 1)), (Range{1, 1}));
  // TC05: (1, 3, 1), outside edge 1 by 1: −1 and 3 (edge 3)
  EXPECT_EQ(edgeDistanceRange(s, Double3(1, 3, 1)), (Range{-1, 3}));
  // TC06: (1, −5, 0.5), far outside edge 3: −5, and 7 from edge 1
  EXPECT_EQ(edgeDistanceRange(s, Double3(1, -5, 0.5)), (Range{-5, 7}));
  // TC07: (1, 3, 3), outside two edges (a corner's region): −1 twice, 3 twice
  EXPECT_EQ(edgeDistanceRange(s, Double3(1, 3, 3)), (Range{-1, 3}));
  // =============== Boundary Values Tests ==================
  // TC11: the triangle's vertices: (2, 0) is on edges 0 and 1 (0 from both; 2 from edge 2);
  // (0, 0) on edges 0 and 2, √2 from the hypotenuse
  EXPECT_EQ(edgeDistanceRange(t, Double3(2, 0, 0)), (Range{0, 2}));
  EXPECT_EQ(edgeDistanceRange(t, Double3(0, 0, 0)), (Range{0, -t.ef[1]}));
  // TC12: the hypotenuse's middle (1, 1): exactly 0 from it (−a − a + 2a), 1 from the legs
  EXPECT_EQ(edgeDistanceRange(t, Double3(1, 1, 0)), (Range{0, 1}));
  // TC13: the square's vertex (1, 2, 2): 0 from edges 1 and 2, 2 from the others
  EXPECT_EQ(edgeDistanceRange(s, Double3(1, 2, 2)), (Range{0, 2}));
  // TC14: the square wound the other way about the other normal: the same four lines (the
  // inward normals do not depend on the winding), in the other order
  const FlatShape r =
      recordOf(Polygon({Point(1, 0, 2), Point(1, 2, 2), Point(1, 2, 0), Point(1, 0, 0)}));
  EXPECT_EQ(r.n.x, -1);
  EXPECT_EQ(edgeDistanceRange(r, Double3(1, 1, 1)), (Range{1, 1}));
  EXPECT_EQ(edgeDistanceRange(r, Double3(1, -5, 0.5)), (Range{-5, 7}));
  EXPECT_EQ(r.ez[0], -1);
  EXPECT_EQ(r.ef[0], -2);  // edge 0 now runs along z = 2
}

TEST(FlatShapesTests, shortestEdge) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the right triangle of legs 2: 2 (the hypotenuse is 2√2)
  EXPECT_EQ(recordOf(Triangle(Point(0, 0, 0), Point(2, 0, 0), Point(0, 2, 0))).shortestEdge, 2);
  // TC02: the 3-4-5 triangle, its shortest edge the last (closing) one: 3
  EXPECT_EQ(recordOf(Triangle(Point(0, 0, 0), Point(4, 0, 0), Point(0, 3, 0))).shortestEdge, 3);
  // TC03: the square of side 2: 2; a rectangle 3 by 1: 1
  EXPECT_EQ(recordOf(Polygon({Point(1, 0, 0), Point(1, 2, 0), Point(1, 2, 2), Point(1, 0, 2)}))
                .shortestEdge,
            2);
  EXPECT_EQ(recordOf(Polygon({Point(0, 0, 5), Point(3, 0, 5), Point(3, 1, 5), Point(0, 1, 5)}))
                .shortestEdge,
            1);
  // TC04: a quad of edges 4, 4, 5 and 1 (its shortest the closing edge (0,1,0) → (0,0,0)): 1
  EXPECT_EQ(recordOf(Polygon({Point(0, 0, 0), Point(4, 0, 0), Point(4, 4, 0), Point(0, 1, 0)}))
                .shortestEdge,
            1);
  // =============== Boundary Values Tests ==================
  // TC11: two shortest edges of one length, neither along an axis: 5, 5 and 6 give 5 (√25)
  EXPECT_EQ(recordOf(Triangle(Point(0, 0, 0), Point(3, 0, 4), Point(6, 0, 0))).shortestEdge, 5);
}

TEST(FlatShapesTests, edgeNormalsAreUnitInPlaneAndInwards) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: random triangles and convex quads (3 to 4 vertices, every winding): each edge's normal
  // is unit and in the plane, every vertex lies on or inside every edge's line (within 10^-12 of
  // the size), the edge's own two vertices on it, and the centroid strictly inside (e·c − ef > 0);
  // a triangle's unused lane repeats edge 0, bit for bit
  Random random(9);
  std::vector<Geometry> shapes;
  for (int i = 0; i < 2000; ++i) {
    const Double3 c = random.inBox(Aabb(Double3(-20), Double3(20)));
    const double s = random.uniform(0.5, 5);
    if (i % 2 == 0) {
      try {
        shapes.emplace_back(random.triangleAround(c, s));
      } catch (const std::invalid_argument&) {
      }
    } else {
      shapes.emplace_back(Polygon(onEllipse(random, c, randomFrame(random), s, s * 0.5, 4)));
    }
  }
  std::vector<std::uint32_t> all(shapes.size());
  for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  const FlatShapes flats(Primitives(std::span<const Geometry>(shapes)), all);
  int checked = 0;
  for (std::uint32_t k = 0; k < flats.size(); ++k) {
    const FlatShape& f = flats.record(k);
    const std::span<const Point> vs = verticesOf(shapes[f.shape]);
    Double3 c;
    for (const Point& v : vs) c = c + v.xyz();
    c = c / static_cast<double>(vs.size());
    double size = 0;
    for (const Point& v : vs) size = std::max(size, std::sqrt((v.xyz() - c).lengthSquared()));
    for (std::size_t e = 0; e < vs.size(); ++e) {
      const Double3 normal(f.ex[e], f.ey[e], f.ez[e]);
      const auto distance = [&](const Double3& x) { return normal.dot(x) - f.ef[e]; };
      ASSERT_NEAR(normal.lengthSquared(), 1, 1e-14) << k << " edge " << e;
      ASSERT_NEAR(normal.dot(f.n), 0, 1e-14) << k << " edge " << e;
      ASSERT_GT(distance(c), 0) << k << " edge " << e;
      ASSERT_NEAR(distance(vs[e].xyz()), 0, 1e-12 * size) << k << " edge " << e;
      ASSERT_NEAR(distance(vs[(e + 1) % vs.size()].xyz()), 0, 1e-12 * size) << k << " edge " << e;
      for (const Point& v : vs) ASSERT_GT(distance(v.xyz()), -1e-12 * size) << k << " edge " << e;
      ++checked;
    }
    if (f.vertices == 3) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(f.ex[3]), std::bit_cast<std::uint64_t>(f.ex[0]));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(f.ey[3]), std::bit_cast<std::uint64_t>(f.ey[0]));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(f.ez[3]), std::bit_cast<std::uint64_t>(f.ez[0]));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(f.ef[3]), std::bit_cast<std::uint64_t>(f.ef[0]));
    }
  }
  EXPECT_GT(checked, 6500);
}

TEST(FlatShapesTests, records) {
  // A scene of every kind: flat shapes at 1 (a triangle at z = 1), 3 (a square at z = 2), 4 (a
  // pentagon at z = 3) and 6 (a triangle at z = 4), the others not flat.
  const std::vector<Geometry> shapes{
      Sphere(Point(0, 0, -5), 1),
      Triangle(Point(0, 0, 1), Point(2, 0, 1), Point(0, 2, 1)),
      Plane(Point(0, 0, -10), Vector(0, 0, 1)),
      Polygon({Point(-1, -1, 2), Point(1, -1, 2), Point(1, 1, 2), Point(-1, 1, 2)}),
      Polygon({Point(-2, -2, 3), Point(2, -2, 3), Point(3, 1, 3), Point(0, 3, 3), Point(-3, 1, 3)}),
      Tube(1, Ray(Point(5, 5, 0), Vector(0, 0, 1))),
      Triangle(Point(-1, -1, 4), Point(1, -1, 4), Point(0, 1, 4)),
      Cylinder(1, Ray(Point(-5, -5, 0), Vector(0, 0, 1)), 2),
  };
  const Primitives primitives{std::span<const Geometry>(shapes)};
  // ============ Equivalence Partitions Tests ==============
  // TC01: isFlat: triangles and polygons only
  const bool flat[] = {false, true, false, true, true, false, true, false};
  for (std::size_t i = 0; i < shapes.size(); ++i)
    EXPECT_EQ(FlatShapes::isFlat(shapes[i]), flat[i]) << i;
  // TC02: records in the order given (not the shapes' order): each names its shape and counts
  // its vertices; the first four vertices side by side (a triangle's fourth lane repeats vertex
  // 0); planeT's point and normal are stage 3's, bit for bit
  const std::uint32_t order[] = {6, 1, 4, 3};
  const std::uint32_t vertexCount[] = {3, 3, 5, 4};
  const FlatShapes flats(primitives, order);
  ASSERT_EQ(flats.size(), 4u);
  EXPECT_EQ(flats.memoryBytes(), 4 * sizeof(FlatShape));
  for (std::uint32_t k = 0; k < 4; ++k) {
    const FlatShape& f = flats.record(k);
    EXPECT_EQ(f.shape, order[k]);
    EXPECT_EQ(f.vertices, vertexCount[k]);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(&f) % 32, 0u) << "record " << k << " not aligned";
    const Geometry& g = shapes[order[k]];
    const std::span<const Point> vs = verticesOf(g);
    for (std::size_t lane = 0; lane < 4; ++lane) {
      const Double3& v = vs[lane < vs.size() ? lane : 0].xyz();
      EXPECT_EQ(f.x[lane], v.x) << k << " lane " << lane;
      EXPECT_EQ(f.y[lane], v.y) << k << " lane " << lane;
      EXPECT_EQ(f.z[lane], v.z) << k << " lane " << lane;
    }
    const Plane plane = std::holds_alternative<Triangle>(g) ? std::get<Triangle>(g).plane()
                                                            : std::get<Polygon>(g).plane();
    EXPECT_EQ(std::bit_cast<std::uint64_t>(f.q.z), std::bit_cast<std::uint64_t>(plane.point().z()));
    EXPECT_EQ(f.q.x, plane.point().x());
    EXPECT_EQ(f.q.y, plane.point().y());
    EXPECT_EQ(f.n.x, plane.normal().x());
    EXPECT_EQ(f.n.y, plane.normal().y());
    EXPECT_EQ(f.n.z, plane.normal().z());
  }
  // TC03: each record answers for its own shape: a ray from (0.25, 0.25, 0) straight up meets
  // the shape of record k at its height z = 4, 1, 3, 2; a ray beside them all (x = 10) misses
  const Ray up(Point(0.25, 0.25, 0), Vector(0, 0, 1));
  const double heights[] = {4, 1, 3, 2};
  for (std::uint32_t k = 0; k < 4; ++k) {
    const Roots roots = flats.roots(k, up);
    ASSERT_EQ(roots.size(), 1) << k;
    EXPECT_EQ(roots[0], heights[k]) << k;
    EXPECT_TRUE(flats.roots(k, Ray(Point(10, 0.25, 0), Vector(0, 0, 1))).empty()) << k;
  }
  // TC04: the instruction set asked for is kept; bestSimd is never Scalar on x86-64 (SSE2 is
  // its baseline)
  EXPECT_EQ(FlatShapes(primitives, order, Simd::Scalar).simd(), Simd::Scalar);
#if defined(__SSE2__)
  EXPECT_EQ(FlatShapes(primitives, order, Simd::Sse2).simd(), Simd::Sse2);
#endif
#if defined(__x86_64__)
  EXPECT_NE(FlatShapes::bestSimd(), Simd::Scalar);
#endif
  // =============== Boundary Values Tests ==================
  // TC11: no record: default-made, or made from no shape
  EXPECT_EQ(FlatShapes().size(), 0u);
  EXPECT_EQ(FlatShapes().memoryBytes(), 0u);
  EXPECT_EQ(FlatShapes(primitives, std::span<const std::uint32_t>()).size(), 0u);
  // TC12: one record of the last flat shape alone
  const std::uint32_t last = 6;
  const FlatShapes one(primitives, std::span(&last, 1));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one.record(0).shape, 6u);
  EXPECT_EQ(one.memoryBytes(), sizeof(FlatShape));
}

}  // namespace
}  // namespace rt
