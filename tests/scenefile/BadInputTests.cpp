// Bad input: every class of error the loader reports, each with its exact message.
//
// Every case is one equivalence partition (EPnn) or boundary value (BVnn) of the input space of
// parseScene. Positions were counted by hand (and cross-checked with an independent script):
// the line is 1-based, the column counts characters from 1. Most cases share lines 1-3 (a valid
// camera) so that the offending value sits on line 4, which starts with two spaces.
#include <gtest/gtest.h>

#include <string>

#include "scenefile/SceneFile.h"

namespace rt {
namespace {

struct BadInput {
  const char* name;
  std::string text;
  std::string message;  ///< the exact what() of the SceneError
};

const BadInput BAD_INPUTS[] = {
    // EP01: malformed JSON - a comma before a closing brace (error at the brace)
    {"MalformedTrailingComma",
     "{\n"
     "  \"background\": [0, 0, 0],\n"
     "}\n",
     "bad.json:3:1: malformed JSON: syntax error while parsing object key - unexpected '}'; "
     "expected string literal"},
    // EP02: malformed JSON - a misspelt literal (error at the literal's start)
    {"MalformedBadLiteral",
     "{\n"
     "  \"name\": nul\n"
     "}\n",
     "bad.json:2:11: malformed JSON: syntax error while parsing value - invalid literal; last "
     "read: '\"name\": nul<U+000A>'"},
    // EP03: malformed JSON - text after the document
    {"MalformedTrailingText", "{\"name\": \"x\"} y\n",
     "bad.json:1:15: malformed JSON: syntax error while parsing value - invalid literal; last "
     "read: '\"x\"} y'; expected end of input"},
    // BV01: malformed JSON - empty text
    {"MalformedEmpty", "",
     "bad.json:1:1: malformed JSON: syntax error while parsing value - unexpected end of input; "
     "expected '[', '{', or a literal"},
    // EP04: the document is not an object
    {"NotAnObject", "[1, 2]\n", "bad.json:1:1: expected a scene object, got [1,2]"},
    // EP05: wrong type - a string where a number is expected
    {"WrongTypeNumber",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": \"far\",\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:2:73: camera.vpDistance: expected a positive number, got \"far\""},
    // EP06: wrong type - an object where an array is expected
    {"WrongTypeArray",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": {}\n"
     "}\n",
     "bad.json:4:17: geometries: expected an array of geometries, got {}"},
    // EP07: wrong type - a number where a string is expected
    {"WrongTypeString",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"name\": 7\n"
     "}\n",
     "bad.json:4:11: name: expected a string, got 7"},
    // EP08: wrong type - a point with two coordinates
    {"WrongTypePoint",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0], \"radius\": 1}]\n"
     "}\n",
     "bad.json:4:47: geometries[0].center: expected a point [x,y,z], got [0,0]"},
    // EP09: missing required key at the top level (error at the document)
    {"MissingCamera",
     "{\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:1:1: missing required key 'camera'"},
    // EP10: missing required key of a geometry (error at the geometry)
    {"MissingRadius",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -5]}]\n"
     "}\n",
     "bad.json:4:18: geometries[0]: missing required key 'radius'"},
    // EP11: missing type of a light
    {"MissingType",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"lights\": [{\"intensity\": [1, 1, 1]}]\n"
     "}\n",
     "bad.json:4:14: lights[0]: missing required key 'type'"},
    // EP12: unknown key close to a known one (a transposition)
    {"UnknownKeySuggested",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -5], \"raduis\": 1}]\n"
     "}\n",
     "bad.json:4:59: geometries[0].raduis: unknown key; did you mean 'radius'?"},
    // EP13: unknown top-level key close to a known one
    {"UnknownTopLevelKeySuggested",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometry\": []\n"
     "}\n",
     "bad.json:4:3: geometry: unknown key; did you mean 'geometries'?"},
    // EP14: unknown key far from every known one: the known keys are listed
    {"UnknownKeyListed",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"fps\": 4}\n"
     "}\n",
     "bad.json:4:14: render.fps: unknown key; expected one of: tracer, maxLevel, minK, seed, "
     "gridLines, gridColor, samples, adaptive, adaptiveThreshold, adaptiveDepth, beamDepth, accel "
     "and 2 more"},
    // EP15: unknown key differing only in case
    {"UnknownKeyCase",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"materials\": {\"m\": {\"kd\": 0.5}}\n"
     "}\n",
     "bad.json:4:23: materials.m.kd: unknown key; did you mean 'kD'?"},
    // EP16: a key given twice in one object
    {"DuplicateKey",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"name\": \"a\", \"name\": \"b\"\n"
     "}\n",
     "bad.json:4:16: name: duplicate key 'name'"},
    // EP17: non-finite number (overflows a double)
    {"NonFiniteRadius",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -5], \"radius\": 1e999}]\n"
     "}\n",
     "bad.json:4:69: geometries[0].radius: expected a finite number, got 1e999"},
    // EP18: non-finite negative number inside a colour
    {"NonFiniteNegative",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"background\": [-1e999, 0, 0]\n"
     "}\n",
     "bad.json:4:18: background[0]: expected a finite number, got -1e999"},
    // EP19: negative radius
    {"NegativeRadius",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -5], \"radius\": -2}]\n"
     "}\n",
     "bad.json:4:69: geometries[0].radius: expected a positive number, got -2"},
    // BV02: zero radius
    {"ZeroRadius",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -5], \"radius\": 0}]\n"
     "}\n",
     "bad.json:4:69: geometries[0].radius: expected a positive number, got 0"},
    // EP20: non-convex polygon (the constructor's message)
    {"NonConvexPolygon",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"polygon\", \"vertices\": [[0, 0, 0], [2, 0, 0], [1, 0.2, 0], "
     "[2, 2, 0], [0, 2, 0]]}]\n"
     "}\n",
     "bad.json:4:50: geometries[0].vertices: Polygon: the polygon is concave at vertices[2] "
     "(1,0.2,0)"},
    // EP21: polygon with a vertex out of the plane (the constructor's message)
    {"NonPlanarPolygon",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"polygon\", \"vertices\": [[0, 0, 0], [1, 0, 0], [1, 1, 1], "
     "[0, 1, 0]]}]\n"
     "}\n",
     "bad.json:4:50: geometries[0].vertices: Polygon: vertices[3] (0,1,0) is not in the plane of "
     "the first three vertices"},
    // EP22: triangle with collinear vertices (the constructor's message)
    {"CollinearTriangle",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"triangle\", \"vertices\": [[0, 0, 0], [1, 0, 0], [2, 0, "
     "0]]}]\n"
     "}\n",
     "bad.json:4:51: geometries[0].vertices: Triangle: the points (0,0,0), (1,0,0), (2,0,0) do not "
     "define a plane (two coincide or all are collinear)"},
    // EP45: a triangle so large that its normal would overflow: its coordinates are refused
    // first (beyond MAX_COORDINATE, 1e75)
    {"HugeTriangle",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"triangle\", \"vertices\": [[0, 0, 0], [1e300, 0, 0], [0, "
     "1e300, 0]]}]\n"
     "}\n",
     "bad.json:4:64: geometries[0].vertices[1][0]: expected a coordinate from -1e+75 to 1e+75, "
     "got 1e300"},
    // EP45b: a sphere beyond MAX_COORDINATE (its solver's squares overflowed: it vanished)
    {"FarSphere",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -1.000001e75], "
     "\"radius\": 1}]\n"
     "}\n",
     "bad.json:4:54: geometries[0].center[2]: expected a coordinate from -1e+75 to 1e+75, got "
     "-1.000001e75"},
    // EP45c: a radius beyond MAX_COORDINATE
    {"HugeRadius",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -5], \"radius\": 1e155}]\n"
     "}\n",
     "bad.json:4:69: geometries[0].radius: expected a length up to 1e+75, got 1e155"},
    // EP45d: a camera beyond MAX_COORDINATE, and a cylinder's height
    {"FarCamera",
     "{\n"
     "  \"camera\": {\"location\": [0, 2e150, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]}\n"
     "}\n",
     "bad.json:2:30: camera.location[1]: expected a coordinate from -1e+75 to 1e+75, got 2e150"},
    {"HugeCylinderHeight",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"cylinder\", \"axis\": {\"origin\": [0, 0, 0], \"direction\": "
     "[0, 1, 0]}, \"radius\": 1, \"height\": 1e151}]\n"
     "}\n",
     "bad.json:4:117: geometries[0].height: expected a length up to 1e+75, got 1e151"},
    // EP23: zero normal
    {"ZeroNormal",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 0, 0]}]\n"
     "}\n",
     "bad.json:4:66: geometries[0].normal: expected a non-zero vector [x,y,z], got [0,0,0]"},
    // EP24: a direction whose length overflows
    {"HugeDirection",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"tube\", \"axis\": {\"origin\": [0, 0, 0], \"direction\": "
     "[1e200, 0, 0]}, \"radius\": 1}]\n"
     "}\n",
     "bad.json:4:78: geometries[0].axis.direction: expected a vector [x,y,z] of finite length, got "
     "[1e200,0,0]"},
    // EP25: a plane given both by point and normal and by three points
    {"PlaneBothForms",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 0, 1], "
     "\"points\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]\n"
     "}\n",
     "bad.json:4:77: geometries[0].points: give either 'point' and 'normal' or 'points', not both"},
    // EP26: unknown material name close to a defined one
    {"UnknownMaterialSuggested",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"materials\": {\"glass\": {\"kT\": 0.5}, \"mirror\": {\"kR\": 1}}, \"geometries\": "
     "[{\"type\": \"sphere\", \"center\": [0, 0, -5], \"radius\": 1, \"material\": \"glas\"}]\n"
     "}\n",
     "bad.json:4:142: geometries[0].material: expected the name of a material in \"materials\" "
     "(glass, mirror), got \"glas\"; did you mean 'glass'?"},
    // EP27: material name when no material is defined
    {"UnknownMaterialNoneDefined",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -5], \"radius\": 1, "
     "\"material\": \"glass\"}]\n"
     "}\n",
     "bad.json:4:84: geometries[0].material: expected the name of a material in \"materials\" "
     "(none is defined), got \"glass\""},
    // EP28: unknown light type (the known ones listed)
    {"UnknownLightType",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"lights\": [{\"type\": \"sun\", \"intensity\": [1, 1, 1]}]\n"
     "}\n",
     "bad.json:4:23: lights[0].type: expected a light type (directional, point, spot), got "
     "\"sun\""},
    // EP46: a light type that contains a known one ("spotlight"): the suggester's containment
    // rule names it, though it is five edits away
    {"UnknownLightTypeContainingOne",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"lights\": [{\"type\": \"spotlight\", \"intensity\": [1, 1, 1]}]\n"
     "}\n",
     "bad.json:4:23: lights[0].type: expected a light type (directional, point, spot), got "
     "\"spotlight\"; did you mean 'spot'?"},
    // EP29: unknown geometry type (the known ones listed)
    {"UnknownGeometryType",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"box\"}]\n"
     "}\n",
     "bad.json:4:27: geometries[0].type: expected a geometry type (sphere, plane, triangle, "
     "polygon, tube, cylinder, mesh), got \"box\""},
    // EP30: misspelt geometry type
    {"UnknownGeometryTypeSuggested",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"sphre\"}]\n"
     "}\n",
     "bad.json:4:27: geometries[0].type: expected a geometry type (sphere, plane, triangle, "
     "polygon, tube, cylinder, mesh), got \"sphre\"; did you mean 'sphere'?"},
    // EP31: misspelt tracer
    {"UnknownTracer",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"tracer\": \"witted\"}\n"
     "}\n",
     "bad.json:4:24: render.tracer: expected a tracer (rays, normals, hits, ambient, phong, "
     "shadow, whitted, beams), got \"witted\"; did you mean 'whitted'?"},
    // EP32: resolution beyond 2^15 per side
    {"AbsurdResolution",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [100000, 10]},\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:3:47: camera.resolution[0]: expected an integer from 1 to 32768, got 100000"},
    // BV03: resolution 2^15 + 1
    {"ResolutionJustTooLarge",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 32769]},\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:3:51: camera.resolution[1]: expected an integer from 1 to 32768, got 32769"},
    // BV04: resolution 0
    {"ResolutionZero",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [0, 10]},\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:3:47: camera.resolution[0]: expected an integer from 1 to 32768, got 0"},
    // EP33: a fractional resolution
    {"ResolutionFraction",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10.5, 10]},\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:3:47: camera.resolution[0]: expected an integer from 1 to 32768, got 10.5"},
    // EP34: coefficient array of two numbers
    {"CoefficientWrongLength",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"materials\": {\"m\": {\"kT\": [0.5, 0.5]}}\n"
     "}\n",
     "bad.json:4:29: materials.m.kT: expected a coefficient (a number or [r,g,b]), got [0.5,0.5]"},
    // EP35: negative coefficient channel
    {"CoefficientNegative",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"materials\": {\"m\": {\"kD\": [0.5, -0.1, 0.5]}}\n"
     "}\n",
     "bad.json:4:35: materials.m.kD[1]: expected a number from 0 to 1e+12, got -0.1"},
    // EP36: fractional shininess
    {"ShininessFraction",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"materials\": {\"m\": {\"shininess\": 1.5}}\n"
     "}\n",
     "bad.json:4:36: materials.m.shininess: expected an integer from 0 to 2147483647, got 1.5"},
    // EP37: a material name that is not an identifier is quoted in the path
    {"QuotedMaterialName",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"materials\": {\"my glass\": {\"ior\": 0}}\n"
     "}\n",
     "bad.json:4:37: materials[\"my glass\"].ior: expected a positive number, got 0"},
    // EP38: an empty material name
    {"EmptyMaterialName",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"materials\": {\"\": {}}\n"
     "}\n",
     "bad.json:4:17: materials[\"\"]: a material's name must not be empty"},
    // EP39: camera with both a target and a direction
    {"CameraTargetAndTo",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"to\": [0, 0, -1], "
     "\"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:2:59: camera.to: give either 'target' or 'to', not both"},
    // EP40: camera direction without up
    {"CameraToWithoutUp",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"to\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:2:13: camera: missing required key 'up' (required with 'to')"},
    // EP41: camera to and up not orthogonal (the builder's message)
    {"CameraNotOrthogonal",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"to\": [0, 0, -1], \"up\": [0, 1, 1], "
     "\"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"name\": \"x\"\n"
     "}\n",
     "bad.json:2:13: camera: Camera::Builder::setDirection: vTo (0,0,-1) and vUp (0,1,1) must be "
     "orthogonal, their unit vectors' dot product is -0.7071067811865475"},
    // BV05: point light with kC 0
    {"LightKcZero",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"lights\": [{\"type\": \"point\", \"intensity\": [1, 1, 1], \"position\": [0, 0, 0], "
     "\"kC\": 0}]\n"
     "}\n",
     "bad.json:4:85: lights[0].kC: expected a number of at least 2^-40 (the course's zero), got 0"},
    // BV06: maxLevel 0
    {"MaxLevelZero",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"maxLevel\": 0}\n"
     "}\n",
     "bad.json:4:26: render.maxLevel: expected an integer from 1 to 1000, got 0"},
    // BV07: grid lines one pixel beyond the largest image side
    {"GridLinesBeyondTheImage",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"gridLines\": 32769}\n"
     "}\n",
     "bad.json:4:27: render.gridLines: expected an integer from 0 to 32768, got 32769"},
    // BV08: negative grid lines
    {"GridLinesNegative",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"gridLines\": -1}\n"
     "}\n",
     "bad.json:4:27: render.gridLines: expected an integer from 0 to 32768, got -1"},
    // EP47: a grid colour that is not a colour
    {"GridColorNotAColour",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"gridColor\": \"yellow\"}\n"
     "}\n",
     "bad.json:4:27: render.gridColor: expected a colour [r,g,b], got \"yellow\""},
    // EP42: minK above 1
    {"MinKAboveOne",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"minK\": 2}\n"
     "}\n",
     "bad.json:4:22: render.minK: expected a number from 0 to 1, got 2"},
    // EP43: nesting deeper than the limit
    {"TooDeep",
     "{\"name\": "
     "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]]]]"
     "]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]}",
     "bad.json:1:73: "
     "name[0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0]["
     "0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0][0]["
     "0][0][0]: nesting deeper than 64 levels; a scene file needs at most 6"},
    // EP44: the column counts characters, not bytes
    {"Utf8Column",
     "{\"name\": \"h\xc3\xa9"
     "llo \xe2\x98\xba"
     "\", \"x\": 1}",
     "bad.json:1:21: x: unknown key; expected one of: name, camera, views, background, ambient, "
     "lights, materials, geometries, render"},
    // EP45: a mesh with both forms, a model file and inline arrays (at the second form's key)
    {"MeshBothForms",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"a.obj\", \"vertices\": [[0, 0, 0], [1, "
     "0, 0], [0, 1, 0]]}]\n"
     "}\n",
     "bad.json:4:52: geometries[0].vertices: give either 'file' or 'vertices' and "
     "'triangles', not both"},
    // EP46: a mesh with neither form
    {"MeshNeitherForm",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"name\": \"m\"}]\n"
     "}\n",
     "bad.json:4:18: geometries[0]: missing required key 'file' (or give 'vertices' and "
     "'triangles')"},
    // EP47: an inline mesh without triangles
    {"MeshWithoutTriangles",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]\n"
     "}\n",
     "bad.json:4:18: geometries[0]: missing required key 'triangles' (required with "
     "'vertices')"},
    // EP48: triangles without vertices (at the key)
    {"MeshTrianglesWithoutVertices",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"triangles\": [[0, 1, 2]]}]\n"
     "}\n",
     "bad.json:4:35: geometries[0].triangles: 'triangles' index the mesh's 'vertices', which "
     "are not given"},
    // EP49: normals without vertices (at the key)
    {"MeshNormalsWithoutVertices",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"a.obj\", \"normals\": [[0, 0, 1]]}]\n"
     "}\n",
     "bad.json:4:52: geometries[0].normals: 'normals' are one per vertex of an inline mesh's "
     "'vertices', which are not given"},
    // BV07: a vertex index one past the last vertex
    {"MeshIndexOutOfRange",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
     "\"triangles\": [[0, 1, 3]]}]\n"
     "}\n",
     "bad.json:4:103: geometries[0].triangles[0][2]: expected a vertex index from 0 to 2 "
     "(the mesh has 3 vertices), got 3"},
    // BV08: a negative vertex index
    {"MeshNegativeIndex",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
     "\"triangles\": [[-1, 1, 2]]}]\n"
     "}\n",
     "bad.json:4:97: geometries[0].triangles[0][0]: expected a vertex index from 0 to 2 (the "
     "mesh has 3 vertices), got -1"},
    // EP50: an index that is not an integer
    {"MeshFractionalIndex",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
     "\"triangles\": [[0, 1.5, 2]]}]\n"
     "}\n",
     "bad.json:4:100: geometries[0].triangles[0][1]: expected a vertex index from 0 to 2 "
     "(the mesh has 3 vertices), got 1.5"},
    // BV09: an empty mesh: no vertices
    {"MeshNoVertices",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [], \"triangles\": [[0, 1, 2]]}]\n"
     "}\n",
     "bad.json:4:47: geometries[0].vertices: expected an array of at least 3 points [x,y,z], "
     "got []"},
    // BV10: an empty mesh: no triangles
    {"MeshNoTriangles",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
     "\"triangles\": []}]\n"
     "}\n",
     "bad.json:4:95: geometries[0].triangles: expected an array of at least one triangle "
     "[i,j,k] of vertex indices, got []"},
    // EP51: a triangle of two indices
    {"MeshTriangleOfTwo",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
     "\"triangles\": [[0, 1]]}]\n"
     "}\n",
     "bad.json:4:96: geometries[0].triangles[0]: expected a triangle [i,j,k] of vertex "
     "indices, got [0,1]"},
    // EP52: fewer normals than vertices
    {"MeshNormalsCount",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
     "\"triangles\": [[0, 1, 2]], \"normals\": [[0, 0, 1]]}]\n"
     "}\n",
     "bad.json:4:119: geometries[0].normals: expected an array of 3 normals [x,y,z], one per "
     "vertex, got [[0,0,1]]"},
    // EP53: a zero normal
    {"MeshZeroNormal",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
     "\"normals\": [[0, 0, 1], [0, 0, 0], [0, 0, 1]]}]\n"
     "}\n",
     "bad.json:4:105: geometries[0].normals[1]: expected a non-zero vector [x,y,z], got "
     "[0,0,0]"},
    // BV11: a scale of zero
    {"MeshZeroScale",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"a.obj\", \"scale\": 0}]\n"
     "}\n",
     "bad.json:4:61: geometries[0].scale: expected a scale: a non-zero number or [x,y,z] of "
     "non-zero numbers, got 0"},
    // BV12: a scale of zero on one axis
    {"MeshZeroScaleOnAnAxis",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"a.obj\", \"scale\": [1, 0, 1]}]\n"
     "}\n",
     "bad.json:4:61: geometries[0].scale: expected a scale: a non-zero number or [x,y,z] of "
     "non-zero numbers, got [1,0,1]"},
    // EP54: a rotation of two angles
    {"MeshRotationOfTwo",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"a.obj\", \"rotation\": [90, 0]}]\n"
     "}\n",
     "bad.json:4:64: geometries[0].rotation: expected a rotation [x,y,z] in degrees, got "
     "[90,0]"},
    // EP55: coordinates that the scale makes infinite (at the entry)
    {"MeshNotFiniteAfterScale",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1e75, 0, 0], [0, 1, 0]], "
     "\"triangles\": [[0, 1, 2]], \"scale\": 1e300}]\n"
     "}\n",
     "bad.json:4:18: geometries[0]: TriangleMesh: vertices[1] must be finite, got (inf,0,0)"},
    // EP56: every triangle of zero area
    {"MeshOnlyDegenerateTriangles",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [2, 0, 0]], "
     "\"triangles\": [[0, 1, 2], [0, 0, 1]]}]\n"
     "}\n",
     "bad.json:4:18: geometries[0]: TriangleMesh: every one of the 2 triangles has zero area "
     "(none is left)"},
    // EP57: an unknown shading
    {"MeshUnknownShading",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"a.obj\", \"shading\": \"phong\"}]\n"
     "}\n",
     "bad.json:4:63: geometries[0].shading: expected a shading (smooth, flat), got \"phong\""},
    // EP58: group materials for an inline mesh (at the key)
    {"MeshMaterialsInline",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
     "\"triangles\": [[0, 1, 2]], \"materials\": {}}]\n"
     "}\n",
     "bad.json:4:108: geometries[0].materials: 'materials' is for the material groups of a "
     "model file; an inline mesh is one group: give it 'material'"},
    // EP59: group materials that are not an object
    {"MeshMaterialsNotAnObject",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"a.obj\", \"materials\": \"glass\"}]\n"
     "}\n",
     "bad.json:4:65: geometries[0].materials: expected an object of the model file's "
     "material groups and their materials, got \"glass\""},
    // EP60: an empty model file path
    {"MeshEmptyFile",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"\"}]\n"
     "}\n",
     "bad.json:4:43: geometries[0].file: expected a model file's path, got \"\""},
    // EP61: a misspelt key of a mesh
    {"MeshMisspeltKey",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"geometries\": [{\"type\": \"mesh\", \"file\": \"a.obj\", \"normal\": [[0, 0, 1]]}]\n"
     "}\n",
     "bad.json:4:52: geometries[0].normal: unknown key; did you mean 'normals'?"},
    // EP62: light buffers given as a word, not a boolean
    {"LightBuffersNotABoolean",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"lightBuffers\": \"yes\"}\n"
     "}\n",
     "bad.json:4:30: render.lightBuffers: expected true or false, got \"yes\""},
    // EP63: light buffers given as a number (1 is no boolean in JSON)
    {"LightBuffersNumber",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"render\": {\"lightBuffers\": 1}\n"
     "}\n",
     "bad.json:4:30: render.lightBuffers: expected true or false, got 1"},
    // BV64: a colour beyond the files' largest, 10^12 (the render's sums would overflow towards
    // infinity, and meet a zero as NaN)
    {"ColourTooLarge",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"ambient\": {\"color\": [0, 1e308, 0]}\n"
     "}\n",
     "bad.json:4:28: ambient.color[1]: expected a number from 0 to 1e+12, got 1e308"},
    // BV65: a coefficient beyond it
    {"CoefficientTooLarge",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"materials\": {\"m\": {\"kT\": 1.5e12}}\n"
     "}\n",
     "bad.json:4:29: materials.m.kT: expected a number from 0 to 1e+12, got 1.5e12"},
    // BV66: a kC above 0 but below the course's zero, 2^-40 (the intensity at the light would be
    // beyond any double)
    {"LightKcBelowZeroThreshold",
     "{\n"
     "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
     "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
     "  \"lights\": [{\"type\": \"point\", \"intensity\": [1, 1, 1], \"position\": [0, 0, 0], "
     "\"kC\": 1e-320}]\n"
     "}\n",
     "bad.json:4:85: lights[0].kC: expected a number of at least 2^-40 (the course's zero), got "
     "1e-320"},
};

// gtest prints a case by its name.
void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, ReportsFileLineColumnPathAndExpectation) {
  const BadInput& c = GetParam();
  try {
    (void)parseScene(c.text, "bad.json");
    FAIL() << "accepted: " << c.text;
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), c.message);
  }
}

INSTANTIATE_TEST_SUITE_P(SceneFile, BadInputTest, ::testing::ValuesIn(BAD_INPUTS),
                         [](const ::testing::TestParamInfo<BadInput>& param) {
                           return std::string(param.param.name);
                         });

TEST(BadInputListTest, LongListsOfNamesAreCut) {
  // BV01: 20 materials defined: the message lists 12 and counts the rest.
  std::string materials;
  for (int i = 0; i < 20; ++i)
    materials +=
        std::string(i ? ", " : "") + "\"m" + (i < 10 ? "0" : "") + std::to_string(i) + "\": {}";
  const std::string text =
      "{\n"
      "  \"camera\": {\"location\": [0, 0, 0], \"target\": [0, 0, -1], \"vpDistance\": 1,\n"
      "             \"vpSize\": [1, 1], \"resolution\": [10, 10]},\n"
      "  \"materials\": {" +
      materials +
      "}, \"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, -5], \"radius\": 1, "
      "\"material\": \"glass\"}]\n"
      "}\n";
  try {
    (void)parseScene(text, "bad.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bad.json:4:319: geometries[0].material: expected the name of a material in "
              "\"materials\" (m00, m01, m02, m03, m04, m05, m06, m07, m08, m09, m10, m11 and 8 "
              "more), got \"glass\"");
  }
}

TEST(SceneErrorTest, CarriesThePartsOfItsMessage) {
  // EP01: an error with a position keeps file, line, column, path and detail apart.
  try {
    (void)parseScene("{\"camera\": 5}", "x.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file, "x.json");
    EXPECT_EQ(e.line, 1);
    EXPECT_EQ(e.column, 12);
    EXPECT_EQ(e.path, "camera");
    EXPECT_EQ(e.detail, "expected a camera object, got 5");
  }
}

TEST(SceneErrorTest, FormatsWithoutUnknownParts) {
  // EP01: no position: "FILE: PATH: DETAIL".
  EXPECT_EQ(SceneError::format("f.json", 0, 0, "camera", "d"), "f.json: camera: d");
  // EP02: a position and no path (the document itself).
  EXPECT_EQ(SceneError::format("f.json", 2, 5, "", "d"), "f.json:2:5: d");
  // EP03: everything.
  EXPECT_EQ(SceneError("f.json", 2, 5, "a.b", "d").what(), std::string("f.json:2:5: a.b: d"));
}

TEST(LoadSceneTest, FileErrors) {
  // EP01: a file that does not exist.
  try {
    (void)loadScene("/nonexistent/scene.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot read /nonexistent/scene.json: No such file or directory");
  }
  // EP02: a directory.
  try {
    (void)loadScene("/");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read /: it is a directory");
  }
}

TEST(LoadSceneTest, ContentErrorsNameThePath) {
  // EP01: a readable file with a bad value: the message starts with the path given.
  const std::string path = std::string(RT_SCENEFILE_DATA_DIR) + "/bad-radius.json";
  try {
    (void)loadScene(path);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ":14:16: geometries[3].radius: expected a positive number, got -2");
  }
}

}  // namespace
}  // namespace rt
