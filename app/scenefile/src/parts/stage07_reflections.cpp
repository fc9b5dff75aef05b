// The scene format's stage-7 part: the Whitted tracer's recursion limits.
#include "../Format.h"
#include "../Writers.h"
#include "reflections/WhittedTracer.h"

namespace rt::scenefile {

void registerFormat_stage07_reflections(SceneFormat& format) {
  using R = RenderSettings;
  format.attach<R>("render", "maxLevel", [](const Node& n, R& r) {
    r.maxLevel = readInteger(n, 1, WhittedSettings::MAX_LEVEL_LIMIT);
  });
  format.attach<R>("render", "minK", [](const Node& n, R& r) { r.minK = readNumberIn(n, 0, 1); });
  format.addTracer("whitted");
  format.writeDocument.push_back([](const SceneDocument& doc, Json& j) {
    Json& render = j["render"];
    render["maxLevel"] = doc.render.maxLevel;
    render["minK"] = jsonNumber(doc.render.minK);
  });
}

}  // namespace rt::scenefile
