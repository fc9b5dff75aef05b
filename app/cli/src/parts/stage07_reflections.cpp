// What rt knows of stage 7: the Whitted tracer and the stage's scenes.
#include "CourseTables.h"
#include "reflections/CourseScenes.h"
#include "reflections/WhittedTracer.h"

namespace rt::cli {

void registerCli_stage07_reflections(CliRegistry& registry) {
  registry.tracers.push_back(
      {"whitted", "stage07_reflections", "shadows plus recursive reflection and refraction",
       [](const SceneDocument& doc, const Intersectable* accelerator) {
         return std::unique_ptr<RayTracer>(std::make_unique<WhittedTracer>(
             litScene(doc), accelerator, WhittedSettings{doc.render.maxLevel, doc.render.minK}));
       }});
  addCourseScenes(registry, reflectionScenes(), "stage07_reflections", "whitted");
}

}  // namespace rt::cli
