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
struct PointLight {
  Color intensity;
  Point position;
  double kC = 1, kL = 0, kQ = 0;
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
///         that is zero at distance 0 (kC = 0), or a negative narrowBeam; names the field.
void validate(const LightSource& light);

}  // namespace rt
