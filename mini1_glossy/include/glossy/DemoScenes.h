#pragma once
/// @file DemoScenes.h
/// Mini project 1's demonstration scenes, one per technique (glossy surfaces, diffused glass,
/// soft shadows, anti-aliasing, depth of field, adaptive super-sampling) and one with them all:
/// plain functions of typed parameters, whose defaults are the scenes of the table
/// (glossy/DemoTable.h).

#include "camera/CameraSpec.h"
#include "lighting/CourseScenes.h"
#include "lighting/LitScene.h"

namespace rt {

/// The demonstration scenes, in the table's order (glossy/DemoTable.h). Units are the scene's own
/// (a sphere of radius 1 is about a tenth of the view's width); y is up, the floors are the plane y
/// = 0.
namespace demo {

/// glossySpheres' parameter: N of the glossy spheres' reflected beams (1..BeamSettings::MAX_GRID;
/// 1: sharp mirrors).
struct GlossySpheresParams {
  int beamGrid = 8;
};

/// frostedGlass' parameter: N of the frosted panes' refracted beams (1: clear glass).
struct FrostedGlassParams {
  int beamGrid = 8;
};

/// softShadows' parameter: the shadow rays per shaded point of its light of radius 1.2.
struct SoftShadowsParams {
  int shadowSamples = 32;
};

/// depthOfField's parameter: the lens radius (0: the pinhole).
struct DepthOfFieldParams {
  double aperture = 0.2;
};

/// superSampling's parameters, each technique off by default: N of the glossy sphere's and of
/// the pane's beams, the shadow rays of the light of radius 1, the lens radius.
struct SuperSamplingParams {
  int glossyGrid = 1;
  int frostedGrid = 1;
  int shadowSamples = 1;
  double aperture = 0;
};

/// Four mirror spheres (radius 1, kR 0.8, kS 0.6 nSh 100) in a row on a 24 x 32 checkerboard,
/// their reflected beams of radius 0, 0.03, 0.08 and 0.2 at distance 1 (N = beamGrid; 8: 52 rays):
/// sharp, then glossier. Behind the camera, seen only in the mirrors, a wall of coloured stripes. A
/// point light; 640 x 320.
SceneSetup<LitScene> glossySpheres(const GlossySpheresParams& params = {});

/// Three panes of glass (2 x 2.6, kT 0.85) side by side at z = 0, refracted beams of radius 0
/// (clear), 0.05 and 0.15 at distance 1 (N = beamGrid), in front of a wall of coloured tiles of
/// side 0.4 at z = -3 and a sphere just behind each pane (z = -1): the further behind the glass,
/// the blurrier. A point light; 640 x 320.
SceneSetup<LitScene> frostedGlass(const FrostedGlassParams& params = {});

/// A floor, a sphere resting on it, a floating sphere and a post (a cylinder), under a light of
/// radius 1.2 at (-0.5, 6, 2) sampled by shadowSamples rays per shaded point; 600 x 400.
SceneSetup<LitScene> softShadows(const SoftShadowsParams& params = {});

/// A 96 x 96 checkerboard of emitting black and white tiles (no lights), trimmed to what the
/// camera sees, seen from 1.6 above it,
/// receding towards the horizon, and two flat discs; 400 x 300. Its table entry renders it with
/// 4 x 4 jittered samples per pixel.
SceneSetup<LitScene> antialiasing();

/// Seven spheres of radius 0.5 on a checkerboard, 3 apart in depth, seen through a lens of
/// radius `aperture` focused on the fourth one's centre; 640 x 360. Its table entry traces 24 lens
/// samples per pixel.
SceneSetup<LitScene> depthOfField(const DepthOfFieldParams& params = {});

/// Flat emitting shapes (a triangle, a disc, a quadrilateral, three thin tilted bars) on a flat
/// background, no lights: colour changes only at edges; 300 x 300. Its table entry renders it
/// with adaptive super-sampling, depth 3.
SceneSetup<LitScene> adaptiveEdges();

/// All the techniques in one scene, each off: a glossy sphere (beam radius 0.08, N = 1), a pane
/// of glass in front of half of a red sphere (beam radius 0.08, N = 1), a light of radius 1 (one
/// shadow ray), a blue sphere further back and a focal distance on the glossy sphere (aperture
/// 0); 400 x 300. Rendered as it is, it is the Whitted tracer's image; the knobs turn each
/// technique on.
SceneSetup<LitScene> superSampling(const SuperSamplingParams& params = {});

}  // namespace demo

}  // namespace rt
