#pragma once
/// @file Color.h
/// An RGB colour on the course's 0-255 scale. Components are unbounded above (a light of
/// (800,500,250) is brighter than white) and never negative; a colour is clamped to 255 per
/// channel only when it is written to an image.

#include <array>
#include <cstdint>
#include <iosfwd>

#include "primitives/Double3.h"

namespace rt {

class Color {
 public:
  constexpr Color() = default;
  /// @throws std::invalid_argument for a negative or non-finite component.
  Color(double r, double g, double b);
  /// @throws std::invalid_argument for a negative or non-finite component.
  explicit Color(const Double3& rgb);

  double r() const { return rgb_.x; }
  double g() const { return rgb_.y; }
  double b() const { return rgb_.z; }
  const Double3& rgb() const { return rgb_; }

  Color operator+(const Color& o) const { return Color(rgb_ + o.rgb_, Unchecked{}); }
  Color& operator+=(const Color& o) {
    rgb_ = rgb_ + o.rgb_;
    return *this;
  }
  /// Scaling by a non-negative factor; @throws std::invalid_argument for a negative one.
  Color operator*(double k) const;
  /// Per-channel scaling by non-negative coefficients (kD, kS, ...);
  /// @throws std::invalid_argument for a negative one.
  Color operator*(const Double3& k) const;
  /// Division by a positive count or factor (the course's reduce);
  /// @throws std::invalid_argument for a factor that is not positive.
  Color operator/(double k) const;

  // The per-ray path must never throw (an exception escaping a render thread ends the program),
  // and there every factor is a product of coefficients that were validated, once, when the
  // scene was built. These forms skip the check; everywhere else use the operators above.

  /// this·k for a finite k >= 0 (not checked).
  Color scaledUnchecked(double k) const noexcept { return Color(rgb_ * k, Unchecked{}); }
  /// this·k per channel for finite coefficients >= 0 (not checked).
  Color scaledUnchecked(const Double3& k) const noexcept { return Color(rgb_ * k, Unchecked{}); }
  /// A colour from a triple the caller knows is finite and non-negative (not checked).
  static constexpr Color unchecked(const Double3& rgb) noexcept { return Color(rgb, Unchecked{}); }

  /// Course equality: every channel of the difference isZero.
  bool operator==(const Color& o) const { return rgb_ == o.rgb_; }

  /// The 8-bit value written to an image: each channel clamped to [0,255] and rounded.
  std::array<std::uint8_t, 3> toRgb8() const;

  static const Color BLACK;
  static const Color WHITE;
  static const Color RED;
  static const Color GREEN;
  static const Color BLUE;
  static const Color YELLOW;

 private:
  struct Unchecked {};
  constexpr Color(const Double3& rgb, Unchecked) noexcept : rgb_(rgb) {}
  Double3 rgb_;
};

std::ostream& operator<<(std::ostream& os, const Color& c);

}  // namespace rt
