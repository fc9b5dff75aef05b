#pragma once
/// @file JsonText.h
/// The JSON the app writes, in one layout: scene files (`rt export`, the scene-file library's
/// dumpScene) and `rt probe`'s answers. Short values stay on one line, so a point reads as
/// [0, 0, -50] rather than five lines, and every number is in its shortest form that reads back
/// to the same double.

#include <string>

#include <nlohmann/json.hpp>

#include "primitives/Double3.h"

namespace rt {

/// A double as JSON: an integral value below 2^53 in magnitude as an integer (2 rather than
/// 2.0), a NaN or an infinity as null (JSON has neither), any other value as a double. -0 stays a
/// double, so that it is written as -0.0 and reads back as -0.
nlohmann::ordered_json jsonNumber(double v);

/// [x, y, z], each through jsonNumber.
nlohmann::ordered_json jsonTriple(const Double3& v);

/// j as text, ending with a newline:
/// - two-space indentation;
/// - the document itself one member (or element) per line;
/// - inside it, a value whose one-line form fits within 100 columns stays on one line
///   ({"kA": 0.15, "color": [255, 255, 255]}), except a list of objects (lights, geometries,
///   hits), which gets one line per object;
/// - doubles with the fewest digits that read back to the same double, in printf's %g notation
///   (0.1, 0.0005, 1e-05, 1e+23), -0 as -0.0, NaN and infinities as null; strings escaped as
///   JSON requires, invalid UTF-8 replaced by U+FFFD.
std::string formatJson(const nlohmann::ordered_json& j);

}  // namespace rt
