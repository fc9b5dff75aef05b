#pragma once
// Internal to mini1's part of rt: the demonstration scenes' knobs, the settings that
// `rt render NAME --param KNOB=VALUE` may change. Each changes what a scene file's key of the same
// name sets:
//
//   samples        render.samples: N x N jittered samples per pixel
//   lensSamples    camera.lensSamples: rays through the lens per sample
//   aperture       camera.aperture: the lens radius (0: the pinhole)
//   adaptive       render.adaptive: on or off
//   shadowSamples  shadowSamples of every light with a radius
//   glossyGrid     grid N of every reflected beam with a radius (1: a sharp mirror)
//   frostedGrid    grid N of every refracted beam with a radius (1: clear glass)
//
// The sampling knobs change the table entry's SamplingSettings; the others are the scenes' typed
// parameters (glossy/DemoScenes.h).

#include <string>
#include <vector>

#include "cli/Registry.h"
#include "glossy/DemoTable.h"

namespace rt::cli {

/// "on", "true", "1" or "off", "false", "0".
/// @throws UsageError naming --param `what` for anything else.
bool parseOnOff(const std::string& value, const char* what);

/// The --params of a demonstration scene, in order, with the scene's own values as defaults.
/// @throws std::logic_error for a scene the knobs' table does not know.
std::vector<SceneParam> demoParams(const DemoScene& entry);

/// The demonstration scene as a document (the beams tracer, its sampling settings as the render
/// settings), built with the values of its --params (every one of them in `params`).
/// @throws UsageError naming the first --param, in order, whose value it does not take.
SceneDocument demoDocument(const DemoScene& entry, const SceneParams& params);

}  // namespace rt::cli
