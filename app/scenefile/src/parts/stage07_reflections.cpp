// The scene format's stage-7 part: the Whitted tracer's recursion limits, and a warning for glass
// shapes whose faces are wound both ways (refraction needs outward normals; the analysis is
// stage 7's, reflections/GlassWinding.h).
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../Format.h"
#include "../Writers.h"
#include "reflections/GlassWinding.h"
#include "reflections/WhittedTracer.h"
#include "scenefile/LitDocument.h"

namespace rt::scenefile {

namespace {

/// "geometries[4] ('lid'), geometries[5]", at most six, then "and N more": the shapes by their
/// elements in the file (elementOf, see ShapeElements).
std::string geometryList(const SceneDocument& doc, const std::vector<std::uint32_t>& indices,
                         const std::vector<std::uint32_t>& elementOf) {
  constexpr std::size_t LISTED = 6;
  std::string out;
  for (std::size_t k = 0; k < indices.size() && k < LISTED; ++k) {
    if (k) out += ", ";
    out += "geometries[" + std::to_string(elementOf.at(indices[k])) + "]";
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

/// The warnings for glass wound both ways (see reflections/GlassWinding.h), each at its first
/// face to reverse.
void warnOfMixedWinding(const Node& root) {
  SceneDocument& doc = root.context().doc;
  std::map<std::uint32_t, std::string> warnings;  // by the element of the first face to reverse
  const std::vector<std::uint32_t>& elementOf = root.context().state<ShapeElements>().elementOf;
  for (const WindingProblem& s : glassWindingProblems(litScene(doc))) {
    const std::size_t n = s.reverse.size() + s.keep.size();
    const bool one = s.reverse.size() == 1;
    std::string detail =
        "mixed winding in " + std::string(s.closed ? "a closed glass shape" : "a glass surface") +
        " of " + std::to_string(n) + " faces (" + materialText(doc, s.reverse.front()) + "): ";
    if (s.closed) {
      detail += "the normal" + std::string(one ? " of " : "s of ") +
                geometryList(doc, s.reverse, elementOf) + (one ? " points" : " point") +
                " inwards, those of " + geometryList(doc, s.keep, elementOf) + " outwards";
    } else {
      detail += geometryList(doc, s.reverse, elementOf) + (one ? " is" : " are") +
                " wound against " + geometryList(doc, s.keep, elementOf);
    }
    detail +=
        " (an edge shared by two faces runs the same way in both); refraction needs outward "
        "normals: reverse the order of the vertices of " +
        std::string(s.closed ? (one ? "that face" : "those faces") : "one side");
    warnings.emplace(elementOf.at(s.reverse.front()), std::move(detail));
  }
  if (warnings.empty() || !root.find("geometries")) return;
  // Each warning at its first face's place in the file.
  std::uint32_t element = 0;
  root.member("geometries").forEachElement([&](const Node& g) {
    if (const auto it = warnings.find(element++); it != warnings.end())
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
