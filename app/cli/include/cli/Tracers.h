#pragma once
/// @file Tracers.h
/// The tracer family by name, one per stage present, so that one scene can be rendered by each
/// stage's tracer and the images (and timings) compared: `rt render NAME --tracer phong`.

#include <span>
#include <string>
#include <string_view>

#include "cli/Registry.h"

namespace rt::cli {

/// The tracers of this build, in the course's order (rays, normals, hits, ambient, phong, shadow,
/// whitted, beams in the full course: stage 4's debugging views first).
std::span<const TracerKind> tracerKinds();

/// The tracer called name; the build's default (its highest stage's) for an empty name; or
/// nullptr.
const TracerKind* tracerNamed(std::string_view name);

/// "unknown tracer 'phog'; did you mean 'phong'? (known: rays normals ...)", or for a tracer of
/// a stage the build does not have, "the tracer 'whitted' needs stage07_reflections, which this
/// build does not include".
std::string unknownTracerMessage(std::string_view name);

/// The tracer called name (empty: the default). @throws UsageError "WHAT: " +
/// unknownTracerMessage(name).
const TracerKind& findTracer(std::string_view name, std::string_view what = "--tracer");

}  // namespace rt::cli
