#pragma once
/// @file WhittedTracer.h

#include "intersections/Intersectable.h"
#include "lighting/LitScene.h"
#include "primitives/Color.h"
#include "primitives/Double3.h"
#include "primitives/Ray.h"
#include "shadows/RayOffset.h"
#include "shadows/ShadowTracer.h"

namespace rt {

/// The recursion limits of the Whitted tracer (the course's constants by default).
struct WhittedSettings {
  /// The largest accepted maxLevel: the recursion uses one stack frame per level.
  static constexpr int MAX_LEVEL_LIMIT = 1000;

  /// MAX_CALC_COLOR_LEVEL: the primary hit is at this level; a hit at level 1 casts no
  /// secondary ray. So at most maxLevel − 1 bounces.
  int maxLevel = 10;
  /// MIN_CALC_COLOR_K: a secondary ray whose path weight is lowerThan minK (all three channels)
  /// is not cast. 0 turns the cut-off off (a ray of weight exactly zero is still not cast).
  double minK = 0.001;

  /// @throws std::invalid_argument for maxLevel outside [1, MAX_LEVEL_LIMIT] or a negative or
  ///         non-finite minK.
  void validate() const;
};

/// Which secondary ray a hook is asked to cast: the mini project's glossy surfaces blur the
/// reflected ray, its diffused glass the refracted one.
enum class SecondaryKind { Reflected, Refracted };

/// The course's stage-7 tracer (Whitted): shadows, plus recursive reflection and refraction.
///
///   traceRay(ray)    = background on a miss, else ambient + calcColor(hit, maxLevel, (1,1,1))
///   calcColor(h,l,k) = localEffects(h, k) + (l == 1 ? 0 : globalEffects(h, l, k))
///   globalEffects    = effect(refracted, kT') + effect(reflected, kR')
///   effect(ray, kx)  = 0 if (k·kx).lowerThan(minK), else kx · secondaryColor(ray, l, k·kx)
///   secondaryColor   = calcColor(hit, l − 1, k·kx), or the background on a miss
///
/// With ior == 1 (the default): reflected r = v − 2(v·n)n, refracted = v (straight through),
/// kT' = kT, kR' = kR, exactly as the course. With ior != 1: Snell's direction and Fresnel by
/// Schlick: kT' = (1 − R)·kT, kR' = kR + R·kT (all of kT to the reflection on total internal
/// reflection). A missed secondary ray gives background · kx (the course's 5785 fix).
class WhittedTracer : public ShadowTracer {
 public:
  /// @param scene must outlive the tracer.
  /// @throws what scene.validate() throws (shapes without a row of the appearance table,
  ///         invalid materials or lights); std::invalid_argument for invalid settings.
  explicit WhittedTracer(const LitScene& scene, const Intersectable* accelerator = nullptr,
                         const WhittedSettings& settings = {},
                         const RayOffset& offset = RayOffset{});

  using RayTracer::traceRay;
  Color traceRay(const Ray& ray, SampleContext& ctx) const override;

  const WhittedSettings& settings() const { return settings_; }

 protected:
  /// The colour of a hit at recursion level `level` reached with path weight k (no ambient).
  Color calcColor(const HitContext& h, int level, const Double3& k, SampleContext& ctx) const;

  /// The reflected and refracted contributions of a hit at level > 1.
  Color globalEffects(const HitContext& h, int level, const Double3& k, SampleContext& ctx) const;

  /// One secondary ray of weight kx leaving h along the unit direction dir: nothing when
  /// (k·kx).lowerThan(minK); else kx · secondaryColor(h, ray, kind, level, k·kx), the ray
  /// starting at h.point shifted by the RayOffset to dir's side.
  Color secondaryEffect(const HitContext& h, const Vector& dir, SecondaryKind kind, int level,
                        const Double3& k, const Double3& kx, SampleContext& ctx) const;

  /// The colour seen along one secondary ray (reflected or refracted, says kind) cast from the
  /// hit `from` at recursion level `level` with path weight kkx (= k·kx, already checked against
  /// minK), before it is weighted by kx: calcColor(closest hit, level − 1, kkx), or the
  /// background when the ray hits nothing. Counts one secondary ray in ctx.counts.
  ///
  /// The hook of mini project 1: a tracer that replaces one secondary ray by a beam of rays
  /// overrides this and averages the base version over the beam.
  virtual Color secondaryColor(const HitContext& from, const Ray& secondary, SecondaryKind kind,
                               int level, const Double3& kkx, SampleContext& ctx) const;

  /// What secondaryColor returns once the secondary ray's closest hit is known (hit, or nullopt
  /// for a miss): calcColor(hit, level − 1, kkx), or the background. Counts the ray. A tracer
  /// that finds the hits of several rays together (Intersectable::closestHits) shades each here.
  Color secondaryHitColor(const Ray& secondary, const std::optional<Hit>& hit, int level,
                          const Double3& kkx, SampleContext& ctx) const;

  WhittedSettings settings_;
};

}  // namespace rt
