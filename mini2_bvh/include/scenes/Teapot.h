#pragma once
/// @file Teapot.h
/// The course's own benchmark, TeapotTest: the Utah teapot as a mesh of flat triangles, one
/// point light, a camera looking at it along +z (2024's file, 800 x 800), and the next year's,
/// which adds 400 small "bubbles" rising from the spout (1000 x 1000) and whose comments hold the
/// lecturer's timings of his threads; mini project 2 times its accelerations and threads with
/// both.
///
/// The teapot is stage 2's utahTeapot(detail), placed as the course's 992 triangles are (see
/// teapotMesh); the rest as the course's file sets it (course catalogue §5):
///
///   teapot        emission (200,0,0), kD 0.5, kS 0.5, shininess 60; flat triangles (the
///                 course's have no vertex normals), or smooth with the patches' own normals
///   light         a point light (500,500,500) at (100,0,-100), kC 1, kL 0, kQ 1e-6
///   camera        at (0,0,-1000) along (0,0,1), up (0,1,0), view plane 200 x 200 at 1000:
///                 the plane z = 0 seen from x, y = -100 to 100; 800 x 800 (bubbles: 1000 x 1000)
///   bubbles       spheres of radius U[0.1,1) in the cone whose apex is (90,30,0.2), just above
///                 the spout's tip, opening upwards (+y) with radius 0.3 per unit of height, up
///                 to height 70: height h = U[0,70), at distance U[0,0.3·h) from the axis (the
///                 course's uniform distance, denser near the axis), at an angle U[0,2π);
///                 black, kD U[0,0.1) per channel, kS 0.2, kR 0.1 (and shininess 0, kT 0, as
///                 the course's Material defaults)
///   background    black, no ambient light
///
/// The course's Math.random is replaced by the counter-based RandomStream(seed, bubble, 0, 0),
/// so a scene is a pure function of its parameters.

#include <cstdint>
#include <memory>

#include "camera/CameraSpec.h"
#include "geometries/TriangleMesh.h"
#include "lighting/LitScene.h"

namespace rt {

/// How the teapot is made.
struct TeapotOptions {
  int detail = 4;       ///< quads per patch side, 1..kUtahTeapotMaxDetail; 4: the course's 992
  bool smooth = false;  ///< the patches' normals (smooth shading); false: flat, as the course's
  /// Not the course's: half the side of a square floor under the teapot, in the plane of its
  /// bottom (y = -39.8754), centred below the origin; 0: none. Two triangles (a second mesh),
  /// grey and matte, that catch the teapot's shadow. A floor far larger than the teapot is where
  /// the regular grid loses to the BVH (the grid's cells are sized to the floor, and the whole
  /// teapot falls into a few of them: mini2's README).
  double floor = 0;
};

/// The bubbles of the later year's TeapotTest.
struct BubbleOptions {
  static constexpr int MAX_COUNT = 1'000'000;
  int count = 400;         ///< 0..MAX_COUNT; the course's 400
  std::uint64_t seed = 1;  ///< where the bubbles are, their sizes and their kD
};

/// The Utah teapot of utahTeapot(options.detail), placed as the course's TeapotTest has it: y
/// up, the spout towards +x, the handle towards -x. The course's 992 triangles are Newell's
/// teapot turned so, scaled by about 28.4254 and moved by (0.831025, -39.8754, -1.10804): Newell's
/// point (1.4, 0, 2.4), on the rim, is the course's first point (40.6266, 28.3457, -1.10804),
/// his bottom (z = 0) the course's y = -39.8754, his knob's top (z = 3.15) y = 49.6647. With
/// the scale 28.42544, fitted to them, the course's points (printed to 6 digits; the tests check
/// nine, on every part) are vertices of ours to within 1e-4. The teapot spans x from -84.4 (the
/// handle) to 98.3 (the spout's tip) and y from -39.9 to 49.7, the middle of the 200 x 200 view.
///
///     (x, y, z) of Newell's  ->  (s·x + 0.831025, s·z - 39.8754, -s·y - 1.10804), s = 28.42544
///
/// a quarter turn about x (Newell's +y goes to -z, towards the camera) with no mirror, so the
/// triangles keep their outward winding; the normals (smooth) turn alike.
/// @throws std::invalid_argument naming the detail when it is outside 1..kUtahTeapotMaxDetail.
std::shared_ptr<const TriangleMesh> teapotMesh(const TeapotOptions& options = {});

/// The course's TeapotTest of 2024: the teapot and its light, 800 x 800.
/// @throws std::invalid_argument naming the detail when it is outside 1..kUtahTeapotMaxDetail,
///         or the floor when it is negative or not finite.
SceneSetup<LitScene> teapotScene(const TeapotOptions& options = {});

/// The later year's TeapotTest: the teapot, its light and bubbles.count bubbles, 1000 x 1000.
/// @throws std::invalid_argument naming the detail or the bubble count when out of range.
SceneSetup<LitScene> bubblesScene(const TeapotOptions& options = {},
                                  const BubbleOptions& bubbles = {});

}  // namespace rt
