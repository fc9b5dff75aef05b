// What rt knows of stage 4: the ambient tracer, the course's two-colour scene, the course's
// sampling (one ray through each pixel's centre) and the render loop on the calling thread.
#include "camera/CourseScenes.h"
#include "cli/Registry.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {

namespace {

/// One row after another on the calling thread: a stop request (Ctrl-C) is seen within a row;
/// each row's counts are added once, and its pixels reported to the progress thread once.
RenderOutcome renderRows(const RenderJob& job) {
  RenderOutcome outcome;
  const int nX = job.camera.nX(), nY = job.camera.nY();
  for (int y = 0; y < nY; ++y) {
    if (job.stop && job.stop->load(std::memory_order_relaxed)) {
      outcome.interrupted = true;
      return outcome;
    }
    const PixelBlock row{0, y, nX, y + 1};
    const RayCounts counts = renderBlock(job.camera, job.tracer, job.sampler, row, job.image);
    outcome.counts += counts;
    job.donePixels.fetch_add(row.pixels(), std::memory_order_relaxed);
    job.doneRays.fetch_add(counts.total(), std::memory_order_relaxed);
  }
  return outcome;
}

}  // namespace

void registerCli_stage04_camera(CliRegistry& registry) {
  registry.tracers.push_back({"ambient", "stage04_camera",
                              "the ambient light wherever a ray hits a shape",
                              [](const SceneDocument& doc, const Intersectable* accelerator) {
                                return std::unique_ptr<RayTracer>(
                                    std::make_unique<AmbientTracer>(*doc.scene, accelerator));
                              }});
  // The stage has a single scene and no table. It is the course's ambient-only Scene, as this
  // build's scene model (from stage 5 on, a LitScene whose shapes are black and matte, so that
  // every tracer can render it).
  registry.scenes.push_back(
      {"two-color",
       "the course's base render test: four flat pink shapes on green, ambient only",
       "stage04_camera",
       "ambient",
       {},
       [](const SceneParams&) {
         const SceneSetup<Scene> setup = twoColorScene();
         SceneDocument doc;
         doc.scene = sceneModelOf(setup.scene);
         doc.camera = setup.camera;
         doc.render.tracer = "ambient";
         return doc;
       }});
  registry.makeSampler = [](const RenderSettings& settings) {
    return std::unique_ptr<PixelSampler>(std::make_unique<CenterSampler>(settings.seed));
  };
  registry.render = renderRows;
}

}  // namespace rt::cli
