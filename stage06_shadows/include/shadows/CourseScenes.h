#pragma once
/// @file CourseScenes.h
/// The course's ShadowTests scenes, each written once: this stage's tests render them, and the
/// `rt` program lists and renders them as built-in scenes (`rt render NAME`). The table type is
/// stage05's CourseScene.

#include <span>

#include "camera/CameraSpec.h"
#include "lighting/CourseScenes.h"
#include "lighting/LitScene.h"

namespace rt {

/// The scenes of this stage, in the catalogue's order.
std::span<const CourseScene> shadowScenes();

namespace course {

// ShadowTests. sphereTriangle*: a BLUE sphere (centre (0,0,-200), radius 60, kD 0.5 kS 0.5
// nSh 30), a BLUE triangle of the same material between it and a spot light of (400,240,0)
// aimed along (1,1,-3) with kL 1e-5, kQ 1.5e-7; no ambient light. Camera at (0,0,1000) looking
// at the origin, up +Y, view plane 200x200 at distance 1000, 400x400 pixels.

/// Triangle (-70,-40,0), (-40,-70,0), (-68,-68,-4); light at (-100,-100,200).
SceneSetup<LitScene> sphereTriangleInitial();
/// The triangle moved towards the sphere: (-60,-30,0), (-30,-60,0), (-58,-58,-4).
SceneSetup<LitScene> sphereTriangleMove1();
/// Further: (-50,-20,0), (-20,-50,0), (-48,-48,-4).
SceneSetup<LitScene> sphereTriangleMove2();
/// The initial triangle, the light moved closer to it: (-85,-85,105).
SceneSetup<LitScene> sphereTriangleSpot1();
/// Closer still: (-75,-75,65).
SceneSetup<LitScene> sphereTriangleSpot2();
/// Two black specular triangles (kS 0.8, nSh 60) under a BLUE sphere (centre (0,0,-11),
/// radius 30, kD 0.5 kS 0.5 nSh 30); ambient WHITE x 0.15; a spot light of (700,400,400) at
/// (40,40,115) aimed along (-1,-1,-4), kL 4e-4, kQ 2e-5. Same camera, 600x600 pixels.
SceneSetup<LitScene> trianglesSphere();

}  // namespace course
}  // namespace rt
