// Every key of the scene format, object by object in the documented order, with the stage that
// gives it a meaning (docs/scene-format.md lists them with their defaults; FormatDocTests checks
// that the two agree, and that a full build has a reader for every key).
#include "Format.h"

namespace rt::scenefile {

namespace {

constexpr Presence R = Presence::Required;
constexpr Presence D = Presence::Defaulted;
constexpr Presence O = Presence::Optional;

constexpr std::string_view S04 = "stage04_camera", S05 = "stage05_lighting",
                           S07 = "stage07_reflections", M1 = "mini1_glossy", M2 = "mini2_bvh";

constexpr CatalogueKey KEYS[] = {
    {"document", "name", S04, D, "\"\""},
    {"document", "camera", S04, R, ""},
    {"document", "views", S04, D, "{}"},
    {"document", "background", S04, D, "[0,0,0]"},
    {"document", "ambient", S04, D, "{}"},
    {"document", "lights", S05, D, "[]"},
    {"document", "materials", S05, D, "{}"},
    {"document", "geometries", S04, D, "[]"},
    {"document", "render", S04, D, "{}"},

    {"camera", "location", S04, R, ""},
    {"camera", "target", S04, O, "none"},
    {"camera", "to", S04, O, "none"},
    {"camera", "up", S04, O, "[0,1,0]"},
    {"camera", "vpDistance", S04, R, ""},
    {"camera", "vpSize", S04, R, ""},
    {"camera", "resolution", S04, R, ""},
    {"camera", "aperture", S04, D, "0"},
    {"camera", "focalDistance", S04, D, "0"},
    {"camera", "lensSamples", M1, D, "1"},

    {"ambient", "color", S04, D, "[0,0,0]"},
    {"ambient", "kA", S04, D, "1"},

    {"material", "kD", S05, D, "0"},
    {"material", "kS", S05, D, "0"},
    {"material", "shininess", S05, D, "0"},
    {"material", "kT", S05, D, "0"},
    {"material", "kR", S05, D, "0"},
    {"material", "ior", S05, D, "1"},
    {"material", "reflectedBeam", M1, O, "none"},
    {"material", "refractedBeam", M1, O, "none"},

    {"beam", "distance", M1, D, "1"},
    {"beam", "radius", M1, D, "0"},
    {"beam", "grid", M1, D, "1"},

    {"light directional", "intensity", S05, R, ""},
    {"light directional", "direction", S05, R, ""},
    {"light point", "intensity", S05, R, ""},
    {"light point", "position", S05, R, ""},
    {"light point", "kC", S05, D, "1"},
    {"light point", "kL", S05, D, "0"},
    {"light point", "kQ", S05, D, "0"},
    {"light point", "radius", M1, D, "0"},
    {"light point", "shadowSamples", M1, D, "1"},
    {"light spot", "intensity", S05, R, ""},
    {"light spot", "position", S05, R, ""},
    {"light spot", "kC", S05, D, "1"},
    {"light spot", "kL", S05, D, "0"},
    {"light spot", "kQ", S05, D, "0"},
    {"light spot", "direction", S05, R, ""},
    {"light spot", "narrowBeam", S05, D, "1"},
    {"light spot", "radius", M1, D, "0"},
    {"light spot", "shadowSamples", M1, D, "1"},

    {"geometry sphere", "center", S04, R, ""},
    {"geometry sphere", "radius", S04, R, ""},
    {"geometry plane", "point", S04, O, "none"},
    {"geometry plane", "normal", S04, O, "none"},
    {"geometry plane", "points", S04, O, "none"},
    {"geometry triangle", "vertices", S04, R, ""},
    {"geometry polygon", "vertices", S04, R, ""},
    {"geometry tube", "axis", S04, R, ""},
    {"geometry tube", "radius", S04, R, ""},
    {"geometry cylinder", "axis", S04, R, ""},
    {"geometry cylinder", "radius", S04, R, ""},
    {"geometry cylinder", "height", S04, R, ""},
    {"geometry mesh", "file", M2, O, "none"},
    {"geometry mesh", "vertices", M2, O, "none"},
    {"geometry mesh", "triangles", M2, O, "none"},
    {"geometry mesh", "normals", M2, O, "none"},
    {"geometry mesh", "scale", M2, D, "1"},
    {"geometry mesh", "rotation", M2, D, "[0,0,0]"},
    {"geometry mesh", "translation", M2, D, "[0,0,0]"},
    {"geometry mesh", "shading", M2, D, "\"smooth\""},
    {"geometry mesh", "materials", M2, O, "none"},
    {"geometry", "emission", S05, D, "[0,0,0]"},
    {"geometry", "material", S05, O, "none"},
    {"geometry", "name", S04, D, "\"\""},

    {"axis", "origin", S04, R, ""},
    {"axis", "direction", S04, R, ""},

    {"render", "tracer", S04, O, "the highest stage's"},
    {"render", "maxLevel", S07, D, "10"},
    {"render", "minK", S07, D, "0.001"},
    {"render", "seed", S04, D, "0"},
    {"render", "gridLines", S04, D, "0"},
    {"render", "gridColor", S04, D, "[255,255,0]"},
    {"render", "samples", M1, D, "1"},
    {"render", "adaptive", M1, D, "false"},
    {"render", "adaptiveThreshold", M1, D, "16"},
    {"render", "adaptiveDepth", M1, D, "2"},
    {"render", "beamDepth", M1, D, "\"first\""},
    {"render", "accel", M2, D, "\"bvh4\""},
    {"render", "lightBuffers", M2, D, "true"},
    {"render", "threads", M2, D, "0"},
};

// The debugging views of stage 4 first (they show stages 1, 2 and 3), so the last tracer of a
// build is always its highest stage's.
constexpr CatalogueTracer TRACERS[] = {
    {"rays", "stage04_camera"},         {"normals", "stage04_camera"},
    {"hits", "stage04_camera"},         {"ambient", "stage04_camera"},
    {"phong", "stage05_lighting"},      {"shadow", "stage06_shadows"},
    {"whitted", "stage07_reflections"}, {"beams", "mini1_glossy"}};

}  // namespace

std::span<const CatalogueKey> keyCatalogue() { return KEYS; }
std::span<const CatalogueTracer> tracerCatalogue() { return TRACERS; }

}  // namespace rt::scenefile
