#pragma once
/// @file PhongTracer.h

#include <cstdint>
#include <vector>

#include "camera/RayTracer.h"
#include "intersections/Intersectable.h"
#include "lighting/LightSource.h"
#include "lighting/LitScene.h"
#include "primitives/Color.h"
#include "primitives/Double3.h"
#include "primitives/Point.h"
#include "primitives/Ray.h"
#include "primitives/Vector.h"

namespace rt {

/// The course's stage-6 tracer: emission, ambient light and the Phong model for every light,
/// with no shadows. Stage 6 (ShadowTracer) and stage 7 (WhittedTracer) derive from it.
class PhongTracer : public RayTracer {
 public:
  /// @param scene must outlive the tracer.
  /// @throws what scene.validate() throws (shapes without looks, invalid materials or lights):
  ///         everything shading relies on is checked here, once, so that no ray ever throws.
  explicit PhongTracer(const LitScene& scene, const Intersectable* accelerator = nullptr);

  using RayTracer::traceRay;
  /// Background on a miss; else ambient (once) + localEffects(hit, (1,1,1)).
  Color traceRay(const Ray& ray, SampleContext& ctx) const override;

  const LitScene& litScene() const { return litScene_; }

  /// The course's MIN_CALC_COLOR_K: a light (or, in stage 7, a secondary ray) whose weight is
  /// below this in all three channels contributes nothing and is skipped.
  static constexpr double MIN_CALC_COLOR_K = 0.001;

 protected:
  /// What shading needs of the winning hit, computed once for it (never for the losers).
  struct HitContext {
    std::uint32_t geometry;
    Point point;
    Vector normal;                ///< outward geometric normal at point
    Vector v;                     ///< the incoming ray's direction
    double nv;                    ///< alignZero(normal·v)
    std::uint32_t appearanceRow;  ///< the shape's row of the scene's appearance table
    const Appearance* appearance;
  };

  /// Never throws: where a shape's normal is undefined (see hitNormal) it is taken facing the
  /// ray.
  HitContext makeContext(const Hit& hit, const Ray& ray) const noexcept;

  /// Emission plus, for every light on the viewer's side of the surface ((n·l)(n·v) > 0),
  /// I_L·transmittance·(kD·|n·l| + kS·max(0, −v·r)^nSh) with r = l − 2(l·n)n.
  /// When n·v is zero only the emission is returned. k is the path weight of the recursive
  /// tracer ((1,1,1) for a primary ray).
  Color localEffects(const HitContext& h, const Double3& k, SampleContext& ctx) const;

  /// The transmittance towards light number `light` (the course's ktr): the fraction of its
  /// light that reaches the point, per channel. (1,1,1) in this stage (no shadows); stage 6
  /// casts a shadow ray. Returning a value whose product with k is negligible lets the light be
  /// skipped.
  virtual Double3 transmittance(const HitContext& h, std::uint32_t light, const LightSample& sample,
                                const Double3& k, SampleContext& ctx) const;

  const LitScene& litScene_;

 private:
  /// Per appearance row, computed once by the constructor: which Phong terms its material can
  /// produce (bit DIFFUSE: kD != 0, bit SPECULAR: kS != 0). A shape with neither skips the light
  /// loop.
  enum Terms : std::uint8_t { NONE = 0, DIFFUSE = 1, SPECULAR = 2 };
  std::vector<std::uint8_t> terms_;
};

}  // namespace rt
