#pragma once
/// @file Writers.h
/// What the format's parts share to write a document back: exact comparisons, and numbers,
/// colours, coefficients and directions as JSON that reads back to the same bits.

#include <nlohmann/json.hpp>

#include "common/JsonText.h"
#include "primitives/Color.h"
#include "primitives/Double3.h"
#include "primitives/Vector.h"

namespace rt::scenefile {

using Json = nlohmann::ordered_json;

/// Bitwise equality: 0 and -0 differ, as they do when read back.
bool same(double a, double b);
bool same(const Double3& a, const Double3& b);

inline Json color(const Color& c) { return jsonTriple(c.rgb()); }

/// One number when the three channels are the same, else [r,g,b].
Json coefficient(const Double3& k);

/// A vector that the loader's normalisation turns into exactly u (a stored plane normal, axis
/// or light direction): the shortest such vector found among small integer ratios, u itself
/// and multiples of u.
Json direction(const Vector& u);

}  // namespace rt::scenefile
