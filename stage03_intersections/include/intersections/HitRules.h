#pragma once
/// @file HitRules.h
/// The two rules of Intersectable's queries, applied to one shape's roots at a time, written once
/// for every implementation (the linear Geometries here; the CBR and the BVH of mini project 2),
/// so that they all give the same answers, bit for bit, whatever order they test shapes in.

#include <cstdint>
#include <optional>

#include "intersections/Intersect.h"
#include "intersections/Intersectable.h"

namespace rt {

/// The closest-hit rule: among the shapes offered, in any order, the smallest (t, geometry) pair
/// whose t lies in (0, tMax] (withinDistance, inclusive). Ordering by the pair, not by t alone,
/// makes the answer independent of the order: of two shapes hit at exactly the same t, the one
/// with the smaller index wins, as in a scan by index.
class NearestHit {
 public:
  explicit NearestHit(double tMax) noexcept : tMax_(tMax) {}

  /// Offers one shape's roots (ascending, as every solver returns them): its nearest root counts
  /// when it is within tMax and beats the best pair so far.
  void offer(const Roots& roots, std::uint32_t geometry) noexcept {
    if (roots.empty()) return;
    const double t = roots[0];
    if (!withinDistance(t, tMax_)) return;
    if (!found_ || t < t_ || (t == t_ && geometry < geometry_)) {
      t_ = t;
      geometry_ = geometry;
      found_ = true;
    }
  }

  /// The best t so far, +∞ before any hit. A shape (or a box of shapes) whose hits all lie
  /// strictly beyond it cannot win; one at exactly this t still can, with a smaller index.
  double t() const noexcept { return t_; }

  std::optional<Hit> hit() const noexcept {
    return found_ ? std::optional<Hit>(Hit{t_, geometry_}) : std::nullopt;
  }

 private:
  double tMax_;
  double t_ = INFINITE_DISTANCE;
  std::uint32_t geometry_ = 0;
  bool found_ = false;
};

/// The forEachHit rule for one shape: visits its roots within tMax in ascending order (the first
/// beyond tMax ends the walk). Returns false when visit asked to stop.
inline bool visitHits(const Roots& roots, std::uint32_t geometry, double tMax,
                      const HitVisitor& visit) {
  for (double t : roots) {
    if (!withinDistance(t, tMax)) break;
    if (!visit(Hit{t, geometry})) return false;
  }
  return true;
}

}  // namespace rt
