// rt probe SCENE (--ray OX,OY,OZ DX,DY,DZ | --pixel X,Y): one ray, what it hits, what it sees.
#include <cmath>
#include <ostream>
#include <sstream>

#include "CommandTable.h"
#include "camera/Camera.h"
#include "cli/Tracers.h"
#include "cli/Values.h"
#include "geometries/Geometry.h"

namespace rt::cli {

namespace {

/// A JSON number: the shortest form that reads back to the same double; null if not finite.
std::string number(double v) { return std::isfinite(v) ? formatNumber(v) : "null"; }

std::string triple(const Double3& v) {
  return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

std::string jsonString(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

int probe(const ParsedArgs& args, const Io& io) {
  const bool byRay = args.has("--ray"), byPixel = args.has("--pixel");
  if (byRay == byPixel)
    throw UsageError(std::string(byRay ? "give only one of" : "missing") +
                     " --ray OX,OY,OZ DX,DY,DZ or --pixel X,Y (see rt probe --help)");
  SceneDocument doc = loadSceneArgument(args.positional[0]);
  applySceneOverrides(args, doc);

  std::optional<Ray> ray;
  if (byRay) {
    const std::vector<std::string>& v = *args.values("--ray");
    const Double3 origin = parseTriple(v[0], "--ray origin");
    const Double3 direction = parseTriple(v[1], "--ray direction");
    if (direction.isZero())
      throw UsageError("--ray direction: must not be the zero vector, got '" + v[1] + "'");
    ray.emplace(Point(origin), Vector(direction));
  } else {
    const int nX = doc.camera.nX, nY = doc.camera.nY;
    const auto [x, y] = parseIntPair(*args.value("--pixel"), "--pixel", nX - 1, nY - 1);
    // constructRay takes the grid as arguments: a 1x1 camera spares the nX x nY image.
    ray = doc.camera.builder().setResolution(1, 1).build().constructRay(nX, nY, x, y);
  }
  const std::unique_ptr<RayTracer> tracer = findTracer(doc.render.tracer).make(doc);
  io.out << probeJson(doc, *ray, *tracer);
  return EXIT_OK;
}

}  // namespace

std::string probeJson(const SceneDocument& doc, const Ray& ray, const RayTracer& tracer) {
  std::ostringstream os;
  os << "{\n  \"ray\": {\"origin\": " << triple(ray.head().xyz())
     << ", \"direction\": " << triple(ray.direction().xyz()) << "},\n  \"hits\": [";
  const Geometries& shapes = doc.scene.geometries;
  const std::vector<GeoPoint> hits = shapes.findGeoIntersections(ray);
  for (std::size_t k = 0; k < hits.size(); ++k) {
    const GeoPoint& h = hits[k];
    const std::string* name = doc.geometryName(h.geometry);
    os << (k == 0 ? "\n" : ",\n") << "    {\"t\": " << number(h.t)
       << ", \"point\": " << triple(h.point.xyz())
       << ", \"normal\": " << triple(normalAt(shapes[h.geometry], h.point).xyz())
       << ", \"geometry\": " << h.geometry << ", \"name\": " << (name ? jsonString(*name) : "null")
       << "}";
  }
  os << (hits.empty() ? "" : "\n  ") << "],\n  \"color\": " << triple(tracer.traceRay(ray).rgb())
     << "\n}\n";
  return os.str();
}

Command probeCommand() {
  return {{"probe",
           "trace one ray through a scene and print what it hits, as JSON",
           {"SCENE"},
           {{"--ray", "", 2, "OX,OY,OZ DX,DY,DZ", "the ray's origin and direction"},
            {"--pixel", "", 1, "X,Y", "the camera's ray through pixel X (column), Y (row)"},
            {"--width", "", 1, "W", "image width for --pixel (default: the scene's)"},
            {"--height", "", 1, "H", "image height for --pixel (default: the scene's)"},
            {"--tracer", "", 1, "T", "the tracer that computes color (default: the scene's)"}},
           "Give exactly one of --ray and --pixel. Numbers may be negative and are separated by\n"
           "commas without spaces: rt probe two-color --ray -1,0.5,-2 0,0,1\n\n"
           "Output:\n"
           "  {\"ray\": {\"origin\": [x, y, z], \"direction\": [x, y, z]},\n"
           "   \"hits\": [{\"t\": .., \"point\": [..], \"normal\": [..], \"geometry\": INDEX,\n"
           "             \"name\": NAME or null}, ..],\n"
           "   \"color\": [r, g, b]}\n"
           "hits: every intersection with t > 0, nearest first (the course's\n"
           "findGeoIntersections); normal: the shape's outward unit normal at the point;\n"
           "geometry: the shape's index in the scene; color: what the tracer returns for the\n"
           "ray, unclamped, on the 0-255 scale.\n"},
          probe};
}

}  // namespace rt::cli
