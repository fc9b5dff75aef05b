#include "cli/BuiltinScenes.h"

#include <set>
#include <stdexcept>
#include <vector>

#include "camera/CourseScenes.h"
#include "lighting/CourseScenes.h"
#include "reflections/CourseScenes.h"
#include "shadows/CourseScenes.h"

namespace rt::cli {

namespace {

/// Adds every scene of a stage's table, rendered by default with that stage's tracer.
void addTable(std::vector<BuiltinScene>& out, std::span<const CourseScene> table,
              std::string_view stage, std::string_view tracer) {
  for (const CourseScene& entry : table) {
    auto make = entry.make;
    out.push_back({entry.name, entry.description, std::string(stage), std::string(tracer),
                   [make, t = std::string(tracer)] { return toDocument(make(), t); }});
  }
}

std::vector<BuiltinScene> collectScenes() {
  std::vector<BuiltinScene> scenes;
  // Stage 4 has a single scene and no table; it is an ambient-only Scene, lifted to a LitScene
  // (every shape black and matte) so that every tracer can render it.
  scenes.push_back({"two-color",
                    "the course's base render test: four flat pink shapes on green, ambient only",
                    "stage04_camera", "ambient", [] {
                      const SceneSetup<Scene> setup = twoColorScene();
                      return toDocument({LitScene(setup.scene), setup.camera}, "ambient");
                    }});
  addTable(scenes, lightingScenes(), "stage05_lighting", "phong");
  addTable(scenes, shadowScenes(), "stage06_shadows", "shadow");
  addTable(scenes, reflectionScenes(), "stage07_reflections", "whitted");

  std::set<std::string_view> names;
  for (const BuiltinScene& s : scenes)
    if (!names.insert(s.name).second)
      throw std::logic_error("built-in scenes: the name '" + s.name + "' is used twice");
  return scenes;
}

}  // namespace

std::span<const BuiltinScene> builtinScenes() {
  static const std::vector<BuiltinScene> scenes = collectScenes();
  return scenes;
}

const BuiltinScene* findBuiltinScene(std::string_view name) {
  for (const BuiltinScene& s : builtinScenes())
    if (s.name == name) return &s;
  return nullptr;
}

SceneDocument toDocument(const SceneSetup<LitScene>& setup, std::string_view tracer) {
  SceneDocument doc;
  doc.scene = setup.scene;
  doc.camera = setup.camera;
  doc.render.tracer = std::string(tracer);
  return doc;
}

}  // namespace rt::cli
