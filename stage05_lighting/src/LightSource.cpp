#include "lighting/LightSource.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "primitives/Checks.h"
#include "primitives/Overloaded.h"

namespace rt {

namespace {

/// The point light's part, shared by the spot light: l = normalize(p - position),
/// I = I0 / (kC + kL·d + kQ·d²). nullopt when p is the light's position (l undefined there).
std::optional<LightSample> pointSample(const PointLight& light, const Point& p) noexcept {
  // BEGIN SOLUTION: hint: pointSample, I0 / (kC + kL d + kQ d^2), l = normalize(p - position)
  const Double3 toPoint = p.xyz() - light.position.xyz();
  // The same test the Vector constructor makes: the direction below is never the zero vector.
  if (toPoint.isZero()) return std::nullopt;
  const double d2 = toPoint.lengthSquared();
  const double d = std::sqrt(d2);
  const double attenuation = light.kC + light.kL * d + light.kQ * d2;
  // Multiplying by the reciprocal keeps a (theoretical) infinite attenuation harmless: 1/inf = 0.
  // Neither factor can throw here: attenuation >= kC > 0 (validated with the light), and
  // toPoint / d has length 1.
  return LightSample{light.intensity.scaledUnchecked(1.0 / attenuation),
                     Vector::unchecked(toPoint / d), d};
  // END SOLUTION
}

void validateAttenuation(const char* name, const PointLight& light) {
  requireFinite(light.position.xyz(), name, "position");
  // kC is the attenuation at distance 0: it must be positive or the intensity is infinite there.
  requirePositive(light.kC, name, "kC");
  requireNonNegative(light.kL, name, "kL");
  requireNonNegative(light.kQ, name, "kQ");
  requireNonNegative(light.radius, name, "radius");
  requireBetween(light.shadowSamples, 1, PointLight::MAX_SHADOW_SAMPLES, name, "shadowSamples");
}

}  // namespace

std::optional<LightSample> illuminate(const LightSource& light, const Point& p) noexcept {
  // BEGIN SOLUTION: hint: illuminate, per light type; a spot adds max(0, dir.l)^narrowBeam
  return std::visit(
      Overloaded{
          [](const DirectionalLight& l) -> std::optional<LightSample> {
            return LightSample{l.intensity, l.direction, std::numeric_limits<double>::infinity()};
          },
          [&p](const PointLight& l) { return pointSample(l, p); },
          [&p](const SpotLight& l) -> std::optional<LightSample> {
            std::optional<LightSample> s = pointSample(l, p);
            if (!s) return s;
            // The clamp comes before the power: behind the light the factor is 0, never
            // (negative)^narrowBeam.
            const double cosine = std::max(0.0, l.direction.dot(s->l));
            const double factor = l.narrowBeam == 1 ? cosine : std::pow(cosine, l.narrowBeam);
            s->intensity = s->intensity.scaledUnchecked(factor);  // factor in [0, 1]
            return s;
          },
      },
      light);
  // END SOLUTION
}

void validate(const LightSource& light) {
  std::visit(Overloaded{
                 [](const DirectionalLight& l) {
                   requireFinite(l.direction.xyz(), "DirectionalLight", "direction");
                 },
                 [](const PointLight& l) { validateAttenuation("PointLight", l); },
                 [](const SpotLight& l) {
                   validateAttenuation("SpotLight", l);
                   requireFinite(l.direction.xyz(), "SpotLight", "direction");
                   requireNonNegative(l.narrowBeam, "SpotLight", "narrowBeam");
                 },
             },
             light);
}

}  // namespace rt
