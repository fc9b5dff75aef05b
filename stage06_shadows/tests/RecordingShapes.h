#pragma once
// Test doubles for what a shadow query walks: a plain Intersectable that counts its forEachHit
// walks, and one that is also a LightOccluders and records which light each shadow ray was
// aimed at. Both find the hits of a Geometries (the scene's own shapes, the same indices).

#include <cmath>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "geometries/Geometry.h"
#include "intersections/Geometries.h"
#include "intersections/Intersectable.h"
#include "primitives/Ray.h"
#include "shadows/LightOccluders.h"
#include "shadows/ShadowCrossings.h"

namespace rt::test {

/// The shapes of a Geometries, counting the walks of forEachHit.
class CountingShapes : public Intersectable {
 public:
  explicit CountingShapes(const Geometries& g) : g_(g) {}
  std::optional<Hit> closestHit(const Ray& ray, double tMax,
                                QueryCounts* counts) const noexcept override {
    return g_.closestHit(ray, tMax, counts);
  }
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts) const override {
    ++forEachHitCalls;
    return g_.forEachHit(ray, tMax, visit, counts);
  }

  mutable int forEachHitCalls = 0;

 protected:
  const Geometries& g_;
};

/// Where a LightOccluders puts the crossing of a flat shape (triangle, polygon) that the ray
/// crosses in [tMin, tMax]: at the solver's t, or (as LightOccluders' contract allows) at some
/// other t of the range.
enum class FlatT { SOLVER, AT_T_MIN, AT_T_MAX, MIDDLE };

/// The same shapes as a LightOccluders: crossingsTowards records the light, then hands the
/// crossings over in the reverse of the linear scan's order (as a structure of its own may),
/// flat shapes' at the t that flatT says.
class RecordingOccluders final : public CountingShapes, public LightOccluders {
 public:
  explicit RecordingOccluders(const Geometries& g, FlatT flatT = FlatT::SOLVER)
      : CountingShapes(g), flatT_(flatT) {}

  bool crossingsTowards(std::uint32_t light, const Ray& ray, double tMin, double tMax,
                        ShadowCrossings& crossings, QueryCounts* counts) const override {
    lights.push_back(light);
    std::vector<Hit> hits;
    g_.forEachHit(
        ray, tMax,
        [&hits](const Hit& h) {
          hits.push_back(h);
          return true;
        },
        counts);
    for (auto it = hits.rbegin(); it != hits.rend(); ++it) {
      Hit h = *it;
      if (flatT_ != FlatT::SOLVER && isFlat(h.geometry) && h.t >= tMin && h.t <= tMax)
        h.t = movedT(tMin, tMax);
      if (!crossings.add(h)) return false;
    }
    return true;
  }

  /// The light of every crossingsTowards call, in order.
  mutable std::vector<std::uint32_t> lights;

 private:
  bool isFlat(std::uint32_t geometry) const {
    return std::holds_alternative<Triangle>(g_[geometry]) ||
           std::holds_alternative<Polygon>(g_[geometry]);
  }
  double movedT(double tMin, double tMax) const {
    switch (flatT_) {
      case FlatT::AT_T_MIN:
        return tMin;
      case FlatT::AT_T_MAX:
        return tMax;
      case FlatT::MIDDLE:
        return std::isfinite(tMax) ? tMin + (tMax - tMin) / 2 : tMin + 1;
      case FlatT::SOLVER:
        break;
    }
    return tMin;  // not asked for SOLVER (crossingsTowards keeps the solver's t)
  }

  FlatT flatT_;
};

}  // namespace rt::test
