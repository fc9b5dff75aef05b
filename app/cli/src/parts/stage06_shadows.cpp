// What rt knows of stage 6: the shadow tracer and the stage's scenes.
#include "CourseTables.h"
#include "shadows/CourseScenes.h"
#include "shadows/ShadowTracer.h"

namespace rt::cli {

void registerCli_stage06_shadows(CliRegistry& registry) {
  registry.tracers.push_back({"shadow", "stage06_shadows",
                              "Phong shading with shadows, partial behind transparent shapes",
                              [](const SceneDocument& doc, const Intersectable* accelerator) {
                                return std::unique_ptr<RayTracer>(
                                    std::make_unique<ShadowTracer>(litScene(doc), accelerator));
                              }});
  addCourseScenes(registry, shadowScenes(), "stage06_shadows", "shadow");
}

}  // namespace rt::cli
