// What rt knows of mini project 2: the acceleration structure a render asks for (render.accel,
// --accel: none, cbr, bvh or grid), built once over the scene's shapes before any ray, the render
// on a pool of threads handing out square tiles (render.threads, --threads; 0: every core), and
// `rt bench`, the timing table across stages and accelerations (mini2_bvh/Bench.cpp).
#include <CLI/App.hpp>

#include "bvh/Acceleration.h"
#include "cli/CommandLine.h"
#include "cli/Registry.h"
#include "common/NearestName.h"
#include "mini2_bvh/Bench.h"
#include "parallel/TilePool.h"

namespace rt::cli {

void registerCli_mini2_bvh(CliRegistry& registry) {
  registry.makeAccelerator.supply("mini2_bvh", [](const SceneDocument& doc) {
    return makeAcceleration(doc.render.accel, doc.scene->geometries);
  });
  registry.render.supply("mini2_bvh", [](const RenderJob& job) {
    RenderOptions options;
    options.threads = job.threads;
    options.stop = job.stop;
    options.donePixels = &job.donePixels;
    options.doneRays = &job.doneRays;
    const RenderResult r = renderImage(job.context, job.image, options);
    return RenderOutcome{r.counts, r.interrupted, r.threads};
  });
  registry.commands.push_back(addBenchCommand);
  registry.sceneOptions.push_back([](CLI::App& command, SettingOverrides& into) {
    addOptional(command, "--threads", into.threads,
                "render threads, 0..1024; 0: one per core (default: the scene's render.threads)",
                "N")
        ->transform(integerValidator(0, RenderOptions::MAX_THREADS));
    addOptional(command, "--accel", into.accel,
                "none, cbr, bvh or grid (default: the scene's render.accel, bvh); the image is the "
                "same, bit for bit",
                "A")
        ->check([](const std::string& name) -> std::string {
          if (isAccelerationName(name)) return "";
          return unknownNameMessage("acceleration", name, ACCELERATION_NAMES);
        });
  });
}

}  // namespace rt::cli
