#pragma once
/// @file Tracers.h
/// The tracer family by name, one per stage, so that one scene can be rendered by each stage's
/// tracer and the images (and timings) compared: `rt render NAME --tracer phong`.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "camera/RayTracer.h"
#include "scenefile/SceneDocument.h"

namespace rt::cli {

struct TracerKind {
  std::string_view name;         ///< the value of --tracer and of a scene file's render.tracer
  std::string_view stage;        ///< the stage that adds it
  std::string_view description;  ///< one line
  /// Builds the tracer over doc.scene with doc.render's settings; doc must outlive it.
  std::unique_ptr<RayTracer> (*make)(const SceneDocument& doc);
};

/// ambient, phong, shadow, whitted.
std::span<const TracerKind> tracerKinds();

/// The tracer called name, or nullptr.
const TracerKind* tracerNamed(std::string_view name);

/// "unknown tracer 'phog'; did you mean 'phong'? (known: ambient phong shadow whitted)".
std::string unknownTracerMessage(std::string_view name);

/// The tracer called name. @throws UsageError "WHAT: " + unknownTracerMessage(name).
const TracerKind& findTracer(std::string_view name, std::string_view what = "--tracer");

}  // namespace rt::cli
