// The writer helpers every part of the format uses (Writers.h).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "Writers.h"

namespace rt::scenefile {

/// Bitwise equality: 0 and -0 differ, as they do when read back.
bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(const Double3& a, const Double3& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

Json coefficient(const Double3& k) {
  return same(k.x, k.y) && same(k.y, k.z) ? jsonNumber(k.x) : jsonTriple(k);
}

namespace {

/// True when the shapes' normalisation of c gives exactly u.
bool normalisesTo(const Double3& c, const Vector& u) {
  if (!c.isFinite() || c.isZero() || !std::isfinite(c.lengthSquared())) return false;
  return same(Vector(c).normalized().xyz(), u.xyz());
}

/// A vector that the loader's normalisation turns into exactly u (a stored plane normal, axis
/// or light direction). u itself often is not one: normalising a unit vector again moves about
/// a third of them by an ulp. Tried in order: small integer ratios (a built-in scene's (1,1,1)
/// comes back as [1,1,1]), u itself, then multiples of u.
Double3 directionPreimage(const Vector& u) {
  const Double3& x = u.xyz();
  double smallest = INFINITY, largest = 0;
  for (double c : {x.x, x.y, x.z})
    if (c != 0) {
      smallest = std::min(smallest, std::abs(c));
      largest = std::max(largest, std::abs(c));
    }
  if (largest / smallest <= 1000) {
    for (int k = 1; k <= 24; ++k) {
      const Double3 scaled = x * (k / smallest);
      const Double3 rounded(std::round(scaled.x), std::round(scaled.y), std::round(scaled.z));
      const bool integral = std::abs(scaled.x - rounded.x) < 1e-9 * k &&
                            std::abs(scaled.y - rounded.y) < 1e-9 * k &&
                            std::abs(scaled.z - rounded.z) < 1e-9 * k;
      if (integral && normalisesTo(rounded, u)) return rounded;
    }
  }
  if (normalisesTo(x, u)) return x;
  for (int s = 3; s <= 2000; ++s)
    if (normalisesTo(x * s, u)) return x * s;
  return x;  // not found (rare): the copy may differ from the original by an ulp
}

}  // namespace

Json direction(const Vector& u) { return jsonTriple(directionPreimage(u)); }

}  // namespace rt::scenefile
