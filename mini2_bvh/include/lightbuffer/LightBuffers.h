#pragma once
/// @file LightBuffers.h
/// An acceleration with a light buffer (LightBuffer.h) for each point light of a scene: closest
/// hits and walks go to the structure it wraps (a BVH, a grid, or the scene's own list), and a
/// shadow ray aimed at a point light tests the primitives of one cell of that light's buffer.
/// The same answers as the wrapped structure alone, bit for bit; the shadow tracers find the
/// buffers through stage 6's LightOccluders seam.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "intersections/Geometries.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"
#include "lightbuffer/LightBuffer.h"
#include "lighting/LightSource.h"
#include "shadows/LightOccluders.h"

namespace rt {

/// When light buffers are built.
struct LightBuffersOptions {
  /// Above this many primitives no buffer is made (the walk serves every shadow ray): a buffer
  /// costs a pass over every primitive per light, which a scene of a million stars rendered
  /// once at a small size never wins back.
  std::uint32_t maxPrimitives = 1u << 16;
  LightBufferOptions buffer;
};

class LightBuffers final : public Intersectable, public LightOccluders {
 public:
  /// Buffers for the point and spot lights of `lights` that are points (no radius, or a single
  /// shadow sample) over primitives, which walk (the structure the queries fall back on) covers
  /// too. walk and the primitives must outlive this; the lights are read now only.
  LightBuffers(const Intersectable& walk, Primitives primitives,
               std::span<const LightSource> lights, const LightBuffersOptions& options = {});
  /// The same, owning the structure it wraps.
  LightBuffers(std::unique_ptr<Intersectable> walk, Primitives primitives,
               std::span<const LightSource> lights, const LightBuffersOptions& options = {});

  std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                QueryCounts* counts = nullptr) const noexcept override {
    return walk_.closestHit(ray, tMax, counts);
  }
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts = nullptr) const override {
    return walk_.forEachHit(ray, tMax, visit, counts);
  }
  void closestHits(std::span<const Ray> rays, double tMax, std::span<std::optional<Hit>> hits,
                   QueryCounts* counts = nullptr) const noexcept override {
    walk_.closestHits(rays, tMax, hits, counts);
  }

  /// Through light's buffer when it has one and the ray is aimed at it; else the walk.
  bool crossingsTowards(std::uint32_t light, const Ray& ray, double tMin, double tMax,
                        ShadowCrossings& crossings, QueryCounts* counts = nullptr) const override;

  /// The structure the queries fall back on.
  const Intersectable& walk() const noexcept { return walk_; }
  /// Light number `light`'s buffer, or null (not a point light, or not built).
  const LightBuffer* buffer(std::uint32_t light) const noexcept {
    return light < buffers_.size() && buffers_[light] ? &*buffers_[light] : nullptr;
  }
  std::size_t memoryBytes() const noexcept;

 private:
  std::unique_ptr<Intersectable> owned_;
  const Intersectable& walk_;
  FlatShapes flats_;                   ///< every triangle and polygon among the shapes
  std::vector<std::uint32_t> flatOf_;  ///< shape → its record in flats_ (flat shapes only)
  std::vector<std::optional<LightBuffer>> buffers_;  ///< per light of the scene
};

}  // namespace rt
