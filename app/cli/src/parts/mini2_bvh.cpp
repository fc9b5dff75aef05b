// What rt knows of mini project 2: the acceleration structure a render asks for (render.accel,
// --accel: none, cbr, bvh, bvh4 or grid), built once over the scene's shapes before any ray, the
// render on a pool of threads handing out square tiles (render.threads, --threads; 0: every core),
// `rt bench`, the timing table across stages and accelerations (mini2_bvh/Bench.cpp), and the
// course's own benchmark scene, TeapotTest, with its later year's bubbles (scenes/Teapot.h).
#include <CLI/App.hpp>

#include "bvh/Acceleration.h"
#include "camera/Image.h"
#include "cli/CommandLine.h"
#include "cli/Registry.h"
#include "cli/Values.h"
#include "common/NearestName.h"
#include "geometries/UtahTeapot.h"
#include "mini1_glossy/Knobs.h"
#include "mini2_bvh/Bench.h"
#include "parallel/TilePool.h"
#include "scenefile/LitDocument.h"
#include "scenes/Teapot.h"

namespace rt::cli {

namespace {

/// The parameters both teapot scenes have.
std::vector<SceneParam> teapotParams() {
  return {
      {"detail", "4",
       "quads per Bezier patch side, 1.." + std::to_string(kUtahTeapotMaxDetail) +
           ": 64*d^2 - 8*d triangles (4: the course's 992; 125: about 10^6)"},
      {"smooth", "off", "the patches' own normals (on) or flat triangles as the course's (off)"},
      {"grid", "0", "the course's yellow grid lines every N pixels (the course's: 50; 0: none)"},
      {"floor", "0",
       "not the course's: a square grey floor under the teapot, 2*N wide (two triangles; "
       "10000: where the grid loses to the BVH); 0: none"}};
}

TeapotOptions teapotOptions(const SceneParams& p) {
  return {.detail = parseInt(p.at("detail"), "--param detail", 1, kUtahTeapotMaxDetail),
          .smooth = parseOnOff(p.at("smooth"), "smooth"),
          .floor = parseDouble(p.at("floor"), "--param floor")};
}

/// The scene as a document rendered by the course's tracer of the time (stage 7's Whitted: the
/// course's SimpleRayTracer with shadows, reflection and refraction), with --param grid's lines.
SceneDocument teapotDocument(SceneSetup<LitScene> setup, const SceneParams& p) {
  SceneDocument doc = litDocument(std::move(setup.scene), setup.camera);
  doc.render.tracer = "whitted";
  doc.render.gridLines = parseInt(p.at("grid"), "--param grid", 0, Image::MAX_SIDE);
  return doc;
}

}  // namespace

void registerCli_mini2_bvh(CliRegistry& registry) {
  registry.scenes.push_back(
      {"teapot",
       "the course's TeapotTest, its lecturer's benchmark of threads: the Utah teapot of 992 flat "
       "triangles and a point light, 800x800",
       "mini2_bvh", "whitted", teapotParams(),
       [](const SceneParams& p) { return teapotDocument(teapotScene(teapotOptions(p)), p); }});
  std::vector<SceneParam> bubbleParams = teapotParams();
  bubbleParams.push_back(
      {"count", "400", "bubbles, 0.." + std::to_string(BubbleOptions::MAX_COUNT)});
  bubbleParams.push_back({"seed", "1", "the generator's seed: where the bubbles are"});
  registry.scenes.push_back(
      {"bubbles",
       "the course's later TeapotTest: the teapot and 400 small reflective bubbles rising from its "
       "spout, 1000x1000",
       "mini2_bvh", "whitted", std::move(bubbleParams), [](const SceneParams& p) {
         const BubbleOptions bubbles{
             .count = parseInt(p.at("count"), "--param count", 0, BubbleOptions::MAX_COUNT),
             .seed =
                 static_cast<std::uint64_t>(parseInt(p.at("seed"), "--param seed", 0, INT_MAX))};
         return teapotDocument(bubblesScene(teapotOptions(p), bubbles), p);
       }});
  registry.makeAccelerator.supply("mini2_bvh", [](const SceneDocument& doc) {
    // A scene of stage 4 has no lights: nothing for light buffers to do.
    const auto* lit = dynamic_cast<const LitScene*>(doc.scene.get());
    return makeAcceleration(
        doc.render.accel, doc.scene->geometries,
        lit ? std::span<const LightSource>(lit->lights) : std::span<const LightSource>(),
        doc.render.lightBuffers);
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
                "none, cbr, bvh, bvh4 or grid (default: the scene's render.accel, bvh4); the image "
                "is the same, bit for bit",
                "A")
        ->check([](const std::string& name) -> std::string {
          if (isAccelerationName(name)) return "";
          return unknownNameMessage("acceleration", name, ACCELERATION_NAMES);
        });
    command
        .add_option_function<std::string>(
            "--light-buffers",
            [&into](const std::string& value) { into.lightBuffers = value == "on"; },
            "on or off: a light buffer per point light for the shadow rays (default: the scene's "
            "render.lightBuffers, on); the image is the same, bit for bit")
        ->type_name("on|off")
        ->check([](const std::string& value) -> std::string {
          if (value == "on" || value == "off") return "";
          return "expected on or off, got '" + value + "'";
        });
  });
}

}  // namespace rt::cli
