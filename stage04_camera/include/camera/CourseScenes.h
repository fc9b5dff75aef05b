#pragma once
/// @file CourseScenes.h
/// The course's scenes of this stage, written once: the tests render them and the `rt` program
/// lists them as built-in scenes.

#include "camera/CameraSpec.h"
#include "camera/Scene.h"

namespace rt {

/// The camera of the course's RenderTests: at the origin looking along -Z with up +Y, view plane
/// 500x500 at distance 100, image 1000x1000.
CameraSpec renderTestsCamera();

/// The course's "base render test" (RenderTests.renderTwoColorTest, catalogue stage 5):
/// a sphere at (0,0,-100) of radius 50 and three triangles in the up-left, down-left and
/// down-right quadrants, all in the plane z = -100; ambient light (255,191,191) with kA 1;
/// background (75,127,90); renderTestsCamera(). The shapes are geometries 0 (sphere) to 3
/// (down-right) in that order, which stage 5's multi-colour scene relies on to colour them.
/// Rendered with the ambient tracer every shape is flat pink on green and the up-right quadrant
/// is empty. The course then draws a yellow grid every 100 pixels; that is the caller's job
/// (Camera::printGrid), not part of the scene.
SceneSetup<Scene> twoColorScene();

}  // namespace rt
