#include "geometries/UtahTeapot.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rt {

namespace {

/// The cubic Bernstein weights at t, B0..B3 = (1-t)³, 3t(1-t)², 3t²(1-t), t³, and the quadratic
/// ones of the derivative, (1-t)², 2t(1-t), t²: d/dt Σ Bk·Pk = 3 Σ Qk·(Pk+1 - Pk).
struct Weights {
  double b[4];
  double q[3];
};

Weights weightsAt(double t) {
  const double s = 1 - t;
  return {{s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t}, {s * s, 2 * t * s, t * t}};
}

/// A point of a patch and its partial derivatives there.
struct Sample {
  Double3 p, du, dv, duv;
};

/// P(u, v) = Σi Σj Bi(v)·Bj(u)·P(i, j), first along each row (u), then across the rows (v).
/// The derivatives use the differences of the control points, so that along an edge whose four
/// control points are one point the derivative along it is exactly zero.
Sample evaluate(const std::array<Double3, 16>& cp, const Weights& u, const Weights& v) {
  Double3 row[4];    // each row's curve at u
  Double3 rowDu[4];  // and its derivative in u
  for (int i = 0; i < 4; ++i) {
    const Double3* c = &cp[4 * i];
    row[i] = c[0] * u.b[0] + c[1] * u.b[1] + c[2] * u.b[2] + c[3] * u.b[3];
    rowDu[i] = ((c[1] - c[0]) * u.q[0] + (c[2] - c[1]) * u.q[1] + (c[3] - c[2]) * u.q[2]) * 3;
  }
  Sample s;
  s.p = row[0] * v.b[0] + row[1] * v.b[1] + row[2] * v.b[2] + row[3] * v.b[3];
  s.du = rowDu[0] * v.b[0] + rowDu[1] * v.b[1] + rowDu[2] * v.b[2] + rowDu[3] * v.b[3];
  s.dv = ((row[1] - row[0]) * v.q[0] + (row[2] - row[1]) * v.q[1] + (row[3] - row[2]) * v.q[2]) * 3;
  s.duv = ((rowDu[1] - rowDu[0]) * v.q[0] + (rowDu[2] - rowDu[1]) * v.q[1] +
           (rowDu[3] - rowDu[2]) * v.q[2]) *
          3;
  return s;
}

/// ∂P/∂u × ∂P/∂v, the normal's direction. Along an edge v = v0 collapsed to a point, ∂P/∂u is
/// zero there and grows as (v - v0)·∂²P/∂u∂v inside the patch, so the normal's limit is the
/// direction of ±∂²P/∂u∂v × ∂P/∂v, the sign that of v - v0 inside (+ at v0 = 0, - at v0 = 1);
/// likewise for an edge u = u0.
Double3 normalDirection(const Sample& s, double u, double v) {
  if (s.du.isExactlyZero()) return (v < 0.5 ? s.duv : -s.duv).cross(s.dv);
  if (s.dv.isExactlyZero()) return s.du.cross(u < 0.5 ? s.duv : -s.duv);
  return s.du.cross(s.dv);
}

}  // namespace

TriangleMesh utahTeapot(int detail) {
  if (detail < 1 || detail > kUtahTeapotMaxDetail)
    throw std::invalid_argument("utahTeapot: detail must be a whole number from 1 to " +
                                std::to_string(kUtahTeapotMaxDetail) +
                                " (quads per patch side), got " + std::to_string(detail));
  const auto n = static_cast<std::uint32_t>(detail);
  const std::uint32_t side = n + 1;  // grid samples per patch side
  const std::size_t patches = UtahTeapotData::kPatchCount;

  std::vector<Weights> weights(side);
  for (std::uint32_t k = 0; k <= n; ++k) weights[k] = weightsAt(static_cast<double>(k) / n);

  std::vector<Point> vertices;
  std::vector<Double3> normals;
  std::vector<TriangleMesh::Indices> triangles;
  vertices.reserve(patches * side * side);
  normals.reserve(patches * side * side);
  triangles.reserve(patches * 2 * n * n);

  for (const auto& patch : UtahTeapotData::kPatches) {
    std::array<Double3, 16> cp;
    for (std::size_t k = 0; k < 16; ++k) cp[k] = UtahTeapotData::kControlPoints[patch[k] - 1];

    const auto first = static_cast<std::uint32_t>(vertices.size());
    for (std::uint32_t i = 0; i <= n; ++i) {    // v = i / n, across the rows
      for (std::uint32_t j = 0; j <= n; ++j) {  // u = j / n, along a row
        const Sample s = evaluate(cp, weights[j], weights[i]);
        vertices.emplace_back(s.p);
        normals.push_back(
            normalDirection(s, static_cast<double>(j) / n, static_cast<double>(i) / n));
      }
    }
    // The quad (i, j)..(i + 1, j + 1) as two triangles wound like ∂P/∂u × ∂P/∂v: a b c, a c d.
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = 0; j < n; ++j) {
        const std::uint32_t a = first + i * side + j;
        const std::uint32_t b = a + 1;
        const std::uint32_t c = a + side + 1;
        const std::uint32_t d = a + side;
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
      }
    }
  }
  return TriangleMesh(std::move(vertices), std::move(triangles), std::move(normals));
}

}  // namespace rt
