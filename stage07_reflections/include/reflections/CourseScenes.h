#pragma once
/// @file CourseScenes.h
/// The course's ReflectionRefractionTests scenes, the report authors' all-features scene from its
/// two viewpoints, and a hall of mirrors, each written once: this stage's tests render them, and
/// the `rt` program lists and renders them as built-in scenes (`rt render NAME`). The table type
/// is stage05's CourseScene.

#include <span>

#include "camera/CameraSpec.h"
#include "lighting/CourseScenes.h"
#include "lighting/LitScene.h"

namespace rt {

/// The scenes of this stage.
std::span<const CourseScene> reflectionScenes();

namespace course {

/// ReflectionRefractionTests.twoSpheres ("refractionTwoSpheres"): a BLUE sphere (centre
/// (0,0,-50), radius 50, kD 0.4 kS 0.3 nSh 100 kT 0.3) around a RED one (radius 25, kD 0.5
/// kS 0.5 nSh 100); a spot light of (1000,600,0) at (-100,-100,500) aimed along (-1,-1,-2),
/// kL 4e-4, kQ 6e-7; no ambient light. Camera at (0,0,1000) looking at the origin, view plane
/// 150x150 at distance 1000, 500x500 pixels.
SceneSetup<LitScene> twoSpheres();

/// ReflectionRefractionTests.twoSpheresOnMirrors ("reflectionTwoSpheresMirrored"): a sphere
/// (centre (-950,-900,-1000), radius 400, emission (0,50,100), kD 0.25 kS 0.25 nSh 20 kT
/// (0.5,0,0)) around one of radius 200 (emission (100,50,20), kD 0.25 kS 0.25 nSh 20); a full
/// mirror triangle (kR 1) and a tinted one (kR (0.5,0,0.4)), both of emission (20,20,20);
/// ambient WHITE x 0.1; a spot light of (1020,400,400) at (-750,-750,-150) aimed along
/// (-1,-1,-4), kL 1e-5, kQ 5e-6. Camera at (0,0,10000) looking at the origin, view plane
/// 2500x2500 at distance 10000, 500x500 pixels.
SceneSetup<LitScene> twoSpheresOnMirrors();

/// ReflectionRefractionTests.trianglesTransparentSphere ("refractionShadow"): the trianglesSphere
/// triangles with kD 0.5 kS 0.5 nSh 60, a BLUE sphere (centre (60,50,-50), radius 30, kD 0.2
/// kS 0.2 nSh 30 kT 0.6) under a spot light of (700,400,400) at (60,50,0) aimed along (0,0,-1),
/// kL 4e-5, kQ 2e-7; ambient WHITE x 0.15. View plane 200x200 at distance 1000, 600x600 pixels.
SceneSetup<LitScene> trianglesTransparentSphere();

/// The report authors' allFeaturesTest (catalogue §6): a floor, a transparent bi-pyramid around a
/// mirror-like sphere, a reflective sphere, a transparent cube, a glass sphere around a point
/// light, a spot and a directional light (18 shapes, 3 lights). Seen from below: camera at
/// (100,20,1000) looking at (0,60,0), view plane 200x200 at distance 1000, 1200x1200 pixels.
SceneSetup<LitScene> allFeaturesBelow();
/// The same scene from above: camera at (250,300,1000), view plane 200x200 at distance 700.
SceneSetup<LitScene> allFeaturesAbove();

/// A hall of mirrors: two parallel 800x300 mirrors (kR 0.9, facing each other along z, 300 apart)
/// around a red and a green sphere on a grey floor, lit by a point light; the camera between the
/// mirrors looks at one of them at an angle, so the reflections repeat into the distance.
/// Shapes: 0 and 1 the mirrors (z = -150 and z = +150), 2 the floor, 3 and 4 the spheres.
SceneSetup<LitScene> hallOfMirrors();

}  // namespace course
}  // namespace rt
