#pragma once
/// @file AmbientLight.h

#include "primitives/Color.h"
#include "primitives/Double3.h"

namespace rt {

/// The scene's uniform ambient light. Convention (course year 5784): its intensity is Ia·kA,
/// with kA on the light; it is added once per primary hit.
class AmbientLight {
 public:
  /// No ambient light: black.
  AmbientLight() = default;
  /// @throws std::invalid_argument for a negative kA.
  AmbientLight(const Color& ia, double kA) : AmbientLight(ia, Double3(kA)) {}
  /// @throws std::invalid_argument for a negative kA component.
  AmbientLight(const Color& ia, const Double3& kA) : ia_(ia), kA_(kA), intensity_(ia * kA) {}

  const Color& ia() const { return ia_; }
  const Double3& kA() const { return kA_; }
  /// Ia·kA.
  const Color& intensity() const { return intensity_; }

  static const AmbientLight NONE;

 private:
  Color ia_;
  Double3 kA_ = Double3::ONE;
  Color intensity_;
};

inline const AmbientLight AmbientLight::NONE{};

}  // namespace rt
