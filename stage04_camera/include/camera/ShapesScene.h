#pragma once
/// @file ShapesScene.h
/// The scene of the debugging views (camera/DebugTracers.h): one of each of stage 2's six shapes
/// where the camera sees it clearly, so that `rt render shapes` shows their normals and
/// `--tracer hits` their intersections.

#include "camera/CameraSpec.h"
#include "camera/Scene.h"

namespace rt {

/// One of each shape, on a dark background (20, 20, 30), geometries in this order:
///   0 a floor plane y = −300 (normal +Y): the image below the horizon;
///   1 a sphere, left;
///   2 a finite cylinder with caps, right, its axis (0, 0.6, 0.8) leaning towards the camera so
///     that its top cap shows;
///   3 a triangle, top, and 4 a convex pentagon, centre, each tilted its own way;
///   5 an infinite tube crossing the image diagonally, from the floor on the left up to the
///     right edge, behind the pentagon and the cylinder.
/// The shapes but the tube's left end are above the horizon, with no floor behind them. The
/// ambient light is white with kA 1 (the ambient tracer shows every shape in white). The camera
/// looks from (0, 0, 1000) at (0, 100, 0); the image is 500 x 500.
SceneSetup<Scene> shapesScene();

}  // namespace rt
