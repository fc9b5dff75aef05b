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

/// A point light with attenuation I0 / (kC + kL·d + kQ·d²).
///
/// radius and shadowSamples are plain data here, used by the first mini project's soft shadows:
/// a light of radius r > 0 is a disk sampled by that many shadow rays (see
/// mini1_glossy/README.md). The default, radius 0 and one sample, is the course's point light.
struct PointLight {
  /// The most shadow rays one light may cast per shaded point.
  static constexpr int MAX_SHADOW_SAMPLES = 4096;

  Color intensity;
  Point position;
  double kC = 1, kL = 0, kQ = 0;
  double radius = 0;      ///< >= 0; 0: a point
  int shadowSamples = 1;  ///< 1..MAX_SHADOW_SAMPLES
  PointLight(const Color& i, const Point& p) : intensity(i), position(p) {}
  PointLight& setKc(double v) {
    kC = v;
    return *this;
  }
  PointLight& setKl(double v) {
    kL = v;
    return *this;
  }
  PointLight& setKq(double v) {
    kQ = v;
    return *this;
  }
  PointLight& setRadius(double r) {
    radius = r;
    return *this;
  }
  PointLight& setShadowSamples(int n) {
    shadowSamples = n;
    return *this;
  }
};

/// A point light aimed along direction: the point light's intensity times
/// max(0, direction·l)^narrowBeam (the seed's "focused spot light" for narrowBeam > 1).
struct SpotLight : PointLight {
  Vector direction;  ///< stored normalised by the constructor
  double narrowBeam = 1;
  SpotLight(const Color& i, const Point& p, const Vector& d)
      : PointLight(i, p), direction(d.normalized()) {}
  SpotLight& setKc(double v) {
    kC = v;
    return *this;
  }
  SpotLight& setKl(double v) {
    kL = v;
    return *this;
  }
  SpotLight& setKq(double v) {
    kQ = v;
    return *this;
  }
  SpotLight& setNarrowBeam(double v) {
    narrowBeam = v;
    return *this;
  }
  SpotLight& setRadius(double r) {
    radius = r;
    return *this;
  }
  SpotLight& setShadowSamples(int n) {
    shadowSamples = n;
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
