// The placement of a model's vertices (ModelTransform.h).
#include "ModelTransform.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace rt::scenefile {

namespace {

/// Sine and cosine of an angle in degrees, exact at multiples of 90 degrees.
std::pair<double, double> sinCosDegrees(double degrees) {
  const double turn = std::fmod(degrees, 360.0);
  const double quarter = turn / 90.0;
  if (quarter == std::floor(quarter)) {
    switch ((static_cast<int>(quarter) % 4 + 4) % 4) {
      case 0:
        return {0.0, 1.0};
      case 1:
        return {1.0, 0.0};
      case 2:
        return {0.0, -1.0};
      default:
        return {-1.0, 0.0};
    }
  }
  const double radians = turn * (3.14159265358979323846 / 180.0);
  return {std::sin(radians), std::cos(radians)};
}

}  // namespace

Affine Affine::after(const Affine& o) const {
  Affine r;
  for (int i = 0; i < 3; ++i) {
    const Double3& a = m[i];
    r.m[i] = {a.x * o.m[0].x + a.y * o.m[1].x + a.z * o.m[2].x,
              a.x * o.m[0].y + a.y * o.m[1].y + a.z * o.m[2].y,
              a.x * o.m[0].z + a.y * o.m[1].z + a.z * o.m[2].z};
  }
  r.t = apply(o.t);
  return r;
}

double Affine::determinant() const {
  const Double3 &a = m[0], &b = m[1], &c = m[2];
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
         a.z * (b.x * c.y - b.y * c.x);
}

Affine Affine::normalMatrix() const {
  const Double3 &a = m[0], &b = m[1], &c = m[2];
  Affine r;
  r.m[0] = {b.y * c.z - b.z * c.y, b.z * c.x - b.x * c.z, b.x * c.y - b.y * c.x};
  r.m[1] = {a.z * c.y - a.y * c.z, a.x * c.z - a.z * c.x, a.y * c.x - a.x * c.y};
  r.m[2] = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  if (determinant() < 0)
    for (Double3& row : r.m) row = -row;
  return r;
}

bool Affine::isIdentity() const {
  // Exactly (Double3's == is the course's equality within 2^-40).
  const auto exactly = [](const Double3& a, const Double3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  };
  const Affine identity;
  for (int i = 0; i < 3; ++i)
    if (!exactly(m[i], identity.m[i])) return false;
  return exactly(t, identity.t);
}

void Affine::place(std::span<Point> vertices, std::span<Double3> normals) const {
  if (isIdentity()) return;
  for (Point& p : vertices) p = Point(apply(p.xyz()));
  if (normals.empty()) return;
  const Affine normalPlace = normalMatrix();
  for (Double3& n : normals) n = normalPlace.linear(n);
}

Affine affineOf(const ModelTransform& tr) {
  const auto refuse = [](const std::string& what) {
    throw std::invalid_argument("the transform is degenerate: " + what);
  };
  if (!tr.scale.isFinite() || tr.scale.x == 0 || tr.scale.y == 0 || tr.scale.z == 0)
    refuse("scale must be finite and non-zero on every axis, got " + tr.scale.str());
  if (!tr.rotationDegrees.isFinite())
    refuse("rotation must be finite, got " + tr.rotationDegrees.str());
  if (!tr.translation.isFinite()) refuse("translation must be finite, got " + tr.translation.str());
  Affine scale;
  scale.m = {Double3(tr.scale.x, 0, 0), Double3(0, tr.scale.y, 0), Double3(0, 0, tr.scale.z)};
  const auto [sx, cx] = sinCosDegrees(tr.rotationDegrees.x);
  const auto [sy, cy] = sinCosDegrees(tr.rotationDegrees.y);
  const auto [sz, cz] = sinCosDegrees(tr.rotationDegrees.z);
  Affine rx, ry, rz;
  rx.m = {Double3(1, 0, 0), Double3(0, cx, -sx), Double3(0, sx, cx)};
  ry.m = {Double3(cy, 0, sy), Double3(0, 1, 0), Double3(-sy, 0, cy)};
  rz.m = {Double3(cz, -sz, 0), Double3(sz, cz, 0), Double3(0, 0, 1)};
  Affine r = rz.after(ry.after(rx.after(scale)));
  r.t = tr.translation;
  return r;
}

}  // namespace rt::scenefile
