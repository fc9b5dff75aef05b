// The scene format's mini-project-1 part: beams on materials (glossy surfaces, diffused glass),
// sizes on lights (soft shadows), lens samples on the camera, and the render's sampling (jittered
// anti-aliasing, adaptive super-sampling, where beams are cast). A material's beams and a light's
// size are stage 5's data (lighting/Material.h, lighting/LightSource.h); this part gives them
// their keys.
#include "../Format.h"
#include "../Writers.h"
#include "Lighting.h"
#include "glossy/Samplers.h"
#include "lighting/LightSource.h"
#include "lighting/Material.h"

namespace rt::scenefile {

namespace {

constexpr std::string_view BEAM_DEPTHS[] = {"first", "every"};

BeamSettings readBeam(const Node& n) {
  static const KeyTable<BeamSettings> keys = sceneFormat().table<BeamSettings>("beam");
  BeamSettings beam;
  readObject(n, keys, beam, "a beam object {distance, radius, grid}");
  return beam;
}

}  // namespace

void registerFormat_mini1_glossy(SceneFormat& format) {
  using B = BeamSettings;
  format.attach<B>("beam", "distance", [](const Node& n, B& b) { b.distance = readPositive(n); });
  format.attach<B>("beam", "radius", [](const Node& n, B& b) { b.radius = readNonNegative(n); });
  format.attach<B>("beam", "grid",
                   [](const Node& n, B& b) { b.grid = readInteger(n, 1, BeamSettings::MAX_GRID); });
  format.attach<Material>("material", "reflectedBeam",
                          [](const Node& n, Material& m) { m.reflectedBeam = readBeam(n); });
  format.attach<Material>("material", "refractedBeam",
                          [](const Node& n, Material& m) { m.refractedBeam = readBeam(n); });

  for (const char* type : {"light point", "light spot"}) {
    format.attach<LightFields>(
        type, "radius", [](const Node& n, LightFields& f) { f.radius = readNonNegative(n); });
    format.attach<LightFields>(type, "shadowSamples", [](const Node& n, LightFields& f) {
      f.shadowSamples = readInteger(n, 1, PointLight::MAX_SHADOW_SAMPLES);
    });
  }

  format.attach<CameraFields>("camera", "lensSamples", [](const Node& n, CameraFields& f) {
    f.lensSamples = readInteger(n, 1, JitteredSampler::MAX_LENS_SAMPLES);
  });

  using R = RenderSettings;
  format.attach<R>("render", "samples", [](const Node& n, R& r) {
    r.samples = readInteger(n, 1, JitteredSampler::MAX_GRID);
  });
  format.attach<R>("render", "adaptive", [](const Node& n, R& r) { r.adaptive = readBoolean(n); });
  format.attach<R>("render", "adaptiveThreshold",
                   [](const Node& n, R& r) { r.adaptiveThreshold = readNonNegative(n); });
  format.attach<R>("render", "adaptiveDepth", [](const Node& n, R& r) {
    r.adaptiveDepth = readInteger(n, 0, AdaptiveSampler::MAX_DEPTH);
  });
  format.attach<R>("render", "beamDepth", [](const Node& n, R& r) {
    r.beamDepth = readChoice(n, "a beam depth", BEAM_DEPTHS);
  });
  format.addTracer("beams");

  format.writeDocument.push_back([](const SceneDocument& doc, Json& j) {
    const RenderSettings& r = doc.render;
    const RenderSettings d;
    if (r.lensSamples != d.lensSamples) j["camera"]["lensSamples"] = r.lensSamples;
    Json& render = j["render"];
    if (r.samples != d.samples) render["samples"] = r.samples;
    if (r.adaptive != d.adaptive) render["adaptive"] = r.adaptive;
    if (!same(r.adaptiveThreshold, d.adaptiveThreshold))
      render["adaptiveThreshold"] = jsonNumber(r.adaptiveThreshold);
    if (r.adaptiveDepth != d.adaptiveDepth) render["adaptiveDepth"] = r.adaptiveDepth;
    if (r.beamDepth != d.beamDepth) render["beamDepth"] = r.beamDepth;
  });
}

}  // namespace rt::scenefile
