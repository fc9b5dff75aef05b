#pragma once
/// @file DemoTable.h
/// Mini project 1's table of demonstration scenes (glossy/DemoScenes.h), each written once: this
/// stage's tests check them, and `rt` lists and renders them as built-in scenes (`rt render
/// NAME`) with the beams tracer.
///
/// A stage-7 scene is a CourseScene: a lit scene and its camera. These scenes also come with the
/// render settings they are meant for (4 x 4 samples per pixel, 16 lens samples, adaptive...),
/// which belong to the render, not to the scene: `rt` writes them into the document's `render`
/// object. So a demonstration scene is a CourseScene (checked by stage 5's checkSceneTable) plus
/// its SamplingSettings. What `rt render NAME --param` may change is the program's choice (its
/// mini-1 part): the scenes' typed parameters (DemoScenes.h) and the sampling settings.

#include <span>

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

/// A demonstration scene: a course-style entry (name, description, the scene with its default
/// parameters and its camera) and the render settings it is meant for.
struct DemoScene {
  CourseScene course;
  SamplingSettings sampling;

  /// The scene, its camera and its sampling settings.
  DemoSetup build() const;
};

/// The demonstration scenes, the techniques first, then all of them in one scene.
std::span<const DemoScene> demoScenes();

/// Checks a table of demonstration scenes: what checkSceneTable checks of the course entries,
/// then that each entry's sampling settings make a pixel sampler.
/// @throws std::logic_error naming the first bad entry (its index and name) and what is wrong.
void checkDemoTable(std::span<const DemoScene> table);

}  // namespace rt
