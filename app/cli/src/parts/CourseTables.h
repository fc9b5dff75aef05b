#pragma once
// Internal to the stage parts from stage 5 on: a stage's table of course scenes as built-in
// scenes, each rendered by default with that stage's tracer.

#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "cli/Registry.h"
#include "lighting/CourseScenes.h"
#include "scenefile/LitDocument.h"

namespace rt::cli {

inline void addCourseScenes(CliRegistry& registry, std::span<const CourseScene> table,
                            std::string_view stage, std::string_view tracer) {
  for (const CourseScene& entry : table) {
    auto make = entry.make;
    registry.scenes.push_back({entry.name,
                               entry.description,
                               std::string(stage),
                               std::string(tracer),
                               {},
                               [make, t = std::string(tracer), every = entry.gridInterval,
                                colour = entry.gridColor](const SceneParams&) {
                                 SceneSetup<LitScene> setup = make();
                                 SceneDocument doc =
                                     litDocument(std::move(setup.scene), setup.camera);
                                 doc.render.tracer = t;
                                 // The course's grid over its picture, where its table gives one.
                                 if (every > 0) {
                                   doc.render.gridLines = every;
                                   doc.render.gridColor = colour;
                                 }
                                 return doc;
                               }});
  }
}

}  // namespace rt::cli
