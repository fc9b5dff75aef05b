#include "intersections/Intersect.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

#include "primitives/Util.h"

namespace rt {

void Roots::add(double t) noexcept {
  if (!(alignZero(t) > 0) || count_ == CAPACITY) return;
  int i = count_++;
  for (; i > 0 && t_[i - 1] > t; --i) t_[i] = t_[i - 1];
  t_[i] = t;
}

namespace {

/// The largest absolute coordinate of a point: the scale of its rounding error.
double magnitude(const Double3& p) noexcept {
  return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

}  // namespace

// "Starts on it" (Intersect.h) is decided relative to the coordinates' size: a head computed as
// a hit point far from the origin lies off the plane by rounding error of about ε·|coordinates|,
// and a glancing ray relaunched from it would otherwise find the plane again at a tiny t that the
// course's fixed 2^-40 threshold does not catch.
double planeT(const Double3& q, const Double3& n, const Ray& ray) noexcept {
  // BEGIN SOLUTION: hint: planeT, t = n.(q - P0) / n.dir; NaN when parallel or starting on it
  const double nd = alignZero(n.dot(ray.direction().xyz()));
  if (nd == 0) return NAN;
  const Double3& p0 = ray.head().xyz();
  const double numerator = n.dot(q - p0);
  const double roundoff =
      8 * std::numeric_limits<double>::epsilon() * std::max(magnitude(q), magnitude(p0));
  if (std::abs(numerator) <= roundoff) return NAN;
  // Opposite signs: the root is behind the head, which every caller drops; skip the division.
  if ((numerator > 0) != (nd > 0)) return NAN;
  return numerator / nd;
  // END SOLUTION
}

bool passesInside(std::span<const Point> vertices, const Ray& ray) noexcept {
  // BEGIN SOLUTION: hint: passesInside, the signs of dir.(vi x v(i+1)) agree; 0 is a miss
  const Double3& p0 = ray.head().xyz();
  const Double3& dir = ray.direction().xyz();
  const std::size_t n = vertices.size();
  int sign = 0;
  Double3 vi = vertices[0].xyz() - p0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t next = i + 1 == n ? 0 : i + 1;  // the last edge closes the boundary
    const Double3 vNext = vertices[next].xyz() - p0;
    const Double3 ni = vi.cross(vNext);
    const double s = dir.dot(ni);
    // isZero(dir·normalize(ni)) without the square root: s² < threshold²·|ni|².
    if (s * s <= ZERO_THRESHOLD * ZERO_THRESHOLD * ni.lengthSquared()) return false;
    const int si = s > 0 ? 1 : -1;
    if (sign != 0 && si != sign) return false;
    sign = si;
    vi = vNext;
  }
  return true;
  // END SOLUTION
}

namespace {

/// The two roots of a·t² + b·t + c = 0 in the cancellation-free form, or none when the
/// discriminant is not positive (a tangent ray does not intersect, as for the course's sphere).
void addQuadraticRoots(double a, double b, double c, Roots& roots) noexcept {
  // BEGIN SOLUTION: hint: addQuadraticRoots, a t^2 + b t + c = 0 without cancellation
  const double disc = b * b - 4 * a * c;
  if (alignZero(disc) <= 0) return;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  roots.add(q / a);
  if (q != 0) roots.add(c / q);
  // END SOLUTION
}

}  // namespace

Roots intersectSphereRoots(const Double3& centre, double r, const Ray& ray) noexcept {
  // BEGIN SOLUTION: hint: intersectSphereRoots, tm -/+ th; from the centre t = r
  // u = O - P0, tm = dir·u, d² = |u|² - tm²; th = √(r² - d²); t = tm ∓ th.
  Roots roots;
  const Double3 u = centre - ray.head().xyz();
  if (u.isZero()) {  // the head is the centre: one hit at distance r
    roots.add(r);
    return roots;
  }
  const double tm = ray.direction().xyz().dot(u);
  const double thSquared = alignZero(r * r - (u.lengthSquared() - tm * tm));
  if (thSquared <= 0) return roots;  // the line misses or is tangent
  const double th = std::sqrt(thSquared);
  roots.add(tm - th);
  roots.add(tm + th);
  return roots;
  // END SOLUTION
}

Roots intersectRoots(const Sphere& s, const Ray& ray) noexcept {
  return intersectSphereRoots(s.center().xyz(), s.radius(), ray);
}

Roots intersectRoots(const Plane& p, const Ray& ray) noexcept {
  // BEGIN SOLUTION: hint: intersectRoots(Plane), the root from planeT
  Roots roots;
  roots.add(planeT(p.point().xyz(), p.normal().xyz(), ray));
  return roots;
  // END SOLUTION
}

namespace {
/// A flat convex shape (triangle, polygon, mesh triangle): the root of its plane through q with
/// unit normal n, kept when the ray passes inside.
Roots flatRoots(const Double3& q, const Double3& n, std::span<const Point> vertices,
                const Ray& ray) noexcept {
  // BEGIN SOLUTION: hint: flatRoots, the plane's root when the ray passesInside
  Roots roots;
  const double tHit = planeT(q, n, ray);
  if (alignZero(tHit) > 0 && passesInside(vertices, ray)) roots.add(tHit);
  return roots;
  // END SOLUTION
}
}  // namespace

Roots intersectRoots(const Triangle& t, const Ray& ray) noexcept {
  return flatRoots(t.vertices()[0].xyz(), t.normal().xyz(), t.vertices(), ray);
}

Roots intersectRoots(const Polygon& p, const Ray& ray) noexcept {
  return flatRoots(p.plane().point().xyz(), p.plane().normal().xyz(), p.vertices(), ray);
}

Roots intersectRoots(const TriangleMesh& mesh, std::size_t t, const Ray& ray) noexcept {
  // flatRoots' two conditions for a Triangle of these corners, whose plane is (first corner,
  // flatNormal's bits), taken in the other order: both are pure, so the root is the same, and
  // the inside test needs no normal. Most rays that reach a mesh triangle in a hierarchy pass
  // beside it, and so never pay for the normal's square root.
  Roots roots;
  const std::array<Point, 3> corners = mesh.corners(t);
  if (!passesInside(corners, ray)) return roots;
  roots.add(planeT(corners[0].xyz(), mesh.flatNormal(t).xyz(), ray));
  return roots;
}

namespace {
/// Roots of the infinite tube: |(P(t) - Pa)⊥|² = r², where ⊥ removes the axis component.
/// Parallel rays (no component across the axis) have none.
void addTubeRoots(const Tube& tube, const Ray& ray, Roots& roots) noexcept {
  // BEGIN SOLUTION: hint: addTubeRoots, |(P(t) - Pa) across the axis|^2 = r^2
  const Double3& va = tube.axis().direction().xyz();
  const Double3& v = ray.direction().xyz();
  const Double3 dp = ray.head().xyz() - tube.axis().head().xyz();
  const Double3 vPerp = v - va * va.dot(v);
  const Double3 dpPerp = dp - va * va.dot(dp);
  const double a = vPerp.lengthSquared();
  if (isZero(a)) return;
  const double r = tube.radius();
  addQuadraticRoots(a, 2 * vPerp.dot(dpPerp), dpPerp.lengthSquared() - r * r, roots);
  // END SOLUTION
}
}  // namespace

Roots intersectRoots(const Tube& t, const Ray& ray) noexcept {
  Roots roots;
  addTubeRoots(t, ray, roots);
  return roots;
}

Roots intersectRoots(const Cylinder& c, const Ray& ray) noexcept {
  // BEGIN SOLUTION: hint: intersectRoots(Cylinder), the side between the bases, the caps
  // The side: tube roots whose axial coordinate lies strictly between the bases. The caps: the
  // base planes' roots inside the base disc, the rim included when the ray crosses the solid
  // there (so a rim point is found once, and its normal is the base's, as Cylinder::normal
  // says).
  Roots roots;
  const Double3& va = c.axis().direction().xyz();
  const Double3& pa = c.axis().head().xyz();
  const double h = c.height();
  const double r2 = c.radius() * c.radius();

  Roots side;
  addTubeRoots(c.tube(), ray, side);
  for (double t : side) {
    const double s = va.dot(ray.point(t).xyz() - pa);
    if (alignZero(s) > 0 && alignZero(s - h) < 0) roots.add(t);
  }
  const Double3& dir = ray.direction().xyz();
  for (const auto& [centre, outward] : {std::pair{pa, -va}, std::pair{pa + va * h, va}}) {
    const double t = planeT(centre, va, ray);
    if (!(alignZero(t) > 0)) continue;
    const Double3 radial = ray.point(t).xyz() - centre;
    const double rim = alignZero(radial.lengthSquared() - r2);
    if (rim > 0) continue;  // outside the disc
    // On the rim itself the ray counts only when it crosses into or out of the solid there:
    // inwards both across the cap and radially, or outwards both ways. A ray that grazes the
    // rim, or runs along the side parallel to the axis, only touches the edge.
    if (rim == 0 && !(alignZero(dir.dot(outward)) * alignZero(dir.dot(radial)) > 0)) continue;
    roots.add(t);
  }
  return roots;
  // END SOLUTION
}

Roots intersectRoots(const Geometry& g, const Ray& ray) noexcept {
  return std::visit([&ray](const auto& shape) { return intersectRoots(shape, ray); }, g);
}

}  // namespace rt
