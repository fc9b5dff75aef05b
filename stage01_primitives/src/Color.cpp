#include "primitives/Color.h"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace rt {

namespace {
bool nonNegativeFinite(double v) { return std::isfinite(v) && v >= 0; }
bool nonNegativeFinite(const Double3& v) {
  return nonNegativeFinite(v.x) && nonNegativeFinite(v.y) && nonNegativeFinite(v.z);
}
std::uint8_t channel(double v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0)));
}
}  // namespace

const Color Color::BLACK{Double3(0, 0, 0), Unchecked{}};
const Color Color::WHITE{Double3(255, 255, 255), Unchecked{}};
const Color Color::RED{Double3(255, 0, 0), Unchecked{}};
const Color Color::GREEN{Double3(0, 255, 0), Unchecked{}};
const Color Color::BLUE{Double3(0, 0, 255), Unchecked{}};
const Color Color::YELLOW{Double3(255, 255, 0), Unchecked{}};

Color::Color(double r, double g, double b) : Color(Double3(r, g, b)) {}

Color::Color(const Double3& rgb) : rgb_(rgb) {
  if (!nonNegativeFinite(rgb)) {
    throw std::invalid_argument("Color: components must be finite and non-negative, got " +
                                rgb.str());
  }
}

Color Color::operator*(double k) const {
  if (!nonNegativeFinite(k)) {
    throw std::invalid_argument("Color scaling: factor must be finite and non-negative, got " +
                                formatNumber(k));
  }
  return Color(rgb_ * k, Unchecked{});
}

Color Color::operator*(const Double3& k) const {
  if (!nonNegativeFinite(k)) {
    throw std::invalid_argument(
        "Color scaling: coefficients must be finite and non-negative, got " + k.str());
  }
  return Color(rgb_ * k, Unchecked{});
}

Color Color::operator/(double k) const {
  if (!(std::isfinite(k) && k > 0)) {
    throw std::invalid_argument("Color reduce: divisor must be positive, got " + formatNumber(k));
  }
  return Color(rgb_ / k, Unchecked{});
}

std::array<std::uint8_t, 3> Color::toRgb8() const {
  return {channel(rgb_.x), channel(rgb_.y), channel(rgb_.z)};
}

std::ostream& operator<<(std::ostream& os, const Color& c) { return os << "Color" << c.rgb(); }

}  // namespace rt
