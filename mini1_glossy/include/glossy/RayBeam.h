#pragma once
/// @file RayBeam.h
/// A beam of rays around one secondary ray: the reference report's generateRayBeam, with its flaws
/// fixed.
///
///                      target circle, radius r, at distance d along the main ray
///                     ___________
///        N×N grid    |  . : . : .|   the grid covers the circle's bounding square; a cell is
///        of cells    | : . : . : |   in the beam when its centre is inside the circle
///        of side     |. : . : . :|   (≈ π/4·N² cells), and its sample is jittered inside the
///        s = 2r/N    |___________|   cell: c + (U − ½, V − ½)·s
///                          ^
///                          | d
///                          |
///                 ---------o--------- surface (the hit point, shifted off it)
///
/// Each sample's direction goes from the ray's origin to its point on the target plane; a sample
/// on the wrong side of the surface (sign(n·dir) ≠ sign(n·main)) is dropped, so glossy
/// reflections never dip into the surface and diffused refraction never comes back out. The
/// colour of the beam is the average of the colours its rays see.
///
/// Fixed from the Java course project: the main ray is not traced twice (it is not added to the
/// grid's rays; with N = 1 or r = 0 the beam is the main ray alone); the grid is cell-centred (the
/// reference report's started at −r, leaving the last row and column uncovered); the frame of the
/// target plane works for every direction (see Frame.h; the reference report's failed for −Y).

#include <cstdint>

#include "glossy/Frame.h"
#include "lighting/Material.h"
#include "primitives/Random.h"
#include "primitives/Util.h"
#include "primitives/Vector.h"

namespace rt {

/// True when the centre of cell (i, j) of an N × N grid lies inside the grid's inscribed circle.
/// In units of half a cell the centres sit at 2i + 1 − N (−N+1 … N−1) and the radius is N, so the
/// test is on integers, exact, and never on the boundary: for odd N the coordinates are even and
/// N² is odd; for even N they are odd, and odd² + odd² ≡ 2 (mod 4) while N² ≡ 0.
constexpr bool cellInBeam(int i, int j, int grid) noexcept {
  const int x = 2 * i + 1 - grid, y = 2 * j + 1 - grid;
  return x * x + y * y <= grid * grid;
}

/// The number of cells of an N × N grid whose centres lie inside the inscribed circle: the rays
/// of a full beam (fewer when some are on the wrong side). 1 for N = 1. About π/4·N².
int beamCellCount(int grid) noexcept;

/// A material's BeamSettings (lighting/Material.h: distance d, radius r, grid N) describe a beam.

/// Calls visit(direction) for every ray of the beam around the unit direction main, leaving a
/// surface of unit normal n, and returns how many there were. Without a beam
/// (!settings.isBeam()), or when every sample falls on the wrong side (a grazing beam), visit
/// gets the main direction alone. Each kept cell draws its jitter from random (two numbers).
/// Allocates nothing, never throws (unless visit does).
template <typename Visit>
int forEachBeamRay(const Vector& main, const Vector& n, const BeamSettings& settings,
                   RandomStream& random, Visit&& visit) {
  // BEGIN SOLUTION: hint: forEachBeamRay, kept cells, jittered, on the right side
  if (!settings.isBeam()) {
    visit(main);
    return 1;
  }
  const Double3& dir = main.xyz();
  const Frame frame = Frame::around(dir);
  const Double3 centre = dir * settings.distance;  // relative to the ray's origin
  const int grid = settings.grid;
  const double r = settings.radius, size = 2 * r / grid;
  const double side = alignZero(n.xyz().dot(dir));
  int count = 0;
  for (int j = 0; j < grid; ++j) {
    const double y = (j + 0.5) * size - r;
    for (int i = 0; i < grid; ++i) {
      if (!cellInBeam(i, j, grid)) continue;
      const double x = (i + 0.5) * size - r;
      const Sample2 jitter = random.next2D();
      const Double3 target =
          centre + frame.inPlane(x + (jitter.u - 0.5) * size, y + (jitter.v - 0.5) * size);
      // |target| >= distance·(1 − ...) > 0: the target plane is at distance d > 0 along dir and
      // orthogonal to it, so target is never the zero vector.
      const Vector sample = Vector::unchecked(target).normalized();
      if (alignZero(n.xyz().dot(sample.xyz())) * side <= 0) continue;  // the wrong side
      visit(sample);
      ++count;
    }
  }
  if (count == 0) {
    visit(main);
    return 1;
  }
  return count;
  // END SOLUTION
}

}  // namespace rt
