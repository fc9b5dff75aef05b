#include "primitives/Random.h"

#include <cmath>
#include <numbers>

namespace rt {

/*
 * Concentric mapping. With a = 2u − 1 and b = 2v − 1 in [−1, 1]², the point lies on the boundary
 * of the square of half-side r = max(|a|, |b|); that square's boundary is mapped to the circle of
 * radius r, linearly in angle within each of its four quarters:
 *
 *     |a| > |b|:  radius a, angle (π/4)·(b/a)
 *     otherwise:  radius b, angle π/2 − (π/4)·(a/b)
 *
 * Concentric squares have the areas of the circles they map to up to the constant π/4, so the
 * map preserves area (uniform in, uniform out).
 */
Sample2 squareToDisk(const Sample2& s) noexcept {
  const double a = 2 * s.u - 1, b = 2 * s.v - 1;
  if (a == 0 && b == 0) return {0, 0};
  double radius, angle;
  if (std::abs(a) > std::abs(b)) {
    radius = a;
    angle = std::numbers::pi / 4 * (b / a);
  } else {
    radius = b;
    angle = std::numbers::pi / 2 - std::numbers::pi / 4 * (a / b);
  }
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

namespace {

/// The golden ratio's conjugate φ⁻¹ = (√5 − 1)/2: the lattice's second coordinate steps by it.
constexpr double INV_PHI = 0.6180339887498949;

/// x − floor(x) for x >= 0.
double fraction(double x) noexcept { return x - std::floor(x); }

}  // namespace

Sample2 diskLatticePoint(int k, int n, const Sample2& shift) noexcept {
  return squareToDisk({fraction((k + 0.5) / n + shift.u), fraction(k * INV_PHI + shift.v)});
}

}  // namespace rt
