#pragma once
/// @file LightSource.h
/// The course's light sources as one closed set (like the shapes, see stage03's README).

#include <optional>
#include <variant>

#include "primitives/Color.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {

/// Light from infinitely far away along a fixed direction, of constant intensity.
struct DirectionalLight {
  Color intensity;
  Vector direction;  ///< stored normalised by the constructor
  DirectionalLight(const Color& i, const Vector& d) : intensity(i), direction(d.normalized()) {}
};

/// The data of a point light with attenuation I0 / (kC + kL·d + kQ·d²); PointLight below adds
/// the course's setters.
///
/// radius and shadowSamples are plain data here, used by the first mini project's soft shadows:
/// a light of radius r > 0 is a disk sampled by that many shadow rays (see
/// mini1_glossy/README.md). The default, radius 0 and one sample, is the course's point light.
struct PointLightFields {
  /// The most shadow rays one light may cast per shaded point.
  static constexpr int MAX_SHADOW_SAMPLES = 4096;

  Color intensity;
  Point position;
  double kC = 1, kL = 0, kQ = 0;
  double radius = 0;      ///< >= 0; 0: a point
  int shadowSamples = 1;  ///< 1..MAX_SHADOW_SAMPLES
  PointLightFields(const Color& i, const Point& p) : intensity(i), position(p) {}
};

/// The course's builder-style setters of a point light's fields, written once for the point
/// light and the spot light: each returns the light being built as its own type Self (the
/// course's SpotLight overrides every setter to return a SpotLight), so that
/// SpotLight(...).setKl(0.001).setNarrowBeam(10) keeps the chain a SpotLight. Base holds the
/// fields (PointLightFields, or PointLight for the spot light, which is a point light).
template <class Self, class Base>
struct PointLightSetters : Base {
  using Base::Base;
  Self& setKc(double v) { return set(this->kC, v); }
  Self& setKl(double v) { return set(this->kL, v); }
  Self& setKq(double v) { return set(this->kQ, v); }
  Self& setRadius(double r) { return set(this->radius, r); }
  Self& setShadowSamples(int n) { return set(this->shadowSamples, n); }

 private:
  template <typename T>
  Self& set(T& field, T value) {
    field = value;
    return static_cast<Self&>(*this);
  }
};

/// A point light with attenuation I0 / (kC + kL·d + kQ·d²) (fields: PointLightFields).
struct PointLight : PointLightSetters<PointLight, PointLightFields> {
  PointLight(const Color& i, const Point& p) : PointLightSetters(i, p) {}
};

/// A point light aimed along direction: the point light's intensity times
/// max(0, direction·l)^narrowBeam (the reference report's "focused spot light" for narrowBeam > 1).
struct SpotLight : PointLightSetters<SpotLight, PointLight> {
  Vector direction;  ///< stored normalised by the constructor
  double narrowBeam = 1;
  SpotLight(const Color& i, const Point& p, const Vector& d)
      : PointLightSetters(i, p), direction(d.normalized()) {}
  SpotLight& setNarrowBeam(double v) {
    narrowBeam = v;
    return *this;
  }
};

using LightSource = std::variant<DirectionalLight, PointLight, SpotLight>;

/// What a light gives a point: its intensity there, the unit direction l from the light to the
/// point, and the distance to the light (+infinity for a directional light).
struct LightSample {
  Color intensity;
  Vector l;
  double distance;
};

/// The light's contribution at p; nullopt when p is the light's own position (l undefined).
/// Allocates nothing.
std::optional<LightSample> illuminate(const LightSource& light, const Point& p) noexcept;

/// @throws std::invalid_argument for negative or non-finite attenuation factors, an attenuation
///         that is zero at distance 0 (kC = 0), a negative narrowBeam, a negative or non-finite
///         radius or shadowSamples outside 1..MAX_SHADOW_SAMPLES; names the field.
void validate(const LightSource& light);

}  // namespace rt
