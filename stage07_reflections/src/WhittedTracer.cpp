#include "reflections/WhittedTracer.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "primitives/Checks.h"
#include "reflections/Optics.h"

namespace rt {

void WhittedSettings::validate() const {
  requireBetween(maxLevel, 1, MAX_LEVEL_LIMIT, "WhittedSettings", "maxLevel");
  requireNonNegative(minK, "WhittedSettings", "minK");
}

WhittedTracer::WhittedTracer(const LitScene& scene, const Intersectable* accelerator,
                             const WhittedSettings& settings, const RayOffset& offset)
    : ShadowTracer(scene, accelerator, offset), settings_(settings) {
  settings_.validate();
}

Color WhittedTracer::traceRay(const Ray& ray, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: WhittedTracer::traceRay, Ia*kA once, then calcColor from the top
  const std::optional<Hit> hit =
      intersector_.closestHit(ray, INFINITE_DISTANCE, &ctx.counts.queries);
  if (!hit) return litScene_.background;
  // The ambient light once, at the top (course 5784: Ia·kA), then the recursion from the top
  // level with the initial weight (1,1,1).
  return litScene_.ambientLight.intensity() +
         calcColor(makeContext(*hit, ray), settings_.maxLevel, Double3::ONE, ctx);
  // END SOLUTION
}

Color WhittedTracer::calcColor(const HitContext& h, int level, const Double3& k,
                               SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: calcColor, the local effects, plus the global ones above level 1
  const Color local = localEffects(h, k, ctx);
  return level == 1 ? local : local + globalEffects(h, level, k, ctx);
  // END SOLUTION
}

/*
 * The course's global effects: a refracted ray weighted by kT and a reflected ray weighted by
 * kR, both from the hit point (shifted off the surface), refraction first.
 *
 * With an index of refraction (ior != 1) Fresnel splits the transmitted fraction kT: of the light
 * that the surface lets through (kT), the part R (Schlick) is reflected instead, so
 *
 *     refracted weight  kT' = (1 − R)·kT        along Snell's direction
 *     reflected weight  kR' = kR + R·kT         along the mirror direction
 *
 * kR (the mirror coating) is kept as it is. On total internal reflection R = 1: all of kT goes
 * to the reflected ray and no refracted ray is cast. ior == 1 takes the course's branch, so the
 * default material renders bit for bit as the course (R would not be 0 there: Schlick's R(θ)
 * grows towards grazing angles even when R0 = 0).
 */
Color WhittedTracer::globalEffects(const HitContext& h, int level, const Double3& k,
                                   SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: globalEffects, the refracted (kT) and reflected (kR) rays (above)
  const Material& m = h.appearance->material;
  constexpr SecondaryKind REFRACTED = SecondaryKind::Refracted;
  constexpr SecondaryKind REFLECTED = SecondaryKind::Reflected;
  // Refraction first, in a statement of its own: the two rays may draw random numbers from ctx
  // (mini project 1's beams), and the operands of a + are evaluated in an order C++ leaves
  // unspecified (GCC takes the right one first, Clang the left), so `a + b` would make the
  // image depend on the compiler.
  if (m.ior == 1) {
    const Color refracted =
        secondaryEffect(h, refractStraight(h.v), REFRACTED, level, k, m.kT, ctx);
    return refracted + secondaryEffect(h, reflect(h.v, h.normal), REFLECTED, level, k, m.kR, ctx);
  }
  const Refraction refraction = refract(h.v, h.normal, m.ior);
  const double r = refraction.reflectance;
  const Color refracted =
      refraction.direction
          ? secondaryEffect(h, *refraction.direction, REFRACTED, level, k, m.kT * (1 - r), ctx)
          : Color::BLACK;
  return refracted +
         secondaryEffect(h, reflect(h.v, h.normal), REFLECTED, level, k, m.kR + m.kT * r, ctx);
  // END SOLUTION
}

Color WhittedTracer::secondaryEffect(const HitContext& h, const Vector& dir, SecondaryKind kind,
                                     int level, const Double3& k, const Double3& kx,
                                     SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: secondaryEffect, black below minK, else the offset ray's colour*kx
  const Double3 kkx = k * kx;
  // The course's cut-off (all three channels below minK); a zero weight is never cast, also
  // when minK is 0.
  if (kkx.lowerThan(settings_.minK) || kkx.isExactlyZero()) {
    return Color::BLACK;
  }
  // kx is a product of validated, non-negative coefficients: no check per ray.
  return secondaryColor(h, offset_.ray(h.point, h.normal, dir), kind, level, kkx, ctx)
      .scaledUnchecked(kx);
  // END SOLUTION
}

Color WhittedTracer::secondaryColor(const HitContext&, const Ray& secondary, SecondaryKind,
                                    int level, const Double3& kkx, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: secondaryColor, the colour at the ray's closest hit (secondaryHitColor)
  return secondaryHitColor(
      secondary, intersector_.closestHit(secondary, INFINITE_DISTANCE, &ctx.counts.queries), level,
      kkx, ctx);
  // END SOLUTION
}

Color WhittedTracer::secondaryHitColor(const Ray& secondary, const std::optional<Hit>& hit,
                                       int level, const Double3& kkx, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: secondaryHitColor, a counted ray: the background or calcColor(level-1)
  ++ctx.counts.secondary;
  // A miss sees the background; the caller weights it by kx (the course's 5785 fix: 5784
  // returned it unweighted).
  if (!hit) return litScene_.background;
  return calcColor(makeContext(*hit, secondary), level - 1, kkx, ctx);
  // END SOLUTION
}

}  // namespace rt
