#pragma once
/// @file ShadowTracer.h

#include "intersections/Intersectable.h"
#include "lighting/LightSource.h"
#include "lighting/LitScene.h"
#include "lighting/PhongTracer.h"
#include "primitives/Double3.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"
#include "shadows/RayOffset.h"
#include "shadows/ShadowQuery.h"

namespace rt {

/// The course's stage-7 part 1: the Phong tracer with shadows and partial shadows.
///
/// For every light that passes the same-side rule, a shadow ray leaves the hit point (shifted by
/// the RayOffset) towards the light, and the light's intensity is scaled by the transmittance
/// Π kT of the blockers in the ray's range (see RayOffset::shadowRange). A light whose
/// transmittance times the path weight k is lowerThan MIN_CALC_COLOR_K (PhongTracer's, 0.001)
/// is skipped.
class ShadowTracer : public PhongTracer {
 public:
  /// @param scene must outlive the tracer.
  /// @param accelerator see RayTracer.
  /// @param offset how secondary rays leave a surface (default: scale-aware).
  /// @throws std::logic_error when scene.appearances and scene.geometries differ in size.
  explicit ShadowTracer(const LitScene& scene, const Intersectable* accelerator = nullptr,
                        const RayOffset& offset = RayOffset{});

  const RayOffset& rayOffset() const { return offset_; }

  /// The shadow query from point p of a surface with unit normal n towards a light that gives p
  /// the sample light, for a path of weight k. Allocates nothing.
  Transmittance shadowQuery(const Point& p, const Vector& n, const LightSample& light,
                            const Double3& k = Double3::ONE) const noexcept;

 protected:
  /// The transmittance towards the light, or ZERO when (transmittance·k).lowerThan(
  /// MIN_CALC_COLOR_K) (the light is then skipped).
  Double3 transparency(const HitContext& h, const LightSample& light,
                       const Double3& k) const override;

  RayOffset offset_;
};

}  // namespace rt
