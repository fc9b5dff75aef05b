#pragma once
/// @file LightBuffer.h
/// Haines and Greenberg's light buffer (1986): for one point light, a cube of directions around
/// it, each face a grid of cells, each cell the list of the primitives seen from the light in
/// that cell's directions. A shadow ray aimed at the light tests the primitives of one cell, in
/// order of their distance from the light, and stops at the first one farther than the ray's
/// origin: no tree to walk. The same hits as any walk over the same primitives, bit for bit,
/// because the exact tests are the same and the lists never miss a primitive a ray could hit
/// (the proof is below).
///
///                  cube face (a, s)          a ray aimed at the light c, from its origin o:
///            +---+---+---+---+---+            its direction from c, g = −dir, picks the face
///            |   |   | ● |   |   |            (the axis a of g's largest component, s its sign)
///            +---+---+---+---+---+            and the cell: u = g_b/|g_a|, v = g_c/|g_a|
///            |   | ▒▒▒▒▒▒▒▒▒ |   |            (b, c the other two axes) on the face's grid.
///            +---+---▒-------+---+            A primitive is listed in every cell its box meets
///                  c *                        (the box's corners projected the same way).
///
/// **Claim.** For a ray o + t·dir aimed at the light (below), every primitive with a computed
/// root t in (0, tMax] is in the ray's cell or in the light's list of near primitives.
///
/// **Proof.** Let w = o − c and g = −dir (|g| = 1 up to rounding). A point X = o + t·dir has
/// X − c = (w·g − t)·g + w⊥, with w⊥ the part of w across g and ρ = |w⊥| the distance from c to
/// the ray's line. The query takes the ray only when ρ <= R0/10^4, w·g >= R0 and tMax <= w·g +
/// R0/2, for a near radius R0; otherwise it walks the fallback structure. Take a primitive with a
/// root t in (0, tMax]; the point X lies in the primitive's trusted box (the box a BVH trusts:
/// every computed root's point lies in it, FloatBox.h).
///  1. If |X − c| < R0, the box comes within R0 of c: the primitive is on the near list.
///  2. Else (w·g − t)² + ρ² >= R0², so |w·g − t| > R0/2, and w·g − t >= −R0/2 (t <= tMax): so
///     α = w·g − t > R0/2 > 0. X − c = α·g + w⊥ makes an angle of at most θ = 1.2·ρ/R0 with g,
///     and its component along the face's axis, s·(X − c)_a >= α/√3 − ρ > R0/4: X is among the
///     box's points that the face's projection takes (those at least R0/4 in front of the light
///     along a). On the face, an angle θ moves (u, v) by at most 3.1·θ per coordinate (the
///     derivative of tan is 1 + u² + v² <= 3 there), and every primitive's rectangle of (u, v) is
///     padded by 4θ_max plus rounding: the cell of g holds a point of the padded rectangle.
///  3. Distance: |X − c| <= α + ρ <= w·g + R0 for t > 0, and a listed primitive's distance from
///     c (its box's, rounded down) is at most |X − c|: the query may stop at the first primitive
///     of a cell (sorted by that distance) farther than w·g + R0.
/// Unbounded primitives (planes, tubes) and those beyond the float range are on the near list,
/// with a lower bound of their distance from c. So the query tests a superset of the primitives
/// that have a root in (0, tMax], with their own exact solvers: the same roots as a walk.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "bvh/FlatShapes.h"
#include "geometries/Geometry.h"
#include "intersections/HitRules.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"
#include "primitives/Point.h"
#include "primitives/Ray.h"

namespace rt {

/// How a light buffer is built.
struct LightBufferOptions {
  /// Cells along a face's side; 0: from the number of bounded primitives (16 to 128).
  int resolution = 0;
  /// The most list entries (a primitive in a cell) a buffer may hold per primitive, beyond one
  /// per cell; a finer grid that would hold more is halved, down to 8 cells a side, and below
  /// that no buffer is made (build() returns nullopt).
  std::size_t entriesPerPrimitive = 64;
  /// The most bounded primitives a buffer may keep on its near list (within R0 of the light),
  /// which every query tests; with more, no buffer is made (build() returns nullopt) and the walk,
  /// which tests about as many shapes per ray, answers instead.
  std::size_t nearPrimitives = 8;
};

class LightBuffer {
 public:
  /// A primitive as a list holds it: its number, and its distance from the light (a lower bound,
  /// in float rounded down).
  struct Entry {
    float distance;
    /// How it is tested (the top seven bits: Flags) and what: the primitive's number, or for a
    /// flat shape its record in the FlatShapes table (the low FLAG_SHIFT = 25 bits).
    std::uint32_t code;
    /// The part of the cell the primitive's padded rectangle covers, in 256ths of the cell:
    /// columns [sub[0], sub[1]], rows [sub[2], sub[3]]. A ray outside it cannot hit the
    /// primitive (the same argument as for the cell, at a finer grain).
    std::array<std::uint8_t, 4> sub{0, 255, 0, 255};

    std::uint32_t index() const noexcept { return code & INDEX_MASK; }
    std::uint32_t flags() const noexcept { return code >> FLAG_SHIFT; }
  };
  /// How a cell's entry is tested. Neither SPHERE nor FLAT: its shape's solver through
  /// Primitives. SPHERE: the sphere's solver directly. FLAT (a polygon or a triangle whose plane
  /// is at least R0 from the light): first the side of its plane the ray starts on, since a ray
  /// that starts on the light's side cannot cross it before the light (LightBuffer.cpp proves
  /// it); BACK when its normal points away from the light's side. CERTAIN: a flat shape whose
  /// crossing may be decided without its solver, with margins (LightBuffer.cpp).
  enum Flags : std::uint32_t {
    SPHERE = 1,
    FLAT = 2,
    BACK = 4,
    CERTAIN = 8,
    INSIDE = 16,   ///< CERTAIN, and every ray of the cell crosses the shape well inside
    OUTSIDE = 32,  ///< CERTAIN, and every ray of the cell crosses its plane well outside an
                   ///< edge and well inside another
    WHOLE = 64,    ///< the entry covers the whole cell (sub is 0..255 both ways)
  };
  static constexpr int FLAG_SHIFT = 25;
  static constexpr std::uint32_t INDEX_MASK = (1u << FLAG_SHIFT) - 1;

  /// The buffer of a point light at `light` over the primitives (viewed, not copied: they must
  /// outlive it unchanged); nullopt when its lists would exceed options' budget even at 8 cells a
  /// side, or when more than options.nearPrimitives bounded primitives lie within R0 of the
  /// light. @throws std::invalid_argument when options.resolution is negative or above 1024.
  /// flats: the records of the primitives' triangles and polygons (shapes), and flatOf[i] the
  /// record of shape i (any value for other shapes); both must outlive the buffer.
  static std::optional<LightBuffer> build(Primitives primitives, const Point& light,
                                          const FlatShapes& flats,
                                          std::span<const std::uint32_t> flatOf,
                                          const LightBufferOptions& options = {});

  /// Calls visit for every hit with t in (0, tMax] of ray (the same hits as a walk) and returns
  /// true when it went through and false when visit stopped it; returns nullopt, having visited
  /// nothing, when the ray is not aimed at the light (the caller walks instead: see the proof).
  /// Adds the exact tests it made to tests.
  template <typename Visit>
  std::optional<bool> forEachHit(const Ray& ray, double tMin, double tMax, const Visit& visit,
                                 std::uint64_t& tests, std::uint64_t& certified) const;

  // ---- Inspection: for the tests and the README ----
  const Point& light() const noexcept { return light_; }
  int resolution() const noexcept { return n_; }
  /// The near radius R0 of the proof.
  double nearRadius() const noexcept { return nearRadius_; }
  /// Primitives tested for every ray that reaches their distance: within R0 of the light, or
  /// unbounded and not planes (tubes), or beyond floats.
  std::span<const Entry> nearList() const noexcept { return near_; }
  /// A plane, tested for every ray unless the ray's origin is on the light's side of it.
  struct PlaneEntry {
    Double3 normal;  ///< the plane's unit normal, pointed from it towards the light
    double offset;   ///< normal·q for the plane's point q
    double margin;   ///< a side test below this is not trusted (rounding)
    std::uint32_t primitive;
  };
  std::span<const PlaneEntry> planes() const noexcept { return planes_; }
  /// The list of cell (face, column i, row j): face = 2·axis + (negative ? 1 : 0).
  std::span<const Entry> cell(int face, int i, int j) const noexcept;
  /// The cell a direction from the light falls in, as the query finds it: {face, i, j}.
  std::array<int, 3> cellOf(const Double3& direction) const noexcept;
  /// Entries of every cell (a primitive counted once per cell it is listed in).
  std::size_t entryCount() const noexcept { return entries_.size(); }
  std::size_t memoryBytes() const noexcept;

  /// The largest distance ρ from the light to a ray's line, relative to R0, that the query takes.
  static constexpr double AIM = 1e-4;
  /// The near radius R0 for a scene of size S (the largest coordinate of the primitives' trusted
  /// boxes and of the light, at least 1) whose bounded primitives' boxes lie within E of the
  /// light (their farthest corners): 10^-3 of the smaller of S and E, and at least 10^-4·S. So a
  /// scene far from the origin relative to its size does not put its shapes around the light on
  /// the near list. The proofs ask only R0 in [10^-4·S, 10^-3·S]: R0 far above the rounding of
  /// coordinates of size S (some 10^-16·S) and AIM·R0 above the shadow rays' shift off the
  /// surface (RayOffset: 10^-9 of the point's largest coordinate).
  static double nearRadiusOf(double size, double reach) noexcept {
    return std::max(NEAR_FLOOR * size, NEAR * std::min(size, reach));
  }
  static constexpr double NEAR = 1e-3;
  static constexpr double NEAR_FLOOR = 1e-4;
  /// The half side of a face in (u, v), past 1 so that a direction near a cube edge is found on
  /// either face: 1 + MARGIN, MARGIN far above the 3.1·θ of the proof.
  static constexpr double FACE_MARGIN = 1e-3;
  /// The smallest |n·dir| of a ray whose crossing of a flat shape may be certain.
  static constexpr double MIN_SLOPE = 1e-3;
  /// A crossing is certain only for a ray whose origin's coordinates are within CERTAIN_REACH
  /// times the scene's size S (the largest coordinate of the primitives' boxes and the light),
  /// at least CERTAIN_MARGIN·S behind the shape's plane, and crossing it at least
  /// CERTAIN_MARGIN·S inside (or outside) its edges.
  static constexpr double CERTAIN_REACH = 4;
  static constexpr double CERTAIN_MARGIN = 1e-3;

 private:
  LightBuffer() = default;
  /// The cell of direction g from the light, and where in it (sub: column, row in 256ths).
  std::uint32_t cellIndex(const Double3& g, std::array<int, 2>& sub) const noexcept;

  Primitives primitives_{std::span<const Geometry>{}};
  const FlatShapes* flats_ = nullptr;
  /// The flat shapes' planes (n·x = offset), by record: the side test's data, packed.
  struct FlatPlane {
    Double3 n;
    double offset;
    std::uint32_t shape;
  };
  std::vector<FlatPlane> flatPlanes_;
  Point light_ = Point::ZERO;
  int n_ = 0;
  double nearRadius_ = 0;
  double aimSquared_ = 0;  ///< (AIM·R0)²
  double halfSide_ = 1 + FACE_MARGIN;
  double scale_ = 0;  ///< n / (2·halfSide)
  std::vector<Entry> near_;
  std::vector<PlaneEntry> planes_;
  double sideMargin_ = 0;     ///< 10^-13 of the largest coordinate of the primitives' boxes
  double certainReach_ = 0;   ///< the origin's largest coordinate for a certain crossing
  double certainDepth_ = 0;   ///< how far behind a flat shape's plane the origin must be
  double certainInside_ = 0;  ///< how far inside (or outside) its edges the crossing must be
  std::vector<std::uint32_t> cellStart_;  ///< 6·n² + 1 offsets into entries_
  std::vector<Entry> entries_;
};

inline std::uint32_t LightBuffer::cellIndex(const Double3& g,
                                            std::array<int, 2>& sub) const noexcept {
  const double ax = std::abs(g.x), ay = std::abs(g.y), az = std::abs(g.z);
  int axis;
  double major, b, c, sign;
  if (ax >= ay && ax >= az) {
    axis = 0, major = ax, b = g.y, c = g.z, sign = g.x;
  } else if (ay >= az) {
    axis = 1, major = ay, b = g.z, c = g.x, sign = g.y;
  } else {
    axis = 2, major = az, b = g.x, c = g.y, sign = g.z;
  }
  const int face = 2 * axis + (sign < 0 ? 1 : 0);
  const double inv = scale_ / major;
  const double last = n_ - 1;
  const auto index = [&](double x, int& within) {
    const double k = std::clamp(x * inv + static_cast<double>(n_) * 0.5, 0.0, last + 0.999);
    const int i = static_cast<int>(k);
    within = static_cast<int>((k - i) * 256);
    return i;
  };
  const int i = index(b, sub[0]);
  const int j = index(c, sub[1]);
  return static_cast<std::uint32_t>((face * n_ + j) * n_ + i);
}

template <typename Visit>
[[gnu::always_inline]] inline std::optional<bool> LightBuffer::forEachHit(
    const Ray& ray, double tMin, double tMax, const Visit& visit, std::uint64_t& tests,
    std::uint64_t& certified) const {
  const Double3 w = ray.head().xyz() - light_.xyz();
  const Double3 g = -ray.direction().xyz();
  const double wg = w.dot(g);
  const double r0 = nearRadius_;
  // The proof's conditions, written so that a NaN fails them.
  if (!(wg >= r0) || !(tMax <= wg + 0.5 * r0)) {
    return std::nullopt;
  }
  const Double3 across = w.cross(g);
  if (!(across.lengthSquared() <= aimSquared_)) {
    return std::nullopt;
  }
  const double gg = g.lengthSquared();
  if (!(gg >= 1 - 1e-6 && gg <= 1 + 1e-6)) return std::nullopt;
  const double reach = wg + r0;
  // At or above reach (2^-20 up, then rounded to a float: 2^-24 at most): never drops an entry.
  const auto reachF = static_cast<float>(reach * (1 + 0x1p-20));
  std::array<int, 2> sub;
  const std::uint32_t cell = cellIndex(g, sub);
  const Entry* e = entries_.data() + cellStart_[cell];
  const Entry* const end = entries_.data() + cellStart_[cell + 1];
  for (const Entry& near : near_) {
    if (near.distance > reach) continue;
    ++tests;
    if (!visitHits(primitives_.roots(near.index(), ray), near.index(), tMax, visit)) return false;
  }
  // A plane the ray starts on the light's side of lies beyond the light: no hit (the file
  // comment of LightBuffer.cpp says why the margin suffices).
  const Double3& o = ray.head().xyz();
  const double oMagnitude = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)});
  const double oMargin = 1e-13 * oMagnitude;
  for (const PlaneEntry& plane : planes_) {
    if (plane.normal.dot(o) - plane.offset > plane.margin + oMargin) continue;
    ++tests;
    if (!visitHits(primitives_.roots(plane.primitive, ray), plane.primitive, tMax, visit))
      return false;
  }
  const double sideMargin = oMargin + sideMargin_;
  const std::span<const Geometry> shapes = primitives_.shapes();
  // Whether this ray's flat crossings may be decided with margins: its origin within the
  // scene's reach, its range reaching close to the light and starting well before any certain
  // crossing (LightBuffer.cpp).
  const bool certain =
      oMagnitude <= certainReach_ && tMax >= wg - 0.5 * r0 && tMin <= 0.5 * certainDepth_;
  const Double3& dir = ray.direction().xyz();
  for (; e != end && e->distance <= reachF; ++e) {
    const std::uint32_t index = e->index();
    const std::uint32_t flags = e->flags();
    // One branch for the four comparisons (a bitwise or of ints, not ||): which way it goes is
    // as random as the rays.
    if (!(flags & WHOLE) && (int{sub[0] < e->sub[0]} | int{sub[0] > e->sub[1]} |
                             int{sub[1] < e->sub[2]} | int{sub[1] > e->sub[3]}))
      continue;
    std::uint32_t primitive = index;
    Roots roots;
    if (flags & SPHERE) {
      const Sphere& sphere = *std::get_if<Sphere>(&shapes[index]);
      roots = intersectSphereRoots(sphere.center().xyz(), sphere.radius(), ray);
    } else if (!(flags & FLAT)) {
      roots = primitives_.roots(index, ray);
    } else {
      const FlatPlane& plane = flatPlanes_[index];
      primitive = plane.shape;
      const double side = plane.n.dot(o) - plane.offset;
      // > 0: on the light's side (the side's sign flipped for BACK, without a branch).
      const double lit = std::bit_cast<double>(std::bit_cast<std::uint64_t>(side) ^
                                               std::uint64_t{flags & BACK} << 61);
      if (lit > sideMargin) continue;
      if (certain && (flags & CERTAIN) && -lit >= certainDepth_) {
        if (flags & INSIDE) {  // the cell's rays cross it well inside, at a slope: no solver
          ++certified;
          // Crossed once, somewhere in [tMin, tMax]: the query needs no more (LightOccluders).
          if (!visit(Hit{tMax, primitive})) return false;
          continue;
        }
        if (flags & OUTSIDE) continue;  // they cross its plane well outside it
        const double slope = plane.n.dot(dir);
        if (std::abs(slope) >= MIN_SLOPE) {
          const double t = -side / slope;
          const Double3 x = o + dir * t;
          const auto [inside, outside] = edgeDistanceRange(flats_->record(index), x);
          if (inside >= certainInside_) {  // crossed, well inside: no solver
            ++certified;
            if (!visit(Hit{t, primitive})) return false;
            continue;
          }
          if (inside <= -certainInside_ && outside >= certainInside_) continue;  // missed
        }
      }
      roots = flats_->roots(index, ray);
    }
    ++tests;
    if (!visitHits(roots, primitive, tMax, visit)) return false;
  }
  return true;
}

}  // namespace rt
