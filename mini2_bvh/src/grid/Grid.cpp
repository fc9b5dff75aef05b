// The regular grid: its build (the resolution, each shape listed in the cells its box touches,
// counted, then filled into one flat array) and its queries (the 3D-DDA walk of Amanatides and
// Woo, each shape tested in the first cell of its run only). Grid.h explains the choices.

#include "grid/Grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "bvh/BoundingBox.h"
#include "bvh/FloatBox.h"
#include "bvh/HugePages.h"
#include "bvh/SlabRay.h"
#include "bvh/UnboundedShapes.h"
#include "intersections/HitRules.h"

namespace rt {

namespace {

constexpr std::uint32_t SHAPE_BITS = 26;
constexpr std::uint32_t SHAPE_MASK = (1u << SHAPE_BITS) - 1;

/// The cells per axis for `shapes` bounded shapes in a box of the given extents (Grid.h).
std::array<int, 3> resolutionFor(const Double3& extent, std::size_t shapes) {
  std::array<int, 3> n{1, 1, 1};
  std::array<bool, 3> free{};
  for (int a = 0; a < 3; ++a) free[a] = component(extent, a) > 0;
  // Each pass hands the cells to the axes still free; an axis that gets a single cell is fixed
  // at one and the next pass shares its cells among the others (at most three passes).
  for (int pass = 0; pass < 3; ++pass) {
    int m = 0;
    double volume = 1;
    for (int a = 0; a < 3; ++a)
      if (free[a]) {
        ++m;
        volume *= component(extent, a);
      }
    if (m == 0) break;
    const double k =
        std::pow(Grid::CELLS_PER_SHAPE * static_cast<double>(shapes) / volume, 1.0 / m);
    bool fixedOne = false;
    for (int a = 0; a < 3; ++a) {
      if (!free[a]) continue;
      const double cells = std::clamp(std::round(k * component(extent, a)), 1.0,
                                      static_cast<double>(Grid::MAX_CELLS_PER_AXIS));
      n[a] = static_cast<int>(cells);
      if (n[a] == 1) {
        free[a] = false;
        fixedOne = true;
      }
    }
    if (!fixedOne) break;
  }
  return n;
}

bool isFinite(const FloatBox& b) noexcept {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a])) return false;
  return true;
}

}  // namespace

Grid::Grid(Primitives primitives) : primitives_(primitives) {
  // The large arrays on 2 MiB pages where the system offers them (HugePages.h), those written
  // whole with their pages made at once; the two lists reserved for every primitive (address
  // space: only what is written takes memory).
  std::vector<std::uint32_t> bounded;
  std::vector<Aabb> boxes;
  reserveHuge(bounded, primitives.size());
  reserveHuge(boxes, primitives.size());
  for (std::uint32_t i = 0; i < primitives.size(); ++i) {
    const std::optional<Aabb> exact = boundingBox(primitives, i);
    const FloatBox stored = exact ? conservativeBox(*exact) : FloatBox::empty();
    if (!exact || !isFinite(stored)) {
      unbounded_.push_back(i);
      continue;
    }
    bounded.push_back(i);
    boxes.push_back(stored.widen());
    box_.expand(boxes.back());
  }
  if (bounded.empty()) return;
  if (bounded.back() >= MAX_SHAPES)
    throw std::length_error("Grid: bounded primitive " + std::to_string(bounded.back()) +
                            " of the scene's " + std::to_string(primitives.size()) +
                            ": an entry holds indices below " + std::to_string(MAX_SHAPES));

  n_ = resolutionFor(box_.extent(), bounded.size());
  for (int a = 0; a < 3; ++a) {
    const double d = component(box_.extent(), a);
    width_[a] = d / n_[a];
    invWidth_[a] = d > 0 ? n_[a] / d : 0;
  }
  // A shape's cells: the index box of its stored box widened by CELL_MARGIN of a cell.
  struct CellRange {
    std::array<int, 3> lo, hi;
  };
  auto cellOf = [this](double p, int a) {
    const double u = (p - component(box_.lo, a)) * invWidth_[a];
    if (!(u > 0)) return 0;
    if (u >= n_[a]) return n_[a] - 1;
    return static_cast<int>(u);
  };
  std::vector<CellRange> ranges;
  reserveHugeWritten(ranges, bounded.size());
  ranges.resize(bounded.size());
  for (std::size_t s = 0; s < bounded.size(); ++s)
    for (int a = 0; a < 3; ++a) {
      const double margin = CELL_MARGIN * width_[a];
      ranges[s].lo[a] = cellOf(component(boxes[s].lo, a) - margin, a);
      ranges[s].hi[a] = cellOf(component(boxes[s].hi, a) + margin, a);
    }

  // Count the entries of each cell (in offsets_[c + 1]), add them up into offsets, then fill.
  const std::size_t cells = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
  const auto cellIndex = [this](int x, int y, int z) {
    return static_cast<std::size_t>(x) +
           static_cast<std::size_t>(n_[0]) *
               (static_cast<std::size_t>(y) + static_cast<std::size_t>(n_[1]) * z);
  };
  reserveHugeWritten(offsets_, cells + 1);
  offsets_.assign(cells + 1, 0);
  std::uint64_t total = 0;
  for (const CellRange& r : ranges) {
    for (int z = r.lo[2]; z <= r.hi[2]; ++z)
      for (int y = r.lo[1]; y <= r.hi[1]; ++y)
        for (int x = r.lo[0]; x <= r.hi[0]; ++x) ++offsets_[cellIndex(x, y, z) + 1];
    total += static_cast<std::uint64_t>(r.hi[0] - r.lo[0] + 1) * (r.hi[1] - r.lo[1] + 1) *
             (r.hi[2] - r.lo[2] + 1);
    if (total > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("Grid: more than 2^32 (cell, shape) entries for " +
                              std::to_string(bounded.size()) + " shapes");
  }
  for (std::size_t c = 0; c < cells; ++c) offsets_[c + 1] += offsets_[c];
  reserveHugeWritten(entries_, total);
  entries_.resize(total);
  std::vector<std::uint32_t> next;
  reserveHugeWritten(next, cells);
  next.assign(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t s = 0; s < bounded.size(); ++s) {
    const CellRange& r = ranges[s];
    for (int z = r.lo[2]; z <= r.hi[2]; ++z)
      for (int y = r.lo[1]; y <= r.hi[1]; ++y)
        for (int x = r.lo[0]; x <= r.hi[0]; ++x) {
          // The face bits: bit a when the cell is the range's lowest on axis a, bit 3 + a when
          // it is its highest.
          const std::array<int, 3> at{x, y, z};
          std::uint32_t faces = 0;
          for (int a = 0; a < 3; ++a) {
            if (at[a] == r.lo[a]) faces |= 1u << a;
            if (at[a] == r.hi[a]) faces |= 8u << a;
          }
          entries_[next[cellIndex(x, y, z)]++] = bounded[s] | faces << SHAPE_BITS;
        }
  }
}

std::vector<std::uint32_t> Grid::cellShapes(int x, int y, int z) const {
  if (x < 0 || y < 0 || z < 0 || x >= n_[0] || y >= n_[1] || z >= n_[2]) return {};
  const std::size_t c = static_cast<std::size_t>(x) + static_cast<std::size_t>(n_[0]) * y +
                        static_cast<std::size_t>(n_[0]) * n_[1] * z;
  std::vector<std::uint32_t> shapes;
  for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k)
    shapes.push_back(entries_[k] & SHAPE_MASK);
  return shapes;
}

std::size_t Grid::memoryBytes() const noexcept {
  return (offsets_.capacity() + entries_.capacity() + unbounded_.capacity()) *
         sizeof(std::uint32_t);
}

template <typename Limit, typename Visit>
bool Grid::walk(const Ray& ray, const Limit& limit, const Visit& visit,
                std::uint64_t& cellsVisited) const {
  // BEGIN SOLUTION: hint: Grid::walk, Amanatides and Woo's 3D-DDA from the ray's entry cell
  if (offsets_.empty()) return true;
  const SlabRay slab(ray);
  double tEntry;
  if (!slabHit(slab, box_, limit(), tEntry)) return true;
  const Double3& o = ray.head().xyz();
  const Double3& d = ray.direction().xyz();
  std::array<int, 3> cell{}, step{};
  std::array<double, 3> tNext{}, inv{}, origin{}, lo{};
  // Where the ray crosses the plane of cell boundary j on axis a: the boundary lo + j·width.
  const auto crossing = [&](int a, int j) { return (lo[a] + j * width_[a] - origin[a]) * inv[a]; };
  for (int a = 0; a < 3; ++a) {
    origin[a] = component(o, a);
    lo[a] = component(box_.lo, a);
    const double da = component(d, a);
    // The entry cell: that of the entry point (rounded down: it may lie just outside the box, so
    // the index is clamped); of the origin itself when the ray starts inside.
    const double p = tEntry == 0 ? origin[a] : origin[a] + tEntry * da;
    const double u = (p - lo[a]) * invWidth_[a];
    cell[a] = !(u > 0) ? 0 : u >= n_[a] ? n_[a] - 1 : static_cast<int>(u);
    inv[a] = 1 / da;
    // A component so small that 1/d overflows counts as parallel to the axis, as in SlabRay.
    if (std::isinf(inv[a]) || da == 0) {
      step[a] = 0;
      tNext[a] = INFINITE_DISTANCE;
    } else {
      step[a] = da > 0 ? 1 : -1;
      tNext[a] = crossing(a, da > 0 ? cell[a] + 1 : cell[a]);
    }
  }
  const std::array<std::int64_t, 3> stride{1, n_[0], static_cast<std::int64_t>(n_[0]) * n_[1]};
  auto index = static_cast<std::int64_t>(cell[0] + stride[1] * cell[1] + stride[2] * cell[2]);
  int axis = -1;
  for (;;) {
    ++cellsVisited;
    if (!visit(static_cast<std::uint32_t>(index), axis, axis >= 0 && step[axis] > 0)) return false;
    // The face met first (the lowest axis on a tie): the next cell begins there.
    const int a =
        tNext[0] <= tNext[1] ? (tNext[0] <= tNext[2] ? 0 : 2) : (tNext[1] <= tNext[2] ? 1 : 2);
    if (step[a] == 0 || tNext[a] > limit()) return true;
    cell[a] += step[a];
    if (cell[a] < 0 || cell[a] >= n_[a]) return true;
    index += step[a] * stride[a];
    axis = a;
    tNext[a] = crossing(a, step[a] > 0 ? cell[a] + 1 : cell[a]);
  }
  // END SOLUTION
}

template <typename F>
bool Grid::forEachNewShape(std::uint32_t cell, int axis, bool up, const F& f) const {
  // The first cell tests every shape; a later one those it is the entry face of.
  const std::uint32_t need = axis < 0 ? 0 : ((up ? 1u : 8u) << axis) << SHAPE_BITS;
  for (std::uint32_t k = offsets_[cell]; k < offsets_[cell + 1]; ++k) {
    const std::uint32_t e = entries_[k];
    if ((e & need) != need) continue;
    if (!f(e & SHAPE_MASK)) return false;
  }
  return true;
}

std::vector<std::array<int, 3>> Grid::cellsAlong(const Ray& ray, double tMax) const {
  std::vector<std::array<int, 3>> cells;
  std::uint64_t visited = 0;
  const double limit = slabLimit(tMax);
  walk(
      ray, [limit] { return limit; },
      [&](std::uint32_t c, int, bool) {
        const auto nx = static_cast<std::uint32_t>(n_[0]), ny = static_cast<std::uint32_t>(n_[1]);
        cells.push_back({static_cast<int>(c % nx), static_cast<int>(c / nx % ny),
                         static_cast<int>(c / nx / ny)});
        return true;
      },
      visited);
  return cells;
}

std::optional<Hit> Grid::closestHit(const Ray& ray, double tMax,
                                    QueryCounts* counts) const noexcept {
  // BEGIN SOLUTION: hint: Grid::closestHit, unbounded shapes, then the walk until the best hit
  NearestHit nearest(tMax);
  std::uint64_t tests = offerUnbounded(unbounded_, primitives_, ray, nearest), visited = 0;
  const double limit = slabLimit(tMax);
  // A cell that begins strictly after the best hit cannot hold a better one; one that begins
  // exactly at it can (a smaller index), so the walk goes on into it.
  walk(
      ray, [&] { return std::min(limit, nearest.t()); },
      [&](std::uint32_t cell, int axis, bool up) {
        return forEachNewShape(cell, axis, up, [&](std::uint32_t shape) {
          ++tests;
          nearest.offer(primitives_.roots(shape, ray), shape);
          return true;
        });
      },
      visited);
  addQueryCounts(counts, tests, visited);
  return nearest.hit();
  // END SOLUTION
}

bool Grid::forEachHit(const Ray& ray, double tMax, HitVisitor visit, QueryCounts* counts) const {
  // BEGIN SOLUTION: hint: Grid::forEachHit, every hit within tMax until the visitor says stop
  std::uint64_t tests = 0, visited = 0;
  bool complete = visitUnbounded(unbounded_, primitives_, ray, tMax, visit, tests);
  if (complete) {
    const double limit = slabLimit(tMax);
    complete = walk(
        ray, [limit] { return limit; },
        [&](std::uint32_t cell, int axis, bool up) {
          return forEachNewShape(cell, axis, up, [&](std::uint32_t shape) {
            ++tests;
            return visitHits(primitives_.roots(shape, ray), shape, tMax, visit);
          });
        },
        visited);
  }
  addQueryCounts(counts, tests, visited);
  return complete;
  // END SOLUTION
}

}  // namespace rt
