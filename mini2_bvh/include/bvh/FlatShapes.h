#pragma once
/// @file FlatShapes.h
/// Polygons and triangles laid out for their exact test, as the hierarchies' leaves and the light
/// buffers run it: the same roots as stage 3's intersectRoots, bit for bit, in fewer steps.
///
/// Stage 3's flatRoots is planeT, then the inside test passesInside: for every edge i, with
/// a_i = v_i − P0, the sign of s_i = dir·(a_i × a_(i+1)) and whether s_i² <= 2^-80·|a_i ×
/// a_(i+1)|². The edges are independent, so for a shape of three or four vertices the four edges
/// are computed side by side, one per lane of a vector of four doubles (AVX2, or two vectors of two
/// with SSE2):
///
///     lane       0          1          2          3
///     a       v0 − P0    v1 − P0    v2 − P0    v3 − P0      (x, y and z: three vectors)
///     b       a1         a2         a3         a0           (a quad: a rotated by a lane)
///     c = a × b, s = (dx·cx + dy·cy) + dz·cz, |c|² = (cx·cx + cy·cy) + cz·cz
///
/// Each lane does the very operations of stage 3's loop, in the same order (no fused multiply-
/// add: the project builds with -ffp-contract=off, and intrinsics are never fused), and IEEE
/// arithmetic rounds a lane as it rounds a scalar: the same s_i and |c_i|², so the same
/// decision. Stage 3's loop stops at the first edge that decides a miss; here every edge is
/// computed and the verdict is the same (a miss when some edge is within the threshold or the
/// signs differ). The vertices are copied next to each other (a Polygon keeps them in a vector
/// of its own, elsewhere in memory), their coordinates side by side. Polygons of more than four
/// vertices keep stage 3's loop.

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "geometries/Geometry.h"
#include "intersections/Intersect.h"
#include "intersections/Primitives.h"
#include "primitives/Double3.h"
#include "primitives/Ray.h"

namespace rt {

/// One polygon or triangle (a shape, not a mesh triangle) as FlatShapes keeps it.
struct alignas(32) FlatShape {
  std::array<double, 4> x, y, z;  ///< the first four vertices, coordinate by coordinate
  /// The edges' lines in the shape's plane, for tests that place a point of the plane with a
  /// margin (the light buffers'): edge k (from vertex k to k + 1) has the unit normal
  /// (ex, ey, ez)[k], in the plane and pointing inwards, and a point X of the plane lies
  /// e_k·X − ef[k] inside it. Unused lanes repeat edge 0; a polygon of more than four vertices
  /// has its first four edges here only (the light buffers never place such a shape).
  std::array<double, 4> ex, ey, ez, ef;
  Double3 q;               ///< planeT's point (stage 3's: the plane's, or vertex 0)
  Double3 n;               ///< planeT's unit normal
  double shortestEdge;     ///< the length of its shortest edge (of all its edges)
  std::uint32_t vertices;  ///< 3, 4, or more (then the shape's own list is used)
  std::uint32_t shape;     ///< its number among the shapes
};

/// The smallest and the largest of the distances of a point x of f's plane inside f's edges
/// (e_k·x − ef[k] over the edges; negative outside the edge): x is inside the shape by at least
/// the first, and outside it, beyond some edge, when the first is negative. Two lanes at a time
/// with SSE2.
inline std::array<double, 2> edgeDistanceRange(const FlatShape& f, const Double3& x) noexcept {
#if defined(__SSE2__)
  const __m128d px = _mm_set1_pd(x.x), py = _mm_set1_pd(x.y), pz = _mm_set1_pd(x.z);
  const auto distances = [&](int k) {
    const __m128d d = _mm_add_pd(
        _mm_add_pd(_mm_mul_pd(_mm_load_pd(&f.ex[k]), px), _mm_mul_pd(_mm_load_pd(&f.ey[k]), py)),
        _mm_mul_pd(_mm_load_pd(&f.ez[k]), pz));
    return _mm_sub_pd(d, _mm_load_pd(&f.ef[k]));
  };
  const __m128d d01 = distances(0), d23 = distances(2);
  const __m128d lo = _mm_min_pd(d01, d23), hi = _mm_max_pd(d01, d23);
  return {_mm_cvtsd_f64(_mm_min_sd(lo, _mm_unpackhi_pd(lo, lo))),
          _mm_cvtsd_f64(_mm_max_sd(hi, _mm_unpackhi_pd(hi, hi)))};
#else
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < 4; ++k) {
    const double d = f.ex[k] * x.x + f.ey[k] * x.y + f.ez[k] * x.z - f.ef[k];
    lo = d < lo ? d : lo;
    hi = d > hi ? d : hi;
  }
  return {lo, hi};
#endif
}

class FlatShapes {
 public:
  /// The instruction set of the inside test; the same bits with each.
  enum class Simd { Scalar, Sse2, Avx2 };
  /// Avx2 where this build and processor have it, else Sse2 on x86-64, else Scalar.
  static Simd bestSimd() noexcept;

  /// True for the shapes kept here: triangles and polygons.
  static bool isFlat(const Geometry& g) noexcept;

  FlatShapes() = default;
  /// Records for shapes[k] of primitives, k in `shapes` (each a flat shape), in that order: the
  /// record of shapes[k] is number k. The shapes must outlive this (a polygon of more than four
  /// vertices is tested on its own list).
  FlatShapes(Primitives primitives, std::span<const std::uint32_t> shapes, Simd simd = bestSimd());

  /// stage 3's intersectRoots of record k's shape, bit for bit. A ray that starts on one side
  /// of the shape's plane and runs away from it is answered at once, without planeT's division
  /// or the edges (awayFromPlane).
  Roots roots(std::uint32_t k, const Ray& ray) const noexcept {
    if (awayFromPlane(records_[k].q, records_[k].n, ray)) return {};
    return solve(k, ray);
  }

  /// True when stage 3's planeT(q, n, ray) is NaN because the ray's head lies strictly on one
  /// side of the plane and its direction strictly points further that way: n·(head − q) and
  /// n·dir of one sign. planeT's numerator is n·(q − head), the first's exact negation (q − head
  /// is head − q negated, component by component, and so is their dot product with n), so the
  /// numerator and alignZero(n·dir) have opposite signs, or the latter is 0, or the numerator is
  /// within the rounding bound: NaN in every case. What a ray leaving a surface (its head
  /// shifted off it along the side it goes to) meets first for the surface it leaves.
  static bool awayFromPlane(const Double3& q, const Double3& n, const Ray& ray) noexcept {
    const double head = n.dot(ray.head().xyz() - q);
    const double along = n.dot(ray.direction().xyz());
    return (head > 0 && along > 0) || (head < 0 && along < 0);
  }

  const FlatShape& record(std::uint32_t k) const noexcept { return records_[k]; }
  std::size_t size() const noexcept { return records_.size(); }
  Simd simd() const noexcept { return simd_; }
  std::size_t memoryBytes() const noexcept { return records_.capacity() * sizeof(FlatShape); }

 private:
  /// roots() past the early answer: planeT, then the inside test.
  Roots solve(std::uint32_t k, const Ray& ray) const noexcept;

  std::vector<FlatShape> records_;
  Primitives primitives_{std::span<const Geometry>{}};
  Simd simd_ = Simd::Scalar;
  bool (*inside_)(const FlatShape&, const Ray&) noexcept = nullptr;
};

}  // namespace rt
