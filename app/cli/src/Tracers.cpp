#include "cli/Tracers.h"

#include <vector>

#include "cli/CommandLine.h"
#include "common/NearestName.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {

std::span<const TracerKind> tracerKinds() { return cliRegistry().tracers; }

const TracerKind* tracerNamed(std::string_view name) {
  const std::vector<TracerKind>& tracers = cliRegistry().tracers;
  if (name.empty()) return tracers.empty() ? nullptr : &tracers.back();
  for (const TracerKind& t : tracers)
    if (t.name == name) return &t;
  return nullptr;
}

std::string unknownTracerMessage(std::string_view name) {
  if (const std::string_view stage = missingTracerStage(name); !stage.empty())
    return needsStageMessage("tracer", name, stage);
  std::vector<std::string_view> names;
  for (const TracerKind& t : tracerKinds()) names.push_back(t.name);
  return unknownNameMessage("tracer", name, names);
}

const TracerKind& findTracer(std::string_view name, std::string_view what) {
  if (const TracerKind* t = tracerNamed(name)) return *t;
  throw UsageError(std::string(what) + ": " + unknownTracerMessage(name));
}

}  // namespace rt::cli
