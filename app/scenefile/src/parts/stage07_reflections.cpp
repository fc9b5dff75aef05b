// The scene format's stage-7 part: the Whitted tracer's recursion limits, and a warning for glass
// shapes whose faces are wound both ways (refraction needs outward normals).
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../Format.h"
#include "../Writers.h"
#include "primitives/Overloaded.h"
#include "reflections/WhittedTracer.h"
#include "scenefile/LitDocument.h"

namespace rt::scenefile {

namespace {

/*
 * Glass made of polygons and triangles: the winding check.
 *
 * Refraction asks the surface's normal whether a ray enters the glass (the ray against the
 * normal: η = 1/ior) or leaves it (η = ior). A polygon's normal follows its winding (right-hand
 * rule), so the faces of a glass shape must all be wound counter-clockwise seen from outside;
 * a face wound the other way refracts as if the glass were outside it. Two faces of a
 * consistently wound surface run along the edge they share in opposite directions; when they
 * run along it in the same direction, one of them is reversed.
 *
 * The faces checked are the polygons and triangles whose material refracts with an index other
 * than 1 (ior ≠ 1 and kT not zero: without transparency the index changes nothing), grouped by
 * appearance (the same material; a different emission makes another group). Within a group, an
 * edge (two vertices, equal bit for bit) shared by exactly two faces links them; each connected
 * set of faces is split into two classes by its links: same class when the shared edge runs in
 * opposite directions. One class is a consistent surface; two classes are mixed winding. For a
 * closed surface (every edge shared by two faces) the signed volume says which class points
 * outwards, with the other class reversed: V = Σ p0·(pk × pk+1)/6 over each face's fan, positive
 * for outward normals. For an open surface the smaller class is named (the first face's class
 * on a tie).
 */

using Vertex = std::array<double, 3>;

Vertex vertexOf(const Point& p) { return {p.xyz().x, p.xyz().y, p.xyz().z}; }

/// The corners of a polygon or triangle; empty for another shape.
std::vector<Point> facePoints(const Geometry& g) {
  return std::visit(Overloaded{
                        [](const Triangle& t) {
                          return std::vector<Point>(t.vertices().begin(), t.vertices().end());
                        },
                        [](const Polygon& p) { return p.vertices(); },
                        [](const auto&) { return std::vector<Point>(); },
                    },
                    g);
}

/// One face's use of an edge: which face, and whether it runs from the smaller vertex.
struct EdgeUse {
  std::size_t face;
  bool forward;
};

/// A connected set of faces with mixed winding: the geometries to reverse and the others.
struct MixedSurface {
  std::vector<std::uint32_t> reverse, keep;
  bool closed = false;
};

/// The mixed surfaces among faces (geometry indices, one material).
std::vector<MixedSurface> mixedSurfaces(const Geometries& shapes,
                                        const std::vector<std::uint32_t>& faces) {
  std::vector<std::vector<Point>> points;
  std::map<std::pair<Vertex, Vertex>, std::vector<EdgeUse>> edges;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    points.push_back(facePoints(shapes[faces[f]]));
    const std::vector<Point>& p = points.back();
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Vertex a = vertexOf(p[k]), b = vertexOf(p[(k + 1) % p.size()]);
      edges[a < b ? std::pair{a, b} : std::pair{b, a}].push_back({f, a < b});
    }
  }
  // Links between faces: flip = the shared edge runs the same way in both.
  struct Link {
    std::size_t other;
    bool flip;
  };
  std::vector<std::vector<Link>> links(faces.size());
  std::vector<bool> open(faces.size(), false);
  for (const auto& [edge, uses] : edges) {
    if (uses.size() != 2 || uses[0].face == uses[1].face) {
      for (const EdgeUse& u : uses) open[u.face] = true;
      continue;
    }
    const bool flip = uses[0].forward == uses[1].forward;
    links[uses[0].face].push_back({uses[1].face, flip});
    links[uses[1].face].push_back({uses[0].face, flip});
  }
  std::vector<MixedSurface> out;
  std::vector<int> side(faces.size(), -1);  // 0 or 1 once visited
  for (std::size_t start = 0; start < faces.size(); ++start) {
    if (side[start] >= 0) continue;
    std::vector<std::size_t> component{start};
    side[start] = 0;
    for (std::size_t next = 0; next < component.size(); ++next)
      for (const Link& l : links[component[next]])
        if (side[l.other] < 0) {
          side[l.other] = side[component[next]] ^ static_cast<int>(l.flip);
          component.push_back(l.other);
        }
    std::array<std::vector<std::size_t>, 2> classes;
    bool closed = true;
    double volume = 0;  // six times the signed volume, the second class reversed
    for (const std::size_t f : component) {
      classes[side[f]].push_back(f);
      closed = closed && !open[f];
      const std::vector<Point>& p = points[f];
      double v = 0;
      for (std::size_t k = 1; k + 1 < p.size(); ++k)
        v += p[0].xyz().dot(p[k].xyz().cross(p[k + 1].xyz()));
      volume += side[f] == 0 ? v : -v;
    }
    if (classes[1].empty()) continue;  // consistent
    // Which class to reverse: the inward one of a closed surface, else the smaller one.
    const int wrong = closed && volume != 0 ? (volume > 0 ? 1 : 0)
                                            : (classes[1].size() <= classes[0].size() ? 1 : 0);
    MixedSurface s;
    s.closed = closed;
    for (const std::size_t f : classes[wrong]) s.reverse.push_back(faces[f]);
    for (const std::size_t f : classes[1 - wrong]) s.keep.push_back(faces[f]);
    std::sort(s.reverse.begin(), s.reverse.end());
    std::sort(s.keep.begin(), s.keep.end());
    out.push_back(std::move(s));
  }
  return out;
}

/// "geometries[4] ('lid'), geometries[5]", at most six, then "and N more".
std::string geometryList(const SceneDocument& doc, const std::vector<std::uint32_t>& indices) {
  constexpr std::size_t LISTED = 6;
  std::string out;
  for (std::size_t k = 0; k < indices.size() && k < LISTED; ++k) {
    if (k) out += ", ";
    out += "geometries[" + std::to_string(indices[k]) + "]";
    if (const std::string* name = doc.geometryName(indices[k])) out += " ('" + *name + "')";
  }
  if (indices.size() > LISTED) out += " and " + std::to_string(indices.size() - LISTED) + " more";
  return out;
}

std::string materialText(const SceneDocument& doc, std::uint32_t geometry) {
  std::ostringstream os;
  if (const std::string* name = materialNameOf(doc, geometry))
    os << "material '" << *name << "'";
  else
    os << "an inline material";
  os << ", ior " << litScene(doc).appearanceOf(geometry).material.ior;
  return os.str();
}

void warnOfMixedWinding(const Node& root) {
  SceneDocument& doc = root.context().doc;
  const LitScene& scene = litScene(doc);
  const Geometries& shapes = scene.geometries;
  std::map<std::uint32_t, std::vector<std::uint32_t>> facesByLook;
  for (std::uint32_t i = 0; i < shapes.size(); ++i) {
    const Material& m = scene.appearanceOf(i).material;
    const bool refracts = m.ior != 1 && !m.kT.isExactlyZero();
    if (refracts && !facePoints(shapes[i]).empty())
      facesByLook[scene.appearanceIndex[i]].push_back(i);
  }
  std::map<std::uint32_t, std::string> warnings;  // by the first face to reverse
  for (const auto& [look, faces] : facesByLook)
    for (const MixedSurface& s : mixedSurfaces(shapes, faces)) {
      const std::size_t n = s.reverse.size() + s.keep.size();
      const bool one = s.reverse.size() == 1;
      std::string detail =
          "mixed winding in " + std::string(s.closed ? "a closed glass shape" : "a glass surface") +
          " of " + std::to_string(n) + " faces (" + materialText(doc, s.reverse.front()) + "): ";
      if (s.closed) {
        detail += "the normal" + std::string(one ? " of " : "s of ") +
                  geometryList(doc, s.reverse) + (one ? " points" : " point") +
                  " inwards, those of " + geometryList(doc, s.keep) + " outwards";
      } else {
        detail += geometryList(doc, s.reverse) + (one ? " is" : " are") + " wound against " +
                  geometryList(doc, s.keep);
      }
      detail +=
          " (an edge shared by two faces runs the same way in both); refraction needs outward "
          "normals: reverse the order of the vertices of " +
          std::string(s.closed ? (one ? "that face" : "those faces") : "one side");
      warnings.emplace(s.reverse.front(), std::move(detail));
    }
  if (warnings.empty() || !root.find("geometries")) return;
  // Each warning at its first face's place in the file (the i-th element is geometry i).
  std::uint32_t i = 0;
  root.member("geometries").forEachElement([&](const Node& g) {
    if (const auto it = warnings.find(i++); it != warnings.end())
      doc.warnings.push_back(g.message(it->second));
  });
}

}  // namespace

void registerFormat_stage07_reflections(SceneFormat& format) {
  using R = RenderSettings;
  format.attach<R>("render", "maxLevel", [](const Node& n, R& r) {
    r.maxLevel = readInteger(n, 1, WhittedSettings::MAX_LEVEL_LIMIT);
  });
  format.attach<R>("render", "minK", [](const Node& n, R& r) { r.minK = readNumberIn(n, 0, 1); });
  format.addTracer("whitted");
  format.checkRead.push_back(warnOfMixedWinding);
  format.writeDocument.push_back([](const SceneDocument& doc, Json& j) {
    Json& render = j["render"];
    render["maxLevel"] = doc.render.maxLevel;
    render["minK"] = jsonNumber(doc.render.minK);
  });
}

}  // namespace rt::scenefile
