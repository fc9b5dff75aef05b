// The flat shapes' inside test with the edges side by side (FlatShapes.h says why the bits are
// stage 3's), written for AVX2 (chosen at run time) and SSE2 (the x86-64 baseline).

#include "bvh/FlatShapes.h"

#include <algorithm>
#include <cmath>
#include <variant>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "primitives/Util.h"

namespace rt {

namespace {

/// Stage 3's loop, for polygons of more than four vertices and for processors without SSE2.
bool insideScalar(const FlatShape& f, std::span<const Point> vertices, const Ray& ray) noexcept {
  (void)f;
  return passesInside(vertices, ray);
}

/// The lanes in use: the shape's edges (three or four).
unsigned laneMask(std::uint32_t vertices) noexcept { return vertices == 3 ? 0b0111u : 0b1111u; }

/// The verdict from the edges' masks: no edge within the threshold, and one sign for all.
bool verdict(unsigned near, unsigned positive, unsigned lanes) noexcept {
  return (near & lanes) == 0 && ((positive & lanes) == 0 || (positive & lanes) == lanes);
}

constexpr double THRESHOLD_SQUARED = ZERO_THRESHOLD * ZERO_THRESHOLD;

#if defined(__SSE2__)

/// Two lanes of edges: s and |c|² of edges whose a and b (= the next a) are given.
struct TwoEdges {
  __m128d s, lengthSquared;
};

TwoEdges twoEdges(__m128d ax, __m128d ay, __m128d az, __m128d bx, __m128d by, __m128d bz,
                  __m128d dx, __m128d dy, __m128d dz) noexcept {
  const __m128d cx = _mm_sub_pd(_mm_mul_pd(ay, bz), _mm_mul_pd(az, by));
  const __m128d cy = _mm_sub_pd(_mm_mul_pd(az, bx), _mm_mul_pd(ax, bz));
  const __m128d cz = _mm_sub_pd(_mm_mul_pd(ax, by), _mm_mul_pd(ay, bx));
  const __m128d s =
      _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, cx), _mm_mul_pd(dy, cy)), _mm_mul_pd(dz, cz));
  const __m128d l =
      _mm_add_pd(_mm_add_pd(_mm_mul_pd(cx, cx), _mm_mul_pd(cy, cy)), _mm_mul_pd(cz, cz));
  return {s, l};
}

bool insideSse2(const FlatShape& f, const Ray& ray) noexcept {
  const Double3& p0 = ray.head().xyz();
  const Double3& d = ray.direction().xyz();
  const __m128d px = _mm_set1_pd(p0.x), py = _mm_set1_pd(p0.y), pz = _mm_set1_pd(p0.z);
  // a for vertices 0, 1 and 2, 3.
  const __m128d ax01 = _mm_sub_pd(_mm_load_pd(&f.x[0]), px);
  const __m128d ay01 = _mm_sub_pd(_mm_load_pd(&f.y[0]), py);
  const __m128d az01 = _mm_sub_pd(_mm_load_pd(&f.z[0]), pz);
  const __m128d ax23 = _mm_sub_pd(_mm_load_pd(&f.x[2]), px);
  const __m128d ay23 = _mm_sub_pd(_mm_load_pd(&f.y[2]), py);
  const __m128d az23 = _mm_sub_pd(_mm_load_pd(&f.z[2]), pz);
  // b for edges 0, 1: (a1, a2); for edges 2, 3: (a3, a0) of a quad, (a0, unused) of a triangle.
  const bool quad = f.vertices == 4;
  const auto next01 = [](__m128d lo, __m128d hi) { return _mm_shuffle_pd(lo, hi, 0b01); };
  const auto next23 = [quad](__m128d lo, __m128d hi) {
    return quad ? _mm_shuffle_pd(hi, lo, 0b01) : _mm_shuffle_pd(lo, hi, 0b00);
  };
  const __m128d dx = _mm_set1_pd(d.x), dy = _mm_set1_pd(d.y), dz = _mm_set1_pd(d.z);
  const TwoEdges e01 = twoEdges(ax01, ay01, az01, next01(ax01, ax23), next01(ay01, ay23),
                                next01(az01, az23), dx, dy, dz);
  const TwoEdges e23 = twoEdges(ax23, ay23, az23, next23(ax01, ax23), next23(ay01, ay23),
                                next23(az01, az23), dx, dy, dz);
  const __m128d t2 = _mm_set1_pd(THRESHOLD_SQUARED);
  const __m128d zero = _mm_setzero_pd();
  const auto near = [&](const TwoEdges& e) {
    return static_cast<unsigned>(
        _mm_movemask_pd(_mm_cmple_pd(_mm_mul_pd(e.s, e.s), _mm_mul_pd(t2, e.lengthSquared))));
  };
  const auto positive = [&](const TwoEdges& e) {
    return static_cast<unsigned>(_mm_movemask_pd(_mm_cmpgt_pd(e.s, zero)));
  };
  return verdict(near(e01) | near(e23) << 2, positive(e01) | positive(e23) << 2,
                 laneMask(f.vertices));
}

#if defined(__GNUC__)
__attribute__((target("avx2"))) bool insideAvx2(const FlatShape& f, const Ray& ray) noexcept {
  const Double3& p0 = ray.head().xyz();
  const Double3& d = ray.direction().xyz();
  const __m256d ax = _mm256_sub_pd(_mm256_load_pd(f.x.data()), _mm256_set1_pd(p0.x));
  const __m256d ay = _mm256_sub_pd(_mm256_load_pd(f.y.data()), _mm256_set1_pd(p0.y));
  const __m256d az = _mm256_sub_pd(_mm256_load_pd(f.z.data()), _mm256_set1_pd(p0.z));
  // b = the next vertex's a: lanes (1, 2, 3, 0) of a quad, (1, 2, 0, unused) of a triangle.
  __m256d bx, by, bz;
  if (f.vertices == 4) {
    bx = _mm256_permute4x64_pd(ax, 0x39), by = _mm256_permute4x64_pd(ay, 0x39);
    bz = _mm256_permute4x64_pd(az, 0x39);
  } else {
    bx = _mm256_permute4x64_pd(ax, 0xC9), by = _mm256_permute4x64_pd(ay, 0xC9);
    bz = _mm256_permute4x64_pd(az, 0xC9);
  }
  const __m256d cx = _mm256_sub_pd(_mm256_mul_pd(ay, bz), _mm256_mul_pd(az, by));
  const __m256d cy = _mm256_sub_pd(_mm256_mul_pd(az, bx), _mm256_mul_pd(ax, bz));
  const __m256d cz = _mm256_sub_pd(_mm256_mul_pd(ax, by), _mm256_mul_pd(ay, bx));
  const __m256d s = _mm256_add_pd(
      _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(d.x), cx), _mm256_mul_pd(_mm256_set1_pd(d.y), cy)),
      _mm256_mul_pd(_mm256_set1_pd(d.z), cz));
  const __m256d l = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(cx, cx), _mm256_mul_pd(cy, cy)),
                                  _mm256_mul_pd(cz, cz));
  const auto near = static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(
      _mm256_mul_pd(s, s), _mm256_mul_pd(_mm256_set1_pd(THRESHOLD_SQUARED), l), _CMP_LE_OQ)));
  const auto positive =
      static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(s, _mm256_setzero_pd(), _CMP_GT_OQ)));
  return verdict(near, positive, laneMask(f.vertices));
}
#endif

#endif  // __SSE2__

}  // namespace

FlatShapes::Simd FlatShapes::bestSimd() noexcept {
#if defined(__SSE2__) && defined(__GNUC__)
  if (__builtin_cpu_supports("avx2")) return Simd::Avx2;
#endif
#if defined(__SSE2__)
  return Simd::Sse2;
#else
  return Simd::Scalar;
#endif
}

bool FlatShapes::isFlat(const Geometry& g) noexcept {
  return std::holds_alternative<Triangle>(g) || std::holds_alternative<Polygon>(g);
}

FlatShapes::FlatShapes(Primitives primitives, std::span<const std::uint32_t> shapes, Simd simd)
    : primitives_(primitives), simd_(simd) {
  records_.reserve(shapes.size());
  for (const std::uint32_t i : shapes) {
    const Geometry& g = primitives.shapes()[i];
    FlatShape f{};
    std::span<const Point> vertices;
    if (const auto* t = std::get_if<Triangle>(&g)) {
      vertices = t->vertices();
      f.q = t->vertices()[0].xyz();
      f.n = t->normal().xyz();
    } else {
      const auto& p = std::get<Polygon>(g);
      vertices = p.vertices();
      f.q = p.plane().point().xyz();
      f.n = p.plane().normal().xyz();
    }
    f.vertices = static_cast<std::uint32_t>(vertices.size());
    f.shape = i;
    for (std::size_t k = 0; k < 4; ++k) {
      // An unused lane repeats vertex 0: finite numbers, masked out of the verdict.
      const Double3& v = vertices[k < vertices.size() ? k : 0].xyz();
      f.x[k] = v.x, f.y[k] = v.y, f.z[k] = v.z;
    }
    // The edges' inward unit normals in the plane: n × edge points inwards for a polygon wound
    // counter-clockwise about n, outwards the other way; the centroid tells which.
    Double3 centroid;
    for (const Point& v : vertices) centroid = centroid + v.xyz();
    centroid = centroid / static_cast<double>(vertices.size());
    f.shortestEdge = INFINITY;
    for (std::size_t k = 0; k < vertices.size(); ++k)
      f.shortestEdge = std::min(
          f.shortestEdge,
          std::sqrt(
              (vertices[(k + 1) % vertices.size()].xyz() - vertices[k].xyz()).lengthSquared()));
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t e = k < vertices.size() ? k : 0;
      const Double3& from = vertices[e].xyz();
      const Double3& to = vertices[(e + 1) % vertices.size()].xyz();
      const Double3 edge = to - from;
      const double length = std::sqrt(edge.lengthSquared());
      Double3 inward = f.n.cross(edge) / length;
      if (inward.dot(centroid - from) < 0) inward = -inward;
      f.ex[k] = inward.x, f.ey[k] = inward.y, f.ez[k] = inward.z;
      f.ef[k] = inward.dot(from);
    }
    records_.push_back(f);
  }
#if defined(__SSE2__)
  inside_ = insideSse2;
#if defined(__GNUC__)
  if (simd_ == Simd::Avx2) inside_ = insideAvx2;
#endif
  if (simd_ == Simd::Scalar) inside_ = nullptr;
#else
  simd_ = Simd::Scalar;
#endif
}

Roots FlatShapes::solve(std::uint32_t k, const Ray& ray) const noexcept {
  const FlatShape& f = records_[k];
  Roots roots;
  const double t = planeT(f.q, f.n, ray);
  if (!(alignZero(t) > 0)) return roots;
  bool inside;
  if (f.vertices <= 4 && inside_ != nullptr) {
    inside = inside_(f, ray);
  } else {
    const Geometry& g = primitives_.shapes()[f.shape];
    const auto* t3 = std::get_if<Triangle>(&g);
    inside = insideScalar(f,
                          t3 ? std::span<const Point>(t3->vertices())
                             : std::span<const Point>(std::get<Polygon>(g).vertices()),
                          ray);
  }
  if (inside) roots.add(t);
  return roots;
}

}  // namespace rt
