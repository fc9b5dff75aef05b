// What rt knows of stage 4: the debugging views (rays, normals, hits) and the ambient tracer,
// the course's two-colour scene and the shapes scene, the course's sampling (one ray through
// each pixel's centre) and the render loop on the calling thread.
#include "camera/CourseScenes.h"
#include "camera/DebugTracers.h"
#include "camera/ShapesScene.h"
#include "cli/Registry.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {

namespace {

/// One row after another on the calling thread: a stop request (Ctrl-C) is seen within a row;
/// each row's counts are added once, and its pixels reported to the progress thread once.
RenderOutcome renderRows(const RenderJob& job) {
  RenderOutcome outcome;
  const int nX = job.context.camera.nX(), nY = job.context.camera.nY();
  for (int y = 0; y < nY; ++y) {
    if (job.stop && job.stop->load(std::memory_order_relaxed)) {
      outcome.interrupted = true;
      return outcome;
    }
    const PixelBlock row{0, y, nX, y + 1};
    const RayCounts counts = renderBlock(job.context, row, job.image);
    outcome.counts += counts;
    job.donePixels.fetch_add(row.pixels(), std::memory_order_relaxed);
    job.doneRays.fetch_add(counts.total(), std::memory_order_relaxed);
  }
  return outcome;
}

/// The tracer T over the document's scene.
template <typename T>
TracerKind tracerKind(std::string name, std::string description, bool debugView) {
  return {std::move(name), "stage04_camera", std::move(description),
          [](const SceneDocument& doc, const Intersectable* accelerator) {
            return std::unique_ptr<RayTracer>(std::make_unique<T>(*doc.scene, accelerator));
          },
          debugView};
}

/// A scene of this stage as a document, in this build's scene model (from stage 5 on, a
/// LitScene whose shapes are black and matte, so that every tracer can render it).
BuiltinScene builtinScene(std::string name, std::string description, std::string tracer,
                          SceneSetup<Scene> (*make)()) {
  return {std::move(name),
          std::move(description),
          "stage04_camera",
          tracer,
          {},
          [make, tracer](const SceneParams&) {
            const SceneSetup<Scene> setup = make();
            SceneDocument doc;
            doc.scene = sceneModelOf(setup.scene);
            doc.camera = setup.camera;
            doc.render.tracer = tracer;
            return doc;
          }};
}

}  // namespace

void registerCli_stage04_camera(CliRegistry& registry) {
  // The debugging views first, in the order of the stages they show (1, 2, 3): the last tracer
  // of the list is the default of a scene file without render.tracer, the highest stage's.
  registry.tracers.push_back(
      tracerKind<RaysTracer>("rays", "debug view: the ray's direction d as (d*0.5+0.5)*255", true));
  registry.tracers.push_back(tracerKind<NormalsTracer>(
      "normals", "debug view: the nearest hit's normal n as (n*0.5+0.5)*255", true));
  registry.tracers.push_back(tracerKind<HitsTracer>(
      "hits", "debug view: hits along the ray: 1 blue, 2 green, 3 yellow, 4+ red", true));
  registry.tracers.push_back(
      tracerKind<AmbientTracer>("ambient", "the ambient light wherever a ray hits a shape", false));
  registry.scenes.push_back(builtinScene(
      "two-color", "the course's base render test: four flat pink shapes on green, ambient only",
      "ambient", twoColorScene));
  registry.scenes.push_back(
      builtinScene("shapes", "one of each of the six shapes of stage 2, shown by their normals",
                   "normals", shapesScene));
  registry.makeSampler.supply("stage04_camera", [](const RenderSettings& settings) {
    return std::unique_ptr<PixelSampler>(std::make_unique<CenterSampler>(settings.seed));
  });
  registry.render.supply("stage04_camera", renderRows);
}

}  // namespace rt::cli
