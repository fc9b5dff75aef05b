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
    return "the tracer '" + std::string(name) + "' needs " + std::string(stage) +
           ", which this build does not include (a course cut before it)";
  std::vector<std::string_view> names;
  for (const TracerKind& t : tracerKinds()) names.push_back(t.name);
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
