// What rt knows of stage 5: the Phong tracer and the stage's scenes.
#include "CourseTables.h"
#include "lighting/PhongTracer.h"

namespace rt::cli {

void registerCli_stage05_lighting(CliRegistry& registry) {
  registry.tracers.push_back({"phong", "stage05_lighting",
                              "emission, ambient light and Phong shading; no shadows",
                              [](const SceneDocument& doc, const Intersectable* accelerator) {
                                return std::unique_ptr<RayTracer>(
                                    std::make_unique<PhongTracer>(litScene(doc), accelerator));
                              }});
  addCourseScenes(registry, lightingScenes(), "stage05_lighting", "phong");
}

}  // namespace rt::cli
