#pragma once
/// @file ShadowCrossings.h
/// One shadow ray's crossings, gathered as a walk finds them: what ShadowQuery does between the
/// hits of its walk, written out (and inline) so that a structure which finds a shadow ray's hits
/// itself (LightOccluders: mini2_bvh's light buffers) hands them over without a call per hit.
///
/// Each hit with t >= tMin is a crossing. An opaque blocker (kT = 0) decides the answer, 0, in
/// any order, and so does a partial product below the cut-off when no kT of the scene exceeds 1
/// (every further factor can only lower it; the margin, far above the rounding differences
/// between orders, keeps the decision independent of the order). Otherwise up to CAPACITY
/// crossings are kept, and their kT multiplied in the canonical order (shape index, t): the same
/// bits whatever order the walk found them in (ShadowQuery.h says why that matters).

#include <cstdint>
#include <utility>

#include "intersections/Intersectable.h"
#include "lighting/LitScene.h"
#include "primitives/Double3.h"

namespace rt {

class ShadowCrossings {
 public:
  /// Crossings kept for the canonical order.
  static constexpr int CAPACITY = 16;
  /// A partial product stops the walk when below cutOff·(1 − MARGIN): far above the relative
  /// rounding difference between two orders of the same factors (~n·2^-53 for n factors).
  static constexpr double MARGIN = 1e-9;

  /// @param productOnlyFalls true when no kT of the scene exceeds 1 in any channel.
  /// @param weight the path weight of the point being shaded.
  ShadowCrossings(const LitScene& scene, double cutOff, bool productOnlyFalls, double tMin,
                  const Double3& weight) noexcept
      : scene_(scene),
        stopBelow_(cutOff * (1 - MARGIN)),
        tMin_(tMin),
        weight_(weight),
        productOnlyFalls_(productOnlyFalls) {}

  /// One hit of the walk (in any order). Returns false once the answer is known without the
  /// hits still to come (an opaque blocker, or the cut-off): the walk may stop.
  [[gnu::always_inline]] bool add(const Hit& hit) noexcept {
    // BEGIN SOLUTION: hint: ShadowCrossings::add, a crossing from tMin on; stop at an opaque one
    if (hit.t < tMin_) return true;  // within ε of the origin: the surface itself
    ++count_;
    const Double3& k = kT(hit.geometry);
    bool cut = k.isExactlyZero();  // an opaque blocker: 0 in any order
    if (!cut && productOnlyFalls_) {
      partial_ = partial_ * k;
      cut = partial_.lowerThan(stopBelow_) || (partial_ * weight_).lowerThan(stopBelow_);
    }
    if (cut) {
      stoppedEarly_ = true;
      return false;
    }
    if (kept_ < CAPACITY)
      crossings_[kept_++] = {hit.geometry, hit.t};
    else
      overflow_ = true;
    return true;
    // END SOLUTION
  }

  /// Π kT of the crossings kept, in the canonical order (shape index, t): the answer when the
  /// walk neither stopped early nor met more than CAPACITY crossings.
  Double3 product() noexcept {
    // BEGIN SOLUTION: hint: ShadowCrossings::product, sort by (shape, t), then multiply
    // Insertion sort: a handful of crossings at most.
    for (int i = 1; i < kept_; ++i)
      for (int j = i; j > 0 && before(crossings_[j], crossings_[j - 1]); --j)
        std::swap(crossings_[j], crossings_[j - 1]);
    Double3 factor = Double3::ONE;
    for (int i = 0; i < kept_; ++i) factor = factor * kT(crossings_[i].geometry);
    return factor;
    // END SOLUTION
  }

  /// The crossings met (hits from tMin on) before the walk ended.
  int count() const noexcept { return count_; }
  /// True when an opaque blocker or the cut-off decided the answer, 0.
  bool stoppedEarly() const noexcept { return stoppedEarly_; }
  /// True when more than CAPACITY crossings were met: product() lacks some of them.
  bool overflow() const noexcept { return overflow_; }

  /// A crossing, ordered by (geometry, t): the canonical order of the product.
  struct Crossing {
    std::uint32_t geometry;
    double t;
  };
  static bool before(const Crossing& a, const Crossing& b) noexcept {
    return a.geometry < b.geometry || (a.geometry == b.geometry && a.t < b.t);
  }

 private:
  const Double3& kT(std::uint32_t geometry) const noexcept {
    return scene_.appearanceOf(geometry).material.kT;
  }

  const LitScene& scene_;
  double stopBelow_;
  double tMin_;
  const Double3& weight_;
  bool productOnlyFalls_;
  bool stoppedEarly_ = false;
  bool overflow_ = false;
  int count_ = 0;
  int kept_ = 0;
  Double3 partial_ = Double3::ONE;  // in the walk's order: only to decide an early stop
  Crossing crossings_[CAPACITY];
};

}  // namespace rt
