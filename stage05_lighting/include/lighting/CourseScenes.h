#pragma once
/// @file CourseScenes.h
/// The course's stage-6 scenes (RenderTests' multi-colour scene, every LightsTests scene and the
/// report authors' multi-light scenes), each written once: the stage's tests render them, and
/// the `rt` program lists and renders them as built-in scenes (`rt render NAME`).

#include <span>

#include "camera/CameraSpec.h"
#include "lighting/LitScene.h"
#include "primitives/Color.h"

namespace rt {

/// A built-in scene: a short kebab-case name for the command line, a one-line description and
/// the function that builds it. Later stages reuse this type for their own tables.
struct CourseScene {
  const char* name;
  const char* description;
  SceneSetup<LitScene> (*make)();
  /// The course draws a grid over some images (RenderTests: every 100 pixels); 0 = no grid.
  int gridInterval = 0;
  Color gridColor = Color::BLACK;
};

/// The scenes of this stage, in the catalogue's order.
std::span<const CourseScene> lightingScenes();

/// Checks a table of built-in scenes (this stage's or a later one's), building every scene:
/// each entry has a unique, non-empty kebab-case name (a-z, 0-9, '-'), a description longer
/// than 10 characters and a make function; each scene it makes has a name, holds together
/// (LitScene::validate) and has a camera that builds.
/// @throws std::logic_error naming the first bad entry (its index and name) and what is wrong.
void checkSceneTable(std::span<const CourseScene> table);

/// The course's values, exactly; scene.name is the course's image name.
namespace course {

/// RenderTests.renderMultiColorTest ("color render test"): a sphere and three triangles with
/// emissions GREEN (up-left), RED (down-left) and BLUE (down-right), no materials, ambient
/// WHITE x 0.2 = (51,51,51), black background; camera at the origin looking along -Z, view
/// plane 500x500 at distance 100, 1000x1000 pixels. The course adds a white grid every 100 px.
SceneSetup<LitScene> renderMultiColor();

// LightsTests. The sphere scenes use camera1 (at (0,0,1000) looking at the origin, up +Y, view
// plane 150x150 at distance 1000, no ambient light); the triangles scenes use camera2 (the same
// with a 200x200 view plane and ambient WHITE x 0.15). All 500x500 pixels.
SceneSetup<LitScene> sphereDirectional();
SceneSetup<LitScene> spherePoint();
SceneSetup<LitScene> sphereSpot();
SceneSetup<LitScene> sphereSpotSharp();
SceneSetup<LitScene> trianglesDirectional();
SceneSetup<LitScene> trianglesPoint();
SceneSetup<LitScene> trianglesSpot();
SceneSetup<LitScene> trianglesSpotSharp();

/// tomi832's lightsScene1: the LightsTests sphere under a directional, a point and a focused
/// spot light; camera1, 1000x1000 pixels ("MultipleTest").
SceneSetup<LitScene> sphereMultiLight();
/// tomi832's lightsScene2: the LightsTests triangles under three lights, ambient WHITE x 0.05;
/// camera2's frame and view plane, 500x500 pixels ("MultipleTestTriangle").
SceneSetup<LitScene> trianglesMultiLight();

}  // namespace course
}  // namespace rt
