#pragma once
/// @file DemoScenes.h
/// Mini project 1's demonstration scenes, one per technique (glossy surfaces, diffused glass,
/// soft shadows, anti-aliasing, depth of field, adaptive super-sampling) and one with them all,
/// each written once: this stage's tests check them, and `rt` lists and renders them as built-in
/// scenes (`rt render NAME`) with the beams tracer.
///
/// A stage-7 scene is a CourseScene: a lit scene and its camera. These scenes also come with the
/// render settings they are meant for (4 x 4 samples per pixel, 16 lens samples, adaptive...),
/// which belong to the render, not to the scene: `rt` writes them into the document's `render`
/// object. So a demonstration scene is a CourseScene (checked by stage 5's checkSceneTable) plus
/// its SamplingSettings, and the few settings `rt render NAME --param` may change (its knobs).

#include <span>
#include <vector>

#include "camera/CameraSpec.h"
#include "glossy/Samplers.h"
#include "lighting/CourseScenes.h"
#include "lighting/LitScene.h"

namespace rt {

/// A demonstration scene as built: the scene, its camera (with its lens) and how to sample it.
struct DemoSetup {
  LitScene scene;
  CameraSpec camera;
  SamplingSettings sampling;
};

/// A setting of a demonstration scene that `rt render NAME --param KNOB=VALUE` may change. Each
/// changes what a scene file's key of the same name sets:
///
///   samples        render.samples: N x N jittered samples per pixel
///   lensSamples    camera.lensSamples: rays through the lens per sample
///   aperture       camera.aperture: the lens radius (0: the pinhole)
///   adaptive       render.adaptive: 1 (on) or 0 (off)
///   shadowSamples  shadowSamples of every light with a radius
///   glossyGrid     grid N of every reflected beam with a radius (1: a sharp mirror)
///   frostedGrid    grid N of every refracted beam with a radius (1: clear glass)
enum class DemoKnob {
  Samples,
  LensSamples,
  Aperture,
  Adaptive,
  ShadowSamples,
  GlossyGrid,
  FrostedGrid
};

/// What a knob is called and which values it takes.
struct DemoKnobInfo {
  const char* name;     ///< the --param name
  const char* meaning;  ///< one line
  double min, max;      ///< the accepted values
  bool integer;         ///< whole numbers only
};

const DemoKnobInfo& knobInfo(DemoKnob knob);

/// True when the setup has something the knob acts on: always for the sampling and the lens,
/// a light with a radius for shadowSamples, a beam with a radius for the grids.
bool knobApplies(const DemoSetup& setup, DemoKnob knob);

/// The knob's value in the setup (adaptive: 1 or 0; shadowSamples and the grids: the first
/// light or beam it acts on; 1 when there is none).
double knobValue(const DemoSetup& setup, DemoKnob knob);

/// Sets the knob's value in the setup.
/// @throws std::invalid_argument naming the knob and its range for a value outside it or, for an
///         integer knob, not whole.
void setKnob(DemoSetup& setup, DemoKnob knob, double value);

/// A demonstration scene: a course-style entry (name, description, scene and camera), the render
/// settings it is meant for, and the knobs `rt` offers as its --params.
struct DemoScene {
  CourseScene course;
  SamplingSettings sampling;
  std::vector<DemoKnob> knobs;

  /// The scene, its camera and its sampling settings.
  DemoSetup build() const;
};

/// The demonstration scenes, the techniques first, then all of them in one scene.
std::span<const DemoScene> demoScenes();

/// Checks a table of demonstration scenes: what checkSceneTable checks of the course entries,
/// then that each entry's sampling settings make a pixel sampler and that each of its knobs, at
/// most once, acts on something in its scene.
/// @throws std::logic_error naming the first bad entry (its index and name) and what is wrong.
void checkDemoTable(std::span<const DemoScene> table);

/// The scenes of the table, in its order. Units are the scene's own (a sphere of radius 1 is
/// about a tenth of the view's width); y is up, the floors are the plane y = 0.
namespace demo {

/// Four mirror spheres (radius 1, kR 0.8, kS 0.6 nSh 100) in a row on a 24 x 32 checkerboard,
/// their reflected beams of radius 0, 0.03, 0.08 and 0.2 at distance 1 (N = 8, 52 rays): sharp,
/// then glossier. Behind the camera, seen only in the mirrors, a wall of coloured stripes. A
/// point light; 640 x 320.
SceneSetup<LitScene> glossySpheres();

/// Three panes of glass (2 x 2.6, kT 0.85) side by side at z = 0, refracted beams of radius 0
/// (clear), 0.05 and 0.15 at distance 1 (N = 8), in front of a wall of coloured tiles of side 0.4
/// at z = -3 and a sphere just behind each pane (z = -1): the further behind the glass, the
/// blurrier. A point light; 640 x 320.
SceneSetup<LitScene> frostedGlass();

/// A floor, a sphere resting on it, a floating sphere and a post (a cylinder), under a light of
/// radius 1.2 at (-0.5, 6, 2) sampled by 32 shadow rays per shaded point; 600 x 400.
SceneSetup<LitScene> softShadows();

/// A 96 x 96 checkerboard of emitting black and white tiles (no lights), trimmed to what the
/// camera sees, seen from 1.6 above it,
/// receding towards the horizon, and two flat discs; 400 x 300. Its table entry renders it with
/// 4 x 4 jittered samples per pixel.
SceneSetup<LitScene> antialiasing();

/// Seven spheres of radius 0.5 on a checkerboard, 3 apart in depth, seen through a lens of
/// radius 0.2 focused on the fourth one's centre; 640 x 360. Its table entry traces 24 lens
/// samples per pixel.
SceneSetup<LitScene> depthOfField();

/// Flat emitting shapes (a triangle, a disc, a quadrilateral, three thin tilted bars) on a flat
/// background, no lights: colour changes only at edges; 300 x 300. Its table entry renders it
/// with adaptive super-sampling, depth 3.
SceneSetup<LitScene> adaptiveEdges();

/// All the techniques in one scene, each off: a glossy sphere (beam radius 0.08, N = 1), a pane
/// of glass in front of half of a red sphere (beam radius 0.08, N = 1), a light of radius 1 (one
/// shadow ray), a blue sphere further back and a focal distance on the glossy sphere (aperture
/// 0); 400 x 300. Rendered as it is, it is the Whitted tracer's image; the knobs turn each
/// technique on.
SceneSetup<LitScene> superSampling();

}  // namespace demo

}  // namespace rt
