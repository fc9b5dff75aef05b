// The light buffer's build: every primitive's distance from the light and its rectangle of cells
// on each face of the cube (LightBuffer.h proves why these lists never miss a hit), and the two
// shortcuts the query takes for flat shapes, proved here. Notation as in LightBuffer.h: c the
// light, S the scene's size (the largest coordinate of the primitives' trusted boxes and of c, at
// least 1), R0 the near radius (LightBuffer::nearRadiusOf: 10^-3 of S, or less when the
// primitives lie closer to c than S, but never below 10^-4·S; the arguments below use only
// R0 >= 10^-4·S, where a rounding of coordinates of size S, some 10^-16·S, is negligible), a ray
// o + t·dir aimed at c with w·g >= R0, ρ <= 10^-4·R0 and tMax <= w·g + R0/2; u = 2^-53.
//
// **The box's rectangle.** Its corners' offsets from c, of size S, are exact to u·S, and the face's
// projection divides them by at least R0/4: the (u, v) they give are exact to some 10^5·u, far
// below the rectangle's padding (4·1.2·AIM).
//
// **The side test.** A flat shape (or a plane) gets the test only when its plane is at least R0
// from c. The ray's point at tMax lies within R0/2 + ρ < R0 of c (|X − c|² = (w·g − t)² + ρ²),
// so on c's side of the plane; so does every point between o and it when o is on c's side too
// (a half-space is convex): the exact ray does not cross the plane in (0, tMax]. The computed
// side n·o − offset is off the exact one by a few u times |n·o| + |offset|, far below the
// margin the query asks (10^-13 of o's and the scene's largest coordinates). Stage 3's planeT,
// for such a ray, either finds no root or one past tMax: the exact crossing lies at least
// R0/2 − ρ beyond the point at tMax along the normal, which no rounding of planeT (relative
// error of a few u in its numerator beyond its own NaN margin) closes.
//
// **Certain crossings.** Stage 3's inside test with P0 = o computes, per edge i of length L_i,
// s_i = dir·(a_i × a_(i+1)), a_i = v_i − o. With X = o + t·dir the exact crossing of the plane
// and h the distance of o from the plane, s_i = det(X − o, a_i, a_(i+1))/t, six times the
// tetrahedron (o, X, v_i, v_(i+1)) over t: s_i = ±L_i·d_i·h/t, d_i the distance of X from edge
// i's line, its sign that of d_i (inside: positive) times one sign common to the edges. The
// query allows a crossing to be decided without the solver (CERTAIN) only when o's coordinates
// are at most 4S, o is at least D = 10^-3·S behind the plane (on the side away from c), and the
// range starts before D/2 and reaches within R0/2 of c. Then t <= B = 5·√3·S (o and X in the
// cube of side 4S and S), |a_i| <= B, and:
//  - Rounding: the computed s_i is within 10·u·B² of the exact one (the differences a_i, the
//    cross product, the dot product: a few roundings of terms of size B²).
//  - Threshold: stage 3 calls s_i zero when s_i² <= T²·|a_i × a_(i+1)|², T = 2^-40; and
//    |a_i × a_(i+1)| = L_i times the distance of o from edge i's line <= L_i·B (1.01 for its
//    own rounding).
// So a crossing with every d_i >= δ (δ = 10^-3·S) has every |s_i| >= L_i·δ·D/B, and when
//     δ·D > B·(10·u·B²/L + 1.01·T·B)     (L the shortest edge)
// every computed s_i is clear of both, with the signs of the exact ones: all alike, a hit.
// A crossing with some d_i <= −δ and some d_j >= δ has two signs that differ: a miss. A shape
// is CERTAIN when the inequality holds a hundredfold (shapes of at most four vertices). The
// hit's t needs no solver: the contract (LightOccluders.h) asks for some t in [tMin, tMax], and
// the exact crossing lies in it with room (t >= h >= D > tMin; X at least R0 from c puts t
// at least R0/2 before tMax), so stage 3's computed root, a few u·B/|n·dir| away at a slope
// |n·dir| >= MIN_SLOPE, lies in it too. The query computes X itself (its rounding is far below
// δ: the 100 to spare) and measures the d_i with the records' unit edge normals
// (edgeDistanceRange).
//
// **Whole cells.** A cell's rays meet a flat shape's plane inside the central projection of
// the cell's padded (u, v) rectangle, which, when every corner direction y meets the plane in
// front of c at a slope |n·y|/|y| >= 2·MIN_SLOPE, is the convex quadrilateral of the four
// corners' points (a central projection maps lines to lines). The distance from an edge's line
// is affine along the plane, so its least and largest values over the cell are at the corners:
// when every edge's least is >= δ, every ray of the cell crosses the shape well inside
// (INSIDE: the query reports a crossing without computing X); when one edge's largest is
// <= −δ and another's least >= δ, every ray misses it (OUTSIDE). The padding (4·1.2·AIM) covers
// the angle between a ray's direction and the direction of its crossing from c, as for the
// cells themselves (LightBuffer.h, step 2).

#include "lightbuffer/LightBuffer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "bvh/BoundingBox.h"
#include "bvh/FloatBox.h"

namespace rt {

namespace {

/// What the build keeps of a primitive: its trusted box, or a plane's, and its distance.
struct Placed {
  std::uint32_t primitive;
  double distance;  ///< a lower bound of the distance from the light to any of its points
  enum class Kind { Box, Plane, Near } kind;
  Aabb box;         ///< Box: the trusted box (conservativeBox, in double)
  Double3 towards;  ///< Plane: its unit normal, pointed from the light towards it
};

double largestAbs(const Double3& p) noexcept {
  return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

/// The distance from c to the box, a lower bound: the exact one less a relative 10^-9.
double boxDistance(const Aabb& b, const Double3& c) noexcept {
  const auto gap = [](double lo, double hi, double x) { return std::max({0.0, lo - x, x - hi}); };
  const Double3 d(gap(b.lo.x, b.hi.x, c.x), gap(b.lo.y, b.hi.y, c.y), gap(b.lo.z, b.hi.z, c.z));
  return std::sqrt(d.lengthSquared()) * (1 - 1e-9);
}

/// The distance from c to the box's farthest corner.
double farthestCorner(const Aabb& b, const Double3& c) noexcept {
  const auto far = [](double lo, double hi, double x) {
    return std::max(std::abs(lo - x), std::abs(hi - x));
  };
  const Double3 d(far(b.lo.x, b.hi.x, c.x), far(b.lo.y, b.hi.y, c.y), far(b.lo.z, b.hi.z, c.z));
  return std::sqrt(d.lengthSquared());
}

/// A lower bound of the distance from c to an unbounded shape's points (and to its computed
/// hits, which lie off the exact surface by rounding): a plane's or a tube's exact distance less
/// a margin of 10^-9 of the coordinates involved; 0 for anything else. A plane's unit normal
/// pointed from c towards it goes to towards.
double unboundedDistance(const Primitives& primitives, std::uint32_t i, const Double3& c,
                         double scale, std::optional<Double3>& towards) noexcept {
  if (!primitives.isShape(i)) return 0;
  const Geometry& g = primitives.shapes()[i];
  double exact = 0, size = scale;
  if (const auto* plane = std::get_if<Plane>(&g)) {
    const Double3& q = plane->point().xyz();
    const Double3& n = plane->normal().xyz();
    const double along = n.dot(q - c);
    exact = std::abs(along);
    size = std::max({size, largestAbs(q), largestAbs(c)});
    towards = along >= 0 ? n : -n;
  } else if (const auto* tube = std::get_if<Tube>(&g)) {
    const Double3& p0 = tube->axis().head().xyz();
    const Double3 across = (c - p0).cross(tube->axis().direction().xyz());
    exact = std::sqrt(across.lengthSquared()) - tube->radius();
    size = std::max({size, largestAbs(p0), largestAbs(c), tube->radius()});
  }
  return std::max(0.0, exact * (1 - 1e-9) - 1e-9 * size);
}

/// How a cell entry of primitive i is tested (LightBuffer::Flags): a sphere directly; a polygon
/// or a triangle whose plane is at least R0 from the light after the side test, CERTAIN when
/// `certain(record)` says its crossings may be decided with margins.
template <typename Certain>
std::uint32_t flagsOf(const Primitives& primitives, std::uint32_t i, const FlatShapes& flats,
                      std::span<const std::uint32_t> flatOf, const Double3& c, double r0,
                      const Certain& certain) noexcept {
  if (!primitives.isShape(i)) return 0;
  const Geometry& g = primitives.shapes()[i];
  if (std::holds_alternative<Sphere>(g)) return LightBuffer::SPHERE;
  if (!FlatShapes::isFlat(g)) return 0;
  const FlatShape& f = flats.record(flatOf[i]);
  const double towardsLight = f.n.dot(c - f.q);
  if (std::abs(towardsLight) * (1 - 1e-9) <= r0) return 0;
  std::uint32_t flags = LightBuffer::FLAT;
  if (towardsLight < 0) flags |= LightBuffer::BACK;
  if (certain(f)) flags |= LightBuffer::CERTAIN;
  return flags;
}

/// A cell's padded cone of directions: face (axis a, sign s), u and v ranges.
struct CellCone {
  int a;
  double s;
  std::array<double, 2> u, v;
};

/// Where the cone of a cell meets a flat shape's plane: wholly inside the shape by `margin` or
/// more from every edge, and at a slope (|n·y| of its unit directions y) of MIN_SLOPE or more
/// (LightBuffer::INSIDE), wholly outside one of its edges by `margin` or more (OUTSIDE), or
/// neither (0). The cone meets the plane in the convex hull of its four corner directions' points
/// (when all four meet it in front of the light), and the distance to an edge line is linear
/// along the plane, so the corners decide.
std::uint32_t placeCell(const FlatShape& f, const Double3& c, const CellCone& cone,
                        double margin) noexcept {
  const int b = (cone.a + 1) % 3, cAxis = (cone.a + 2) % 3;
  const double height = f.n.dot(f.q - c);  // the plane is at n·(x − c) = height
  std::array<double, 4> lowest{INFINITY, INFINITY, INFINITY, INFINITY},
      highest{-INFINITY, -INFINITY, -INFINITY, -INFINITY};
  for (const double u : cone.u)
    for (const double v : cone.v) {
      Double3 y;
      double* yc[3] = {&y.x, &y.y, &y.z};
      *yc[cone.a] = cone.s;
      *yc[b] = u;
      *yc[cAxis] = v;
      const double slope = f.n.dot(y);
      // In front of the light, and not grazing: |n·y|/|y| >= MIN_SLOPE (doubled, for rounding).
      if (!(slope * height > 0) ||
          std::abs(slope) < 2 * LightBuffer::MIN_SLOPE * std::sqrt(y.lengthSquared()))
        return 0;
      const Double3 x = c + y * (height / slope);
      for (std::uint32_t k = 0; k < f.vertices; ++k) {
        const double d = f.ex[k] * x.x + f.ey[k] * x.y + f.ez[k] * x.z - f.ef[k];
        lowest[k] = std::min(lowest[k], d);
        highest[k] = std::max(highest[k], d);
      }
    }
  // Inside: every edge's distance at least the margin. Outside: one edge's at most −margin and
  // another's at least margin, so that two of the signs stage 3 computes differ. (Outside one
  // edge, a point of a convex shape's plane is inside another, but of a sliver by less than
  // rounding may decide: the second margin is needed.)
  bool inside = true, outsideOne = false, insideOne = false;
  for (std::uint32_t k = 0; k < f.vertices; ++k) {
    outsideOne = outsideOne || highest[k] <= -margin;
    insideOne = insideOne || lowest[k] >= margin;
    inside = inside && lowest[k] >= margin;
  }
  if (inside) return LightBuffer::INSIDE;
  return outsideOne && insideOne ? std::uint32_t{LightBuffer::OUTSIDE} : 0u;
}

/// The rectangle of (u, v) a box covers on face (axis a, sign s), for its points at least h in
/// front of the light along a; false when it has none.
bool faceRectangle(const Aabb& box, const Double3& c, int a, double s, double h,
                   std::array<double, 4>& uv) noexcept {
  const int b = (a + 1) % 3, cAxis = (a + 2) % 3;
  const auto lo = [&](int k) { return component(box.lo, k) - component(c, k); };
  const auto hi = [&](int k) { return component(box.hi, k) - component(c, k); };
  // The denominators s·(x_a − c_a) over the box's points in front of the light by h or more.
  const double dLo = std::max(h, s > 0 ? lo(a) : -hi(a));
  const double dHi = s > 0 ? hi(a) : -lo(a);
  if (!(dLo <= dHi)) return false;
  // x/d over x in [xl, xh], d in [dLo, dHi] (d > 0): the extremes are at the corners.
  const auto range = [&](double xl, double xh, double& out0, double& out1) {
    out0 = std::min(xl / dLo, xl / dHi);
    out1 = std::max(xh / dLo, xh / dHi);
  };
  range(lo(b), hi(b), uv[0], uv[1]);
  range(lo(cAxis), hi(cAxis), uv[2], uv[3]);
  return true;
}

/// The directions of a cell (padded): the unit vectors (along the face's axes a, b, c) of
/// (s, u, v)/√(1 + u² + v²) for u in [u0, u1], v in [v0, v1]; per world axis, the range of
/// that component.
struct Cone {
  std::array<double, 3> lo, hi;

  Cone(int a, double s, double u0, double u1, double v0, double v1) noexcept {
    const auto nearest0 = [](double x0, double x1) {
      return x0 <= 0 && x1 >= 0 ? 0.0 : std::min(std::abs(x0), std::abs(x1));
    };
    const auto farthest0 = [](double x0, double x1) {
      return std::max(std::abs(x0), std::abs(x1));
    };
    const double uNear = nearest0(u0, u1), uFar = farthest0(u0, u1);
    const double vNear = nearest0(v0, v1), vFar = farthest0(v0, v1);
    const auto inv = [](double p, double q) { return 1 / std::sqrt(1 + p * p + q * q); };
    // The face's own axis: s/√(1 + u² + v²), largest where u and v are nearest 0.
    const double aLo = inv(uFar, vFar), aHi = inv(uNear, vNear);
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    lo[a] = s > 0 ? aLo : -aHi;
    hi[a] = s > 0 ? aHi : -aLo;
    // x/√(1 + x² + y²) grows with x; for a fixed x its size falls as |y| grows.
    const auto across = [&](double x0, double x1, double yNear, double yFar, double& outLo,
                            double& outHi) {
      outHi = x1 * inv(x1, x1 >= 0 ? yNear : yFar);
      outLo = x0 * inv(x0, x0 <= 0 ? yNear : yFar);
    };
    across(u0, u1, vNear, vFar, lo[b], hi[b]);
    across(v0, v1, uNear, uFar, lo[c], hi[c]);
    for (int k = 0; k < 3; ++k) {  // rounding: widen by far more than a few ulps
      lo[k] -= 1e-12;
      hi[k] += 1e-12;
    }
  }

  double maxAbs(int k) const noexcept { return std::max(std::abs(lo[k]), std::abs(hi[k])); }
  /// The largest n·y over the cone's directions y.
  double maxDot(const Double3& n) const noexcept {
    double m = 0;
    for (int k = 0; k < 3; ++k) {
      const double nk = component(n, k);
      m += nk >= 0 ? nk * hi[k] : nk * lo[k];
    }
    return m;
  }
};

/// How far from c along any direction of the cone a point of the box can be, at least: on
/// every axis where c lies outside the box's slab, the gap over the direction's largest
/// component there. Infinite when no direction of the cone reaches the box.
double boxDistanceAlong(const Aabb& b, const Double3& c, const Cone& cone) noexcept {
  double d = 0;
  for (int k = 0; k < 3; ++k) {
    const double x = component(c, k);
    const double gap = std::max({0.0, component(b.lo, k) - x, x - component(b.hi, k)});
    if (gap > 0) d = std::max(d, gap / cone.maxAbs(k));
  }
  return d;
}

}  // namespace

std::optional<LightBuffer> LightBuffer::build(Primitives primitives, const Point& light,
                                              const FlatShapes& flats,
                                              std::span<const std::uint32_t> flatOf,
                                              const LightBufferOptions& options) {
  if (options.resolution < 0 || options.resolution > 1024)
    throw std::invalid_argument("LightBuffer: resolution " + std::to_string(options.resolution) +
                                " is outside 0..1024");
  const Double3& c = light.xyz();

  // The boxes first: the scene's size sets the near radius.
  std::vector<Placed> placed;
  placed.reserve(primitives.size());
  double scale = std::max(1.0, largestAbs(c));
  double farthest = 0;  // E: the farthest corner of a bounded primitive's box from the light
  std::size_t bounded = 0;
  for (std::uint32_t i = 0; i < primitives.size(); ++i) {
    const std::optional<Aabb> box = boundingBox(primitives, i);
    const Aabb trusted = (box ? conservativeBox(*box) : FloatBox::empty()).widen();
    const bool finite = box && std::isfinite(trusted.lo.x) && std::isfinite(trusted.lo.y) &&
                        std::isfinite(trusted.lo.z) && std::isfinite(trusted.hi.x) &&
                        std::isfinite(trusted.hi.y) && std::isfinite(trusted.hi.z);
    placed.push_back(Placed{i, 0, finite ? Placed::Kind::Box : Placed::Kind::Near, trusted, {}});
    if (finite) {
      scale = std::max({scale, largestAbs(trusted.lo), largestAbs(trusted.hi)});
      farthest = std::max(farthest, farthestCorner(trusted, c));
      ++bounded;
    }
  }

  LightBuffer lb;
  if (primitives.size() > INDEX_MASK + 1u)
    throw std::length_error("LightBuffer: " + std::to_string(primitives.size()) +
                            " primitives, more than an entry can number (2^25)");
  lb.primitives_ = primitives;
  lb.flats_ = &flats;
  lb.flatPlanes_.reserve(flats.size());
  for (std::uint32_t k = 0; k < flats.size(); ++k) {
    const FlatShape& f = flats.record(k);
    lb.flatPlanes_.push_back(FlatPlane{f.n, f.n.dot(f.q), f.shape});
  }
  lb.light_ = light;
  lb.nearRadius_ = nearRadiusOf(scale, bounded > 0 ? farthest : scale);
  lb.aimSquared_ = (AIM * lb.nearRadius_) * (AIM * lb.nearRadius_);
  const double r0 = lb.nearRadius_;
  lb.sideMargin_ = 1e-13 * scale;
  lb.certainReach_ = CERTAIN_REACH * scale;
  lb.certainDepth_ = CERTAIN_MARGIN * scale;
  lb.certainInside_ = CERTAIN_MARGIN * scale;
  // A flat shape's crossings may be decided with margins when the proof's inequality holds for
  // it with a hundredfold to spare (see the file comment).
  const auto certain = [&](const FlatShape& f) {
    if (f.vertices > 4) return false;
    constexpr double u = 0x1p-53;
    const double b = (CERTAIN_REACH + 1) * std::sqrt(3.0) * scale;  // B of the proof
    const double margin = lb.certainInside_ * lb.certainDepth_;
    return margin > 100 * b * (10 * u * b * b / f.shortestEdge + 1.01 * ZERO_THRESHOLD * b);
  };
  // The proof's θ = 1.2·AIM, moving (u, v) by at most 3.1·θ; padded by more, plus rounding.
  const double pad = 4 * 1.2 * AIM + 1e-9;

  // Within R0 of the light, or unbounded and not a plane: on the near list. Planes go to the
  // cells whose directions reach them, boxes to the cells they cover.
  std::vector<std::uint32_t> faced;  // indices into placed
  std::size_t nearBounded = 0;
  for (std::size_t k = 0; k < placed.size(); ++k) {
    Placed& p = placed[k];
    if (p.kind == Placed::Kind::Box) {
      p.distance = boxDistance(p.box, c);
    } else {
      std::optional<Double3> towards;
      p.distance = unboundedDistance(primitives, p.primitive, c, scale, towards);
      if (towards) {
        p.kind = Placed::Kind::Plane;
        p.towards = *towards;
      }
    }
    if (p.kind == Placed::Kind::Plane && p.distance > r0) {
      const auto& plane = std::get<Plane>(primitives.shapes()[p.primitive]);
      const Double3& q = plane.point().xyz();
      lb.planes_.push_back(PlaneEntry{p.towards * -1.0, (p.towards * -1.0).dot(q),
                                      1e-13 * std::max({scale, largestAbs(q)}), p.primitive});
    } else if (p.kind != Placed::Kind::Box || p.distance <= r0) {
      // Bounded shapes this close are tested by every query; the walk tests about as many.
      if (p.kind == Placed::Kind::Box && ++nearBounded > options.nearPrimitives)
        return std::nullopt;
      lb.near_.push_back(Entry{floatBelow(p.distance), p.primitive});  // GENERIC
    } else {
      faced.push_back(static_cast<std::uint32_t>(k));
    }
  }

  // The cells of each listed primitive, face by face, each with the primitive's distance along
  // the cell's directions: counted first, at a resolution that fits the budget, then written.
  int n = options.resolution;
  if (n == 0) {
    n = 16;
    while (n < 128 && static_cast<double>(n) * n < 2.0 * static_cast<double>(bounded)) n *= 2;
  }
  const double halfSide = 1 + FACE_MARGIN;
  // Calls f(cell, distance, sub) for every cell of primitive p at `cells` a side.
  const auto forEachCell = [&](const Placed& p, int cells, const auto& f) {
    const double width = 2 * halfSide / cells;
    const auto index = [&](double x) {
      const double k = (x + halfSide) / width;
      return k <= 0 ? 0 : k >= cells - 1 ? cells - 1 : static_cast<int>(k);
    };
    for (int a = 0; a < 3; ++a)
      for (const double s : {1.0, -1.0}) {
        int i0 = 0, i1 = cells - 1, j0 = 0, j1 = cells - 1;
        // The padded rectangle in cell units (the whole face for a plane).
        std::array<double, 4> k{0, static_cast<double>(cells), 0, static_cast<double>(cells)};
        if (p.kind == Placed::Kind::Box) {
          std::array<double, 4> uv;
          if (!faceRectangle(p.box, c, a, s, 0.25 * r0, uv)) continue;
          if (!(uv[0] - pad <= halfSide && uv[1] + pad >= -halfSide && uv[2] - pad <= halfSide &&
                uv[3] + pad >= -halfSide))
            continue;
          i0 = index(uv[0] - pad), i1 = index(uv[1] + pad);
          j0 = index(uv[2] - pad), j1 = index(uv[3] + pad);
          k = {(uv[0] - pad + halfSide) / width, (uv[1] + pad + halfSide) / width,
               (uv[2] - pad + halfSide) / width, (uv[3] + pad + halfSide) / width};
        }
        // The part of cell (i, j) the rectangle covers, in 256ths, rounded outwards.
        const auto part = [](double lo, double hi, int cell) {
          const auto at = [cell](double x) {
            return static_cast<std::uint8_t>(std::clamp(std::floor((x - cell) * 256), 0.0, 255.0));
          };
          return std::array<std::uint8_t, 2>{at(lo), at(hi)};
        };
        const int face = 2 * a + (s < 0 ? 1 : 0);
        for (int j = j0; j <= j1; ++j)
          for (int i = i0; i <= i1; ++i) {
            const double u0 = -halfSide + i * width - pad, u1 = u0 + width + 2 * pad;
            const double v0 = -halfSide + j * width - pad, v1 = v0 + width + 2 * pad;
            const Cone cone(a, s, u0, u1, v0, v1);
            double d;
            if (p.kind == Placed::Kind::Box) {
              d = std::max(p.distance, boxDistanceAlong(p.box, c, cone) * (1 - 1e-9));
            } else {
              const double reach = cone.maxDot(p.towards);
              if (!(reach > 0)) continue;  // no direction of the cell meets the plane
              d = std::max(p.distance, p.distance / (reach * (1 + 1e-9)));
            }
            const std::array<std::uint8_t, 2> ui = part(k[0], k[1], i), vj = part(k[2], k[3], j);
            if (std::isfinite(d))
              f(static_cast<std::size_t>((face * cells + j) * cells + i), d,
                std::array<std::uint8_t, 4>{ui[0], ui[1], vj[0], vj[1]},
                CellCone{a, s, {u0, u1}, {v0, v1}});
          }
      }
  };
  std::vector<std::uint32_t> counts;
  for (;; n /= 2) {
    if (n < 8) return std::nullopt;
    const std::size_t cellCount = 6 * static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    const std::size_t budget = cellCount + options.entriesPerPrimitive * faced.size();
    counts.assign(cellCount, 0);
    std::size_t total = 0;
    for (const std::uint32_t k : faced) {
      forEachCell(placed[k], n, [&](std::size_t cell, double, const auto&, const CellCone&) {
        ++counts[cell];
        ++total;
      });
      if (total > budget) break;
    }
    if (total <= budget) break;
  }
  lb.n_ = n;
  lb.halfSide_ = halfSide;
  lb.scale_ = n / (2 * halfSide);
  lb.cellStart_.resize(counts.size() + 1);
  lb.cellStart_[0] = 0;
  for (std::size_t cell = 0; cell < counts.size(); ++cell)
    lb.cellStart_[cell + 1] = lb.cellStart_[cell] + counts[cell];
  lb.entries_.resize(lb.cellStart_.back());
  std::vector<std::uint32_t> next(lb.cellStart_.begin(), lb.cellStart_.end() - 1);
  for (const std::uint32_t k : faced) {
    const Placed& p = placed[k];
    const std::uint32_t flags = flagsOf(primitives, p.primitive, flats, flatOf, c, r0, certain);
    const std::uint32_t what = flags & FLAT ? flatOf[p.primitive] : p.primitive;
    const std::uint32_t code = what | flags << FLAG_SHIFT;
    const FlatShape* flat = flags & CERTAIN ? &flats.record(what) : nullptr;
    forEachCell(p, n,
                [&](std::size_t cell, double d, const std::array<std::uint8_t, 4>& sub,
                    const CellCone& cone) {
                  std::uint32_t where = 0;
                  if (flat != nullptr) where = placeCell(*flat, c, cone, lb.certainInside_);
                  const bool whole = sub[0] == 0 && sub[1] == 255 && sub[2] == 0 && sub[3] == 255;
                  lb.entries_[next[cell]++] = Entry{
                      floatBelow(d), code | (where | (whole ? WHOLE : 0u)) << FLAG_SHIFT, sub};
                });
  }
  const auto nearer = [](const Entry& x, const Entry& y) {
    return x.distance < y.distance || (x.distance == y.distance && x.code < y.code);
  };
  for (std::size_t cell = 0; cell < counts.size(); ++cell)
    std::sort(lb.entries_.begin() + lb.cellStart_[cell],
              lb.entries_.begin() + lb.cellStart_[cell + 1], nearer);
  std::sort(lb.near_.begin(), lb.near_.end(), nearer);
  return lb;
}

std::span<const LightBuffer::Entry> LightBuffer::cell(int face, int i, int j) const noexcept {
  const auto k = static_cast<std::size_t>((face * n_ + j) * n_ + i);
  return std::span<const Entry>(entries_).subspan(cellStart_[k], cellStart_[k + 1] - cellStart_[k]);
}

std::array<int, 3> LightBuffer::cellOf(const Double3& direction) const noexcept {
  std::array<int, 2> sub;
  const std::uint32_t k = cellIndex(direction, sub);
  const auto n = static_cast<std::uint32_t>(n_);
  return {static_cast<int>(k / (n * n)), static_cast<int>(k % n), static_cast<int>(k / n % n)};
}

std::size_t LightBuffer::memoryBytes() const noexcept {
  return near_.capacity() * sizeof(Entry) + cellStart_.capacity() * sizeof(std::uint32_t) +
         entries_.capacity() * sizeof(Entry);
}

}  // namespace rt
