// What rt knows of mini project 1: the beams tracer (glossy surfaces, diffused glass, soft
// shadows), the samplers the render settings choose (jittered, lens, adaptive), and the seed's
// galaxy in a glass box with its parameters and points of view, and the demonstration scenes of
// glossy/DemoScenes.h with their knobs as parameters.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli/CommandLine.h"
#include "cli/Registry.h"
#include "cli/Values.h"
#include "glossy/BeamTracer.h"
#include "glossy/DemoScenes.h"
#include "glossy/Galaxy.h"
#include "glossy/Samplers.h"
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

bool parseOnOff(const std::string& value, const char* what) {
  if (value == "on" || value == "true" || value == "1") return true;
  if (value == "off" || value == "false" || value == "0") return false;
  throw UsageError(std::string("--param ") + what + ": expected on or off, got '" + value + "'");
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

/// A knob's value as --param shows it: on or off for adaptive, a number otherwise.
std::string knobText(DemoKnob knob, double value) {
  if (knob == DemoKnob::Adaptive) return value == 1 ? "on" : "off";
  return formatNumber(value);
}

/// A demonstration scene as a document: its scene and camera, its sampling settings as the render
/// settings, each --param given set on it first (the table's defaults are the scene's own values).
SceneDocument demoDocument(const DemoScene& entry, const SceneParams& p) {
  DemoSetup setup = entry.build();
  for (const DemoKnob knob : entry.knobs) {
    const DemoKnobInfo& info = knobInfo(knob);
    const std::string& text = p.at(info.name);
    const std::string what = std::string("--param ") + info.name;
    const double value = knob == DemoKnob::Adaptive ? (parseOnOff(text, info.name) ? 1 : 0)
                         : info.integer ? parseInt(text, what, static_cast<int>(info.min),
                                                   static_cast<int>(info.max))
                                        : parseDouble(text, what);
    try {
      setKnob(setup, knob, value);
    } catch (const std::invalid_argument& e) {
      throw UsageError("--param " + std::string(e.what()));
    }
  }
  SceneDocument doc = litDocument(std::move(setup.scene), setup.camera);
  const SamplingSettings& s = setup.sampling;
  doc.render.tracer = "beams";
  doc.render.samples = s.samples;
  doc.render.lensSamples = s.lensSamples;
  doc.render.adaptive = s.adaptive;
  doc.render.adaptiveThreshold = s.adaptiveThreshold;
  doc.render.adaptiveDepth = s.adaptiveDepth;
  doc.render.seed = s.seed;
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
       "the seed's Glassed Galaxy: ~1000 glowing stars in a diffused-glass box (views: main, "
       "above, inside, side)",
       "mini1_glossy",
       "beams",
       {{"arms", "21", "spiral arms (every seventh from the fourth holds suns)"},
        {"perArm", "50", "positions per arm"},
        {"stars", "0", "about this many stars in all (sets perArm; 0: arms x perArm)"},
        {"diffusion", "on", "the glass box's beams (on or off)"},
        {"layout", "1", "the generator's seed: where the stars are"}},
       galaxyDocument});
  for (const DemoScene& entry : demoScenes()) {
    std::vector<SceneParam> params;
    const DemoSetup defaults = entry.build();
    for (const DemoKnob knob : entry.knobs) {
      const DemoKnobInfo& info = knobInfo(knob);
      params.push_back({info.name, knobText(knob, knobValue(defaults, knob)), info.meaning});
    }
    registry.scenes.push_back({entry.course.name, entry.course.description, "mini1_glossy", "beams",
                               std::move(params),
                               [&entry](const SceneParams& p) { return demoDocument(entry, p); }});
  }
  registry.makeSampler.supply("mini1_glossy", [](const RenderSettings& settings) {
    return makePixelSampler(samplingOf(settings));
  });
}

}  // namespace rt::cli
