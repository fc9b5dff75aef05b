#pragma once
/// @file Grid.h
/// The course's third acceleration structure: a regular grid of voxels over the scene's bounded
/// shapes, walked cell by cell along the ray with the 3D-DDA of Amanatides and Woo (1987). It is
/// an Intersectable over the same shapes and indices as the scene's Geometries and gives the same
/// answers, bit for bit (the README's "The regular grid" says why).
///
/// Build. The grid's box is the union of the bounded shapes' stored boxes (conservativeBox,
/// FloatBox.h). The resolution aims at CELLS_PER_SHAPE = 8 cells per shape, (2·∛N)³ for N
/// shapes, in cubes as near as can be: with the box's extents d_a over its m non-flat axes,
///
///     k = (8·N / ∏ d_a)^(1/m),   n_a = clamp(round(k·d_a), 1, MAX_CELLS_PER_AXIS)
///
/// and a flat axis (d_a = 0), or one that rounds to a single cell, gets n_a = 1 and k is worked
/// out again over the others. Each shape is listed in every cell its stored box touches, that box
/// widened by CELL_MARGIN of a cell on every side (see below). The cells are stored compactly: one
/// offsets array (cell c's shapes are entries [offsets[c], offsets[c+1])) and one flat array of
/// entries, cells in x-fastest order.
///
/// Walk. From the cell where the ray enters the grid's box (or starts inside it), the DDA steps
/// to the neighbour across whichever of the cell's three far faces the ray meets first, until the
/// ray leaves the grid or the next cell begins beyond the best hit so far (closest hit) or beyond
/// tMax (every hit). A shape spanning several cells is tested once per ray, without a mailbox: its
/// cells form a box of cell indices, and since each index changes monotonically along the walk,
/// the walk is inside that box during one run of steps. The shape is tested in the run's first
/// cell only: the walk's first cell, or a cell entered through the shape's entry face (the cell's
/// index on the stepped axis is the shape's lowest, stepping up, or its highest, stepping down).
/// Each entry carries those six face bits beside the shape's index, so the query stays const,
/// shares nothing between threads and allocates nothing.
///
/// Exactness. The stored boxes hold every hit the solvers compute (FloatBox.h). The DDA's own
/// rounding can misorder two face crossings that are within rounding of each other, which skips
/// the corner of a cell by a sliver of that width; the CELL_MARGIN widening lists every shape
/// near such a sliver in the cells beside it, which the walk does visit. (The sliver is about
/// 2^-50 of the distance from the ray's origin, so the margin covers origins up to about 2^30
/// cells away.)
///
/// Planes and tubes are unbounded: they stay outside the grid and are tested on their own
/// first, as in the Bvh; so are shapes whose box does not fit in floats.
///
/// QueryCounts::nodesVisited counts the cells the walk enters (a cell is the grid's node), so
/// `rt bench` and `rt probe` show cells per ray where they show the BVH's nodes per ray.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "bvh/Aabb.h"
#include "geometries/Geometry.h"
#include "intersections/Geometries.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"

namespace rt {

class Grid final : public Intersectable {
 public:
  /// The cells aimed at per bounded shape: 8 = (2·∛N)³ / N.
  static constexpr double CELLS_PER_SHAPE = 8;
  /// The most cells along one axis (256³ cells hold 2 million shapes at 8 per shape).
  static constexpr int MAX_CELLS_PER_AXIS = 256;
  /// A shape's box is widened by this fraction of a cell's width on every side before it is
  /// listed in the cells it touches (the file comment says why).
  static constexpr double CELL_MARGIN = 0x1p-20;
  /// The bound on a bounded shape's index: an entry holds the index in its low 26 bits, its six
  /// face bits above.
  static constexpr std::uint32_t MAX_SHAPES = 1u << 26;

  /// Builds the grid over shapes and mesh triangles alike (each triangle listed in its cells).
  /// @param primitives viewed, not copied (as by a std::span): the shapes and meshes must outlive
  ///        the Grid and stay unchanged. Hit indices are the primitives' numbers.
  /// @throws std::length_error when a bounded primitive's number is MAX_SHAPES or more, or the
  ///         entries outnumber 2^32.
  explicit Grid(Primitives primitives);
  explicit Grid(std::span<const Geometry> shapes) : Grid(Primitives(shapes)) {}
  explicit Grid(const Geometries& geometries) : Grid(geometries.primitives()) {}
  Grid(Geometries&&) = delete;  // would view a temporary

  /// The same answer as Geometries::closestHit over the same shapes, bit for bit. Counts every
  /// cell it enters as a visited node and every exact shape test.
  std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                QueryCounts* counts = nullptr) const noexcept override;
  /// The same hits as Geometries::forEachHit over the same shapes (in another order); stops as
  /// soon as visit returns false.
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts = nullptr) const override;

  // ---- Inspection: for the tests, the benchmark and the README's figures ----

  /// Cells along x, y, z; {0, 0, 0} when no shape is bounded.
  std::array<int, 3> resolution() const noexcept { return n_; }
  /// The grid's box (empty when no shape is bounded).
  const Aabb& box() const noexcept { return box_; }
  /// The number of cells.
  std::size_t cellCount() const noexcept { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  /// The shapes (indices into the scene) listed in cell (x, y, z), ascending.
  std::vector<std::uint32_t> cellShapes(int x, int y, int z) const;
  /// The number of (cell, shape) entries: the shapes' cell counts summed.
  std::size_t entryCount() const noexcept { return entries_.size(); }
  /// The unbounded shapes (planes, tubes; shapes beyond the float range), tested outside the grid.
  std::span<const std::uint32_t> unboundedShapes() const noexcept { return unbounded_; }
  /// Bytes the Grid holds on the heap (offsets, entries, the unbounded list).
  std::size_t memoryBytes() const noexcept;
  /// The cells the walk enters for ray up to tMax (no hit to stop it), in order: for the tests.
  std::vector<std::array<int, 3>> cellsAlong(const Ray& ray, double tMax = INFINITE_DISTANCE) const;

 private:
  /// Walks the cells the ray enters, in order, while the next one begins no later than limit()
  /// (asked again at each step, so that a closest-hit query can shrink it), calling
  /// visit(cell, axis, up) at each: the cell's index, the axis stepped to enter it (−1 for the
  /// first cell) and whether the step went up. Stops when visit returns false, and then returns
  /// false.
  template <typename Limit, typename Visit>
  bool walk(const Ray& ray, const Limit& limit, const Visit& visit,
            std::uint64_t& cellsVisited) const;
  /// Calls f(shape) for each shape of the cell to be tested there (the first cell of its run).
  template <typename F>
  bool forEachNewShape(std::uint32_t cell, int axis, bool up, const F& f) const;

  Primitives primitives_;
  Aabb box_;
  std::array<int, 3> n_{0, 0, 0};
  std::array<double, 3> width_{0, 0, 0};     ///< a cell's width per axis
  std::array<double, 3> invWidth_{0, 0, 0};  ///< n_a / d_a (0 on a flat axis)
  std::vector<std::uint32_t> offsets_;       ///< cellCount() + 1 entries
  std::vector<std::uint32_t> entries_;       ///< shape index | face bits << 26
  std::vector<std::uint32_t> unbounded_;
};

}  // namespace rt
