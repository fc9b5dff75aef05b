#include "reflections/Optics.h"

#include <algorithm>
#include <cmath>

namespace rt {

Vector reflect(const Vector& v, const Vector& n) noexcept {
  // BEGIN SOLUTION: hint: reflect, r = v - 2(v.n)n
  const Double3& vv = v.xyz();
  const Double3& nn = n.xyz();
  // |r| = |v| = 1: never the zero vector, so the unchecked form is safe (per-ray code).
  return Vector::unchecked(vv - nn * (2 * vv.dot(nn)));
  // END SOLUTION
}

double schlick(double cosTheta, double n1, double n2) noexcept {
  // BEGIN SOLUTION: hint: schlick, R0 + (1 - R0)(1 - cos)^5, R0 = ((n1 - n2)/(n1 + n2))^2
  const double r = (n1 - n2) / (n1 + n2);
  const double r0 = r * r;
  const double m = 1 - std::clamp(cosTheta, 0.0, 1.0);
  const double m2 = m * m;
  return r0 + (1 - r0) * (m2 * m2 * m);
  // END SOLUTION
}

Refraction refract(const Vector& v, const Vector& n, double ior) noexcept {
  // BEGIN SOLUTION: hint: refract, Snell's direction, total internal reflection, Schlick's R
  const double nv = n.dot(v);
  const bool entering = nv <= 0;
  const double eta = entering ? 1 / ior : ior;           // η1/η2
  const Double3 facing = entering ? n.xyz() : -n.xyz();  // N: the normal against v
  const double cosI = std::min(1.0, std::abs(nv));
  const double sin2T = eta * eta * (1 - cosI * cosI);
  if (sin2T > 1) return {std::nullopt, 1.0, entering};  // total internal reflection
  const double cosT = std::sqrt(1 - sin2T);
  const Double3 t = v.xyz() * eta + facing * (eta * cosI - cosT);
  // Schlick's cosine is the one on the side of the lower index.
  const double n1 = entering ? 1 : ior, n2 = entering ? ior : 1;
  const double cosSchlick = n1 <= n2 ? cosI : cosT;
  // |t| = 1 for unit v and N (Snell's construction): never zero, so the unchecked form is safe.
  return {Vector::unchecked(t).normalized(), schlick(cosSchlick, n1, n2), entering};
  // END SOLUTION
}

}  // namespace rt
