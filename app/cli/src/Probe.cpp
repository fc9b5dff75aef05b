// rt probe SCENE (--ray OX,OY,OZ DX,DY,DZ | --pixel X,Y): one ray, what it hits, what it sees.
#include <algorithm>
#include <cmath>
#include <optional>
#include <ostream>
#include <utility>

#include <CLI/App.hpp>

#include "CommandRegistration.h"
#include "camera/Camera.h"
#include "cli/Registry.h"
#include "cli/RenderRequest.h"
#include "cli/Tracers.h"
#include "cli/Values.h"
#include "common/JsonText.h"
#include "intersections/Geometries.h"
#include "intersections/Primitives.h"
#include "scenefile/MeshDocument.h"
#include "scenefile/SceneFile.h"

namespace rt::cli {

namespace {

/// rt probe's arguments, as the command line binds them.
struct ProbeArgs {
  SceneArguments scene;
  std::optional<std::pair<std::string, std::string>> ray;  ///< origin, direction
  std::optional<std::string> pixel;
};

int probe(const ProbeArgs& args, const Io& io) {
  const bool byRay = args.ray.has_value(), byPixel = args.pixel.has_value();
  if (byRay == byPixel)
    throw UsageError(std::string(byRay ? "give only one of" : "missing") +
                     " --ray OX,OY,OZ DX,DY,DZ or --pixel X,Y (see rt probe --help)");
  // A pixel's colour needs the camera's image (its size is checked); a ray's does not.
  const RenderRequest request =
      resolveRenderRequest(args.scene, {.makesImage = byPixel, .renders = false});
  for (const std::string& w : request.warnings) io.err << "rt: " << w << "\n";
  const SceneDocument& doc = request.doc;
  std::optional<Ray> ray;
  Color color;
  if (byRay) {
    const auto& [originText, directionText] = *args.ray;
    const Double3 origin = parseTriple(originText, "--ray origin");
    // As a scene file's points: farther, the shapes' solvers overflow and the ray hits nothing.
    if (!(std::max({std::abs(origin.x), std::abs(origin.y), std::abs(origin.z)}) <= MAX_COORDINATE))
      throw UsageError("--ray origin: expected coordinates from -" + formatNumber(MAX_COORDINATE) +
                       " to " + formatNumber(MAX_COORDINATE) + ", got '" + originText + "'");
    const Double3 direction = parseTriple(directionText, "--ray direction");
    if (direction.isZero())
      throw UsageError("--ray direction: must not be the zero vector, got '" + directionText + "'");
    ray.emplace(Point(origin), Vector(direction));
    color = request.buildTracer().tracer->traceRay(*ray);
  } else {
    const int nX = doc.camera.nX, nY = doc.camera.nY;
    const auto [x, y] = parseIntPair(*args.pixel, "--pixel", nX - 1, nY - 1);
    const RenderSetup setup = request.build();
    const Camera& camera = setup.camera;
    // The hits are those of the ray through the pixel's centre; the colour is the pixel's, as a
    // render computes it (every sample of the render's sampler): the same bits as in the image.
    ray = camera.ray(x + 0.5, y + 0.5);
    RayCounts counts;
    color = setup.sampler->pixelColor(camera, *setup.tracer, x, y, counts);
  }
  io.out << probeJson(doc, *ray, color);
  return EXIT_OK;
}

}  // namespace

std::string probeJson(const SceneDocument& doc, const Ray& ray, const Color& color) {
  using Json = nlohmann::ordered_json;
  const Geometries& geometries = doc.scene->geometries;
  const Primitives primitives = geometries.primitives();
  Json hits = Json::array();
  for (const GeoPoint& h : geometries.findGeoIntersections(ray)) {
    Json hit = {{"t", jsonNumber(h.t)},
                {"point", jsonTriple(h.point.xyz())},
                {"normal", jsonTriple(geometries.normalAt(h.geometry, h.point).xyz())},
                {"geometry", h.geometry}};
    const std::string* name = nullptr;
    if (primitives.isShape(h.geometry)) {
      name = doc.geometryName(h.geometry);
    } else {
      // A mesh triangle: which mesh, and which of its triangles (the mesh's own numbering, as
      // its file or its vertices and triangles list them, less the dropped ones).
      const MeshTriangle m = primitives.meshTriangle(h.geometry);
      hit["mesh"] = m.mesh;
      hit["triangle"] = m.triangle;
      name = meshName(doc, m.mesh);
    }
    hit["name"] = name ? Json(*name) : Json(nullptr);
    hits.push_back(std::move(hit));
  }
  const Json answer = {{"ray",
                        {{"origin", jsonTriple(ray.head().xyz())},
                         {"direction", jsonTriple(ray.direction().xyz())}}},
                       {"hits", std::move(hits)},
                       {"color", jsonTriple(color.rgb())}};
  // The scene files' layout: one member per line, a hit per line, numbers in their shortest
  // round-trip form.
  return formatJson(answer);
}

void addProbeCommand(CommandLine& rt) {
  const auto [command, args] = rt.addCommand(
      "probe", "trace one ray through a scene and print what it hits, as JSON",
      "Give exactly one of --ray and --pixel. Numbers may be negative and are separated by\n"
      "commas without spaces: rt probe two-color --ray -1,0.5,-2 0,0,1\n"
      "--view, --width, --height and --seed are refused with --ray: its ray meets no camera\n"
      "and is traced once, as sample 0 with seed 0. The ray, or the pixel's samples, are\n"
      "traced on this thread: probe takes no --threads.\n\n"
      "Output:\n"
      "  {\"ray\": {\"origin\": [x, y, z], \"direction\": [x, y, z]},\n"
      "   \"hits\": [{\"t\": .., \"point\": [..], \"normal\": [..], \"geometry\": INDEX,\n"
      "             \"name\": NAME or null}, ..],\n"
      "   \"color\": [r, g, b]}\n"
      "hits: every intersection with t > 0, nearest first (the course's\n"
      "findGeoIntersections); normal: the shape's outward unit normal at the point (a\n"
      "mesh's shading normal, interpolated when it is smooth); geometry: the shape's\n"
      "index among the scene's shapes that are not meshes (its place in a scene file's\n"
      "geometries when no mesh comes before it), or for a triangle of a mesh the number\n"
      "of those shapes plus its number among the meshes' triangles, with \"mesh\": M,\n"
      "\"triangle\": T before the name (the mesh's); color: what the tracer returns for\n"
      "the ray, unclamped, on the 0-255 scale.\n",
      probe);
  // The values are checked by probe(): a pixel's range depends on the scene's resolution.
  CLI::Option* ray = addOptional(*command, "--ray", args->ray, "the ray's origin and direction",
                                 "OX,OY,OZ DX,DY,DZ");
  addOptional(*command, "--pixel", args->pixel,
              "the camera's ray through pixel X (column), Y (row)", "X,Y");
  addSceneArguments(*command, args->scene, "image width for --pixel (default: the scene's)",
                    "image height for --pixel (default: the scene's)",
                    "the tracer that computes color (default: the scene's)");
  // One ray, or one pixel's samples, is traced on this thread: the render's threads (the
  // scene option of mini project 2 on) would change nothing, so probe does not take them.
  if (CLI::Option* threads = command->get_option_no_throw("--threads"))
    command->remove_option(threads);
  // A ray given directly has no camera, image or pixel, and its colour is the tracer's for one
  // sample (RayTracer::traceRay(ray): seed 0): the options that choose the camera (--view), its
  // image's size or the samples' seed would change nothing. The tracer, the scene's parameters
  // and the acceleration do.
  for (const char* name : {"--view", "--width", "--height", "--seed"})
    ray->excludes(command->get_option(name));
}

}  // namespace rt::cli
