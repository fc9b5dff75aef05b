#include "reflections/GlassWinding.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <variant>

#include "primitives/Overloaded.h"

namespace rt {

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
 * for outward normals. For an open surface the smaller class is named (on a tie, the class
 * without the surface's first face).
 */

namespace {

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

/// The mixed surfaces among faces (geometry indices, one appearance), appended to out.
void mixedSurfaces(const Geometries& shapes, const std::vector<std::uint32_t>& faces,
                   std::vector<WindingProblem>& out) {
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
    WindingProblem s;
    s.closed = closed;
    for (const std::size_t f : classes[wrong]) s.reverse.push_back(faces[f]);
    for (const std::size_t f : classes[1 - wrong]) s.keep.push_back(faces[f]);
    std::sort(s.reverse.begin(), s.reverse.end());
    std::sort(s.keep.begin(), s.keep.end());
    out.push_back(std::move(s));
  }
}

}  // namespace

std::vector<WindingProblem> glassWindingProblems(const LitScene& scene) {
  const Geometries& shapes = scene.geometries;
  std::map<std::uint32_t, std::vector<std::uint32_t>> facesByLook;
  for (std::uint32_t i = 0; i < shapes.size(); ++i) {
    const Material& m = scene.appearanceOf(i).material;
    const bool refracts = m.ior != 1 && !m.kT.isExactlyZero();
    const bool face =
        std::holds_alternative<Triangle>(shapes[i]) || std::holds_alternative<Polygon>(shapes[i]);
    if (refracts && face) facesByLook[scene.appearanceIndex[i]].push_back(i);
  }
  std::vector<WindingProblem> out;
  for (const auto& [look, faces] : facesByLook) mixedSurfaces(shapes, faces, out);
  std::sort(out.begin(), out.end(), [](const WindingProblem& a, const WindingProblem& b) {
    return a.reverse.front() < b.reverse.front();
  });
  return out;
}

}  // namespace rt
