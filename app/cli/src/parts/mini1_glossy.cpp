// What rt knows of mini project 1: the beams tracer (glossy surfaces, diffused glass, soft
// shadows), the samplers the render settings choose (jittered, lens, adaptive), and the reference
// report's galaxy in a glass box with its parameters and points of view, and the demonstration
// scenes of glossy/DemoTable.h with their knobs as parameters (mini1_glossy/Knobs.h).
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli/CommandLine.h"
#include "cli/Registry.h"
#include "cli/Values.h"
#include "glossy/BeamTracer.h"
#include "glossy/DemoTable.h"
#include "glossy/Galaxy.h"
#include "glossy/Samplers.h"
#include "mini1_glossy/Knobs.h"
#include "scenefile/LitDocument.h"

namespace rt::cli {

namespace {

SamplingSettings samplingOf(const RenderSettings& r) {
  return {.samples = r.samples,
          .lensSamples = r.lensSamples,
          .adaptive = r.adaptive,
          .adaptiveThreshold = r.adaptiveThreshold,
          .adaptiveDepth = r.adaptiveDepth,
          .seed = r.seed};
}

SceneDocument galaxyDocument(const SceneParams& p) {
  GalaxyParams params;
  params.arms = parseInt(p.at("arms"), "--param arms", 1, GalaxyParams::MAX_ARMS);
  params.perArm = parseInt(p.at("perArm"), "--param perArm", 1, GalaxyParams::MAX_PER_ARM);
  params.stars =
      parseInt(p.at("stars"), "--param stars", 0, static_cast<int>(GalaxyParams::MAX_STARS));
  params.diffusion = parseOnOff(p.at("diffusion"), "diffusion");
  params.seed = static_cast<std::uint64_t>(parseInt(p.at("layout"), "--param layout", 0, INT_MAX));
  GalaxySetup g = galaxy(params);
  SceneDocument doc = litDocument(std::move(g.scene), g.camera);
  for (const NamedView& v : g.views) doc.views.push_back(v);
  doc.render.tracer = "beams";
  return doc;
}

}  // namespace

void registerCli_mini1_glossy(CliRegistry& registry) {
  registry.tracers.push_back(
      {"beams", "mini1_glossy",
       "Whitted plus ray beams (glossy surfaces, diffused glass) and soft shadows",
       [](const SceneDocument& doc, const Intersectable* accelerator) {
         const BeamTracerSettings beams{doc.render.beamDepth == "every" ? BeamDepth::EveryBounce
                                                                        : BeamDepth::FirstBounce};
         return std::unique_ptr<RayTracer>(std::make_unique<BeamTracer>(
             litScene(doc), accelerator, WhittedSettings{doc.render.maxLevel, doc.render.minK},
             beams));
       }});
  registry.scenes.push_back(
      {"galaxy",
       "the reference report's Glassed Galaxy: ~1000 glowing stars in a diffused-glass box (views: "
       "main, "
       "above, inside, side)",
       "mini1_glossy",
       "beams",
       {{"arms", "21", "spiral arms (every seventh from the fourth holds suns)"},
        {"perArm", "50", "positions per arm"},
        {"stars", "0", "about this many stars in all (sets perArm; 0: arms x perArm)"},
        {"diffusion", "on", "the glass box's beams (on or off)"},
        {"layout", "1", "the generator's seed: where the stars are"}},
       galaxyDocument});
  for (const DemoScene& entry : demoScenes())
    registry.scenes.push_back({entry.course.name, entry.course.description, "mini1_glossy", "beams",
                               demoParams(entry),
                               [&entry](const SceneParams& p) { return demoDocument(entry, p); }});
  registry.makeSampler.supply("mini1_glossy", [](const RenderSettings& settings) {
    return makePixelSampler(samplingOf(settings));
  });
}

}  // namespace rt::cli
