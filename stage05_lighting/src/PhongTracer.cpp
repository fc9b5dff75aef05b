#include "lighting/PhongTracer.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "primitives/Util.h"

namespace rt {

namespace {
/// x^n for an integer n >= 0 by repeated squaring (⌈log2 n⌉ + popcount(n) multiplications):
/// several times cheaper than std::pow, which takes the exponent as a double, and within a few
/// ulps of it for the shininess exponents of the course's materials.
double powInt(double x, int n) noexcept {
  double result = 1;
  while (n > 0) {
    if (n & 1) result *= x;
    x *= x;
    n >>= 1;
  }
  return result;
}
}  // namespace

PhongTracer::PhongTracer(const LitScene& scene, const Intersectable* accelerator)
    : RayTracer(scene, accelerator), litScene_(scene) {
  // Everything the per-ray code relies on is checked here, once, so that shading never throws:
  // the lists are public and may have been filled without LitScene's add functions.
  scene.validate();
  terms_.reserve(scene.appearances.size());
  for (const Appearance& a : scene.appearances) {
    std::uint8_t t = NONE;
    if (!a.material.kD.isExactlyZero()) t |= DIFFUSE;
    if (!a.material.kS.isExactlyZero()) t |= SPECULAR;
    terms_.push_back(t);
  }
}

Color PhongTracer::traceRay(const Ray& ray, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: PhongTracer::traceRay, background on a miss, else Ia*kA + local
  const std::optional<Hit> hit =
      intersector_.closestHit(ray, INFINITE_DISTANCE, &ctx.counts.queries);
  if (!hit) return litScene_.background;
  // Course year 5784: the ambient light's Ia·kA, once per primary hit (not per light, not per
  // recursion level).
  return litScene_.ambientLight.intensity() +
         localEffects(makeContext(*hit, ray), Double3::ONE, ctx);
  // END SOLUTION
}

PhongTracer::HitContext PhongTracer::makeContext(const Hit& hit, const Ray& ray) const noexcept {
  // BEGIN SOLUTION: hint: makeContext, the hit's point, normal, v, n.v and appearance row
  const Point p = ray.point(hit.t);
  const Vector& v = ray.direction();
  const Vector n = litScene_.geometries.hitNormal(hit.geometry, p, -v);
  const std::uint32_t row = litScene_.rowOf(hit.geometry);
  return HitContext{hit.geometry, p, n, v, alignZero(n.dot(v)), row, &litScene_.appearances[row]};
  // END SOLUTION
}

/*
 * Phong at the hit point P, for every light L (unit vectors, l from the light to P, v from the
 * eye to P, n the outward normal):
 *
 *   colour = emission + Σ_L  I_L(P) · T_L · ( kD·|n·l|  +  kS·max(0, −v·r)^nSh ),
 *   r = l − 2(l·n)n   (l mirrored about the surface),
 *
 * T_L the transmittance towards L (the course's ktr): (1,1,1) here, the shadow ray's from stage 6.
 *
 * A light counts only when it is on the viewer's side of the surface: (n·l)(n·v) > 0, both dot
 * products passed through alignZero so rounding noise never decides a side. A grazing view
 * (n·v == 0) sees the emission only.
 */
Color PhongTracer::localEffects(const HitContext& h, const Double3& k, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: localEffects, emission + the Phong terms of each light (above)
  Color color = h.appearance->emission;
  const double nv = h.nv;
  if (nv == 0) return color;
  const std::uint8_t terms = terms_[h.appearanceRow];
  if (terms == NONE) return color;

  const Material& m = h.appearance->material;
  const Double3& n = h.normal.xyz();
  const Double3& v = h.v.xyz();
  const auto lightCount = static_cast<std::uint32_t>(litScene_.lights.size());
  // Each light's sample is worked out one light ahead: its square root and divisions (a chain of
  // some 70 cycles) then run while the light before it is shaded, its shadow ray traced.
  std::optional<LightSample> next;
  if (lightCount > 0) next = illuminate(litScene_.lights[0], h.point);
  for (std::uint32_t light = 0; light < lightCount; ++light) {
    const std::optional<LightSample> sample = next;
    if (light + 1 < lightCount) next = illuminate(litScene_.lights[light + 1], h.point);
    if (!sample) continue;  // P is the light's own position: no direction to shade with
    const double ln = sample->l.xyz().dot(n);
    const double nl = alignZero(ln);
    if (nl * nv <= 0) continue;  // the light is on the other side of the surface

    const Double3 transmitted = transmittance(h, light, *sample, k, ctx);
    if ((transmitted * k).lowerThan(MIN_CALC_COLOR_K)) continue;

    Double3 factor;  // kD·|n·l| + kS·max(0, −v·r)^nSh
    if (terms & DIFFUSE) factor = m.kD * std::abs(nl);
    if (terms & SPECULAR) {
      const Double3 r = sample->l.xyz() - n * (2 * ln);
      const double minusVR = alignZero(-v.dot(r));
      // As the course: no highlight unless −v·r > 0 (also when nSh = 0, where pow would give 1).
      if (minusVR > 0) factor = factor + m.kS * powInt(minusVR, m.shininess);
    }
    // Products of validated coefficients: finite and non-negative, no check needed per ray.
    color += sample->intensity.scaledUnchecked(transmitted).scaledUnchecked(factor);
  }
  return color;
  // END SOLUTION
}

Double3 PhongTracer::transmittance(const HitContext&, std::uint32_t, const LightSample&,
                                   const Double3&, SampleContext&) const {
  return Double3::ONE;
}

}  // namespace rt
