#include "cli/Tracers.h"

#include <vector>

#include "cli/CommandLine.h"
#include "common/NearestName.h"
#include "lighting/PhongTracer.h"
#include "reflections/WhittedTracer.h"
#include "shadows/ShadowTracer.h"

namespace rt::cli {

namespace {

const TracerKind kTracers[] = {
    {"ambient", "stage04_camera", "the ambient light wherever a ray hits a shape",
     [](const SceneDocument& doc) -> std::unique_ptr<RayTracer> {
       return std::make_unique<AmbientTracer>(doc.scene);
     }},
    {"phong", "stage05_lighting", "emission, ambient light and Phong shading; no shadows",
     [](const SceneDocument& doc) -> std::unique_ptr<RayTracer> {
       return std::make_unique<PhongTracer>(doc.scene);
     }},
    {"shadow", "stage06_shadows", "Phong shading with shadows, partial behind transparent shapes",
     [](const SceneDocument& doc) -> std::unique_ptr<RayTracer> {
       return std::make_unique<ShadowTracer>(doc.scene);
     }},
    {"whitted", "stage07_reflections", "shadows plus recursive reflection and refraction",
     [](const SceneDocument& doc) -> std::unique_ptr<RayTracer> {
       return std::make_unique<WhittedTracer>(
           doc.scene, nullptr, WhittedSettings{doc.render.maxLevel, doc.render.minK});
     }},
};

}  // namespace

std::span<const TracerKind> tracerKinds() { return kTracers; }

const TracerKind* tracerNamed(std::string_view name) {
  for (const TracerKind& t : kTracers)
    if (t.name == name) return &t;
  return nullptr;
}

std::string unknownTracerMessage(std::string_view name) {
  std::vector<std::string_view> names;
  for (const TracerKind& t : kTracers) names.push_back(t.name);
  std::string message =
      "unknown tracer '" + std::string(name) + "'" + didYouMean(name, names) + " (known:";
  for (std::string_view n : names) message += " " + std::string(n);
  return message + ")";
}

const TracerKind& findTracer(std::string_view name, std::string_view what) {
  if (const TracerKind* t = tracerNamed(name)) return *t;
  throw UsageError(std::string(what) + ": " + unknownTracerMessage(name));
}

}  // namespace rt::cli
