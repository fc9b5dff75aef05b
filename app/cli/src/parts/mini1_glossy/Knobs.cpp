// The demonstration scenes' --params (see Knobs.h): what each is called and takes, which scene
// offers which, and how their values become the scene's parameters and render settings.
#include "Knobs.h"

#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

#include "cli/CommandLine.h"
#include "cli/Values.h"
#include "glossy/DemoScenes.h"
#include "scenefile/LitDocument.h"

namespace rt::cli {

namespace {

/// A knob: what it is called and means, and which values it takes.
struct Knob {
  enum class Kind { Integer, Number, OnOff };
  const char* name;
  const char* meaning;
  Kind kind;
  double min = 0, max = 1;
};

using enum Knob::Kind;
const Knob SAMPLES{"samples", "N x N jittered samples per pixel", Integer, 1,
                   JitteredSampler::MAX_GRID};
const Knob LENS_SAMPLES{"lensSamples", "rays through the lens per sample", Integer, 1,
                        JitteredSampler::MAX_LENS_SAMPLES};
const Knob APERTURE{"aperture", "the lens radius (0: the pinhole)", Number, 0, 1000};
const Knob ADAPTIVE{"adaptive", "adaptive super-sampling instead of the jittered grid", OnOff};
const Knob SHADOW_SAMPLES{"shadowSamples", "shadow rays per light with a radius", Integer, 1,
                          PointLight::MAX_SHADOW_SAMPLES};
const Knob GLOSSY_GRID{"glossyGrid", "N of every reflected beam (1: a sharp mirror)", Integer, 1,
                       BeamSettings::MAX_GRID};
const Knob FROSTED_GRID{"frostedGrid", "N of every refracted beam (1: clear glass)", Integer, 1,
                        BeamSettings::MAX_GRID};

/// The knobs' values, by knob.
using Values = std::map<const Knob*, double>;

/// A knob a scene offers, with its default when it is one of the scene's parameters (none: a
/// sampling knob, whose default is the table entry's).
struct KnobUse {
  const Knob* knob;
  std::optional<double> sceneDefault;
};

/// A demonstration scene's knobs in --param order, and the scene made with their values.
struct DemoKnobs {
  const char* scene;
  std::vector<KnobUse> knobs;
  SceneSetup<LitScene> (*make)(const Values&);
};

int integer(const Values& v, const Knob& k) { return static_cast<int>(v.at(&k)); }

const std::vector<DemoKnobs>& demoKnobs() {
  using namespace demo;
  static const std::vector<DemoKnobs> table{
      {"glossy-spheres",
       {{&GLOSSY_GRID, GlossySpheresParams{}.beamGrid}, {&SAMPLES, {}}},
       [](const Values& v) { return glossySpheres({.beamGrid = integer(v, GLOSSY_GRID)}); }},
      {"frosted-glass",
       {{&FROSTED_GRID, FrostedGlassParams{}.beamGrid}, {&SAMPLES, {}}},
       [](const Values& v) { return frostedGlass({.beamGrid = integer(v, FROSTED_GRID)}); }},
      {"soft-shadows",
       {{&SHADOW_SAMPLES, SoftShadowsParams{}.shadowSamples}, {&SAMPLES, {}}},
       [](const Values& v) { return softShadows({.shadowSamples = integer(v, SHADOW_SAMPLES)}); }},
      {"antialiasing", {{&SAMPLES, {}}}, [](const Values&) { return antialiasing(); }},
      {"depth-of-field",
       {{&LENS_SAMPLES, {}}, {&APERTURE, DepthOfFieldParams{}.aperture}, {&SAMPLES, {}}},
       [](const Values& v) { return depthOfField({.aperture = v.at(&APERTURE)}); }},
      {"adaptive",
       {{&ADAPTIVE, {}}, {&SAMPLES, {}}},
       [](const Values&) { return adaptiveEdges(); }},
      {"super-sampling",
       {{&GLOSSY_GRID, SuperSamplingParams{}.glossyGrid},
        {&FROSTED_GRID, SuperSamplingParams{}.frostedGrid},
        {&SHADOW_SAMPLES, SuperSamplingParams{}.shadowSamples},
        {&SAMPLES, {}},
        {&LENS_SAMPLES, {}},
        {&APERTURE, SuperSamplingParams{}.aperture},
        {&ADAPTIVE, {}}},
       [](const Values& v) {
         return superSampling({.glossyGrid = integer(v, GLOSSY_GRID),
                               .frostedGrid = integer(v, FROSTED_GRID),
                               .shadowSamples = integer(v, SHADOW_SAMPLES),
                               .aperture = v.at(&APERTURE)});
       }},
  };
  return table;
}

const DemoKnobs& knobsOf(const DemoScene& entry) {
  for (const DemoKnobs& k : demoKnobs())
    if (std::string_view(k.scene) == entry.course.name) return k;
  throw std::logic_error(std::string("demoKnobs: no knobs for the demonstration scene '") +
                         entry.course.name + "'");
}

/// A sampling knob's value in the settings.
double samplingValue(const Knob& k, const SamplingSettings& s) {
  if (&k == &SAMPLES) return s.samples;
  if (&k == &LENS_SAMPLES) return s.lensSamples;
  if (&k == &ADAPTIVE) return s.adaptive ? 1 : 0;
  throw std::logic_error(std::string("samplingValue: ") + k.name + " is not a sampling knob");
}

/// The knob's value in the --params, checked.
double parseKnob(const Knob& k, const SceneParams& params) {
  const std::string& text = params.at(k.name);
  const std::string what = std::string("--param ") + k.name;
  switch (k.kind) {
    case Integer:
      return parseInt(text, what, static_cast<int>(k.min), static_cast<int>(k.max));
    case OnOff:
      return parseOnOff(text, k.name) ? 1 : 0;
    case Number:
      break;
  }
  const double v = parseDouble(text, what);
  if (!(v >= k.min && v <= k.max))
    throw UsageError(what + ": expected a number from " + formatNumber(k.min) + " to " +
                     formatNumber(k.max) + ", got " + formatNumber(v));
  return v;
}

}  // namespace

bool parseOnOff(const std::string& value, const char* what) {
  if (value == "on" || value == "true" || value == "1") return true;
  if (value == "off" || value == "false" || value == "0") return false;
  throw UsageError(std::string("--param ") + what + ": expected on or off, got '" + value + "'");
}

std::vector<SceneParam> demoParams(const DemoScene& entry) {
  std::vector<SceneParam> out;
  for (const auto& [knob, sceneDefault] : knobsOf(entry).knobs) {
    const double value = sceneDefault ? *sceneDefault : samplingValue(*knob, entry.sampling);
    out.push_back({knob->name,
                   knob->kind == OnOff ? (value == 1 ? "on" : "off") : formatNumber(value),
                   knob->meaning});
  }
  return out;
}

SceneDocument demoDocument(const DemoScene& entry, const SceneParams& params) {
  const DemoKnobs& knobs = knobsOf(entry);
  Values values;
  for (const KnobUse& use : knobs.knobs) values[use.knob] = parseKnob(*use.knob, params);
  SceneSetup<LitScene> setup = knobs.make(values);
  SamplingSettings s = entry.sampling;
  if (const auto it = values.find(&SAMPLES); it != values.end())
    s.samples = static_cast<int>(it->second);
  if (const auto it = values.find(&LENS_SAMPLES); it != values.end())
    s.lensSamples = static_cast<int>(it->second);
  if (const auto it = values.find(&ADAPTIVE); it != values.end()) s.adaptive = it->second == 1;
  SceneDocument doc = litDocument(std::move(setup.scene), setup.camera);
  doc.render.tracer = "beams";
  doc.render.samples = s.samples;
  doc.render.lensSamples = s.lensSamples;
  doc.render.adaptive = s.adaptive;
  doc.render.adaptiveThreshold = s.adaptiveThreshold;
  doc.render.adaptiveDepth = s.adaptiveDepth;
  doc.render.seed = s.seed;
  return doc;
}

}  // namespace rt::cli
