#include "lighting/LightSource.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

template <typename... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <typename... F>
Overloaded(F...) -> Overloaded<F...>;

/// The point light's part, shared by the spot light: l = normalize(p - position),
/// I = I0 / (kC + kL·d + kQ·d²). nullopt when p is the light's position (l undefined there).
std::optional<LightSample> pointSample(const PointLight& light, const Point& p) noexcept {
  const Double3 toPoint = p.xyz() - light.position.xyz();
  // The same test the Vector constructor makes, so that Vector(toPoint) below cannot throw.
  if (toPoint.isZero()) return std::nullopt;
  const double d2 = toPoint.lengthSquared();
  const double d = std::sqrt(d2);
  const double attenuation = light.kC + light.kL * d + light.kQ * d2;
  // Multiplying by the reciprocal keeps a (theoretical) infinite attenuation harmless: 1/inf = 0.
  return LightSample{light.intensity * (1.0 / attenuation), Vector(toPoint / d), d};
}

[[noreturn]] void fail(const char* light, const char* field, const std::string& requirement,
                       double value) {
  throw std::invalid_argument(std::string(light) + ": " + field + " must be " + requirement +
                              ", got " + formatNumber(value));
}

void requireFinitePoint(const char* light, const char* field, const Double3& xyz) {
  if (!xyz.isFinite()) {
    throw std::invalid_argument(std::string(light) + ": " + field + " must be finite, got " +
                                xyz.str());
  }
}

void validateAttenuation(const char* name, const PointLight& light) {
  requireFinitePoint(name, "position", light.position.xyz());
  // kC is the attenuation at distance 0: it must be positive or the intensity is infinite there.
  if (!(std::isfinite(light.kC) && light.kC > 0))
    fail(name, "kC", "a positive finite number", light.kC);
  if (!(std::isfinite(light.kL) && light.kL >= 0))
    fail(name, "kL", "a non-negative finite number", light.kL);
  if (!(std::isfinite(light.kQ) && light.kQ >= 0))
    fail(name, "kQ", "a non-negative finite number", light.kQ);
}

}  // namespace

std::optional<LightSample> illuminate(const LightSource& light, const Point& p) noexcept {
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
            s->intensity = s->intensity * factor;
            return s;
          },
      },
      light);
}

void validate(const LightSource& light) {
  std::visit(Overloaded{
                 [](const DirectionalLight& l) {
                   requireFinitePoint("DirectionalLight", "direction", l.direction.xyz());
                 },
                 [](const PointLight& l) { validateAttenuation("PointLight", l); },
                 [](const SpotLight& l) {
                   validateAttenuation("SpotLight", l);
                   requireFinitePoint("SpotLight", "direction", l.direction.xyz());
                   if (!(std::isfinite(l.narrowBeam) && l.narrowBeam >= 0))
                     fail("SpotLight", "narrowBeam", "a non-negative finite number", l.narrowBeam);
                 },
             },
             light);
}

}  // namespace rt
