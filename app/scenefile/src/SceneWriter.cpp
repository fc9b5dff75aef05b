// Writing a SceneDocument as a scene file that reads back to the same document, bit for bit:
// every part of the format present writes its keys, which are then put in the documented order.
#include "Format.h"
#include "common/JsonText.h"
#include "scenefile/SceneFile.h"

namespace rt {

nlohmann::ordered_json toJson(const SceneDocument& doc, const std::filesystem::path& folder) {
  using scenefile::orderKeys;
  if (!doc.scene) throw std::logic_error("toJson: the document has no scene");
  const scenefile::SceneFormat& format = scenefile::sceneFormat();
  for (const auto& check : format.checkDocument) check(doc);
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& write : format.writeDocument) write(doc, j);
  for (const auto& write : format.writeMoreGeometries) write(doc, folder, j["geometries"]);
  orderKeys(j, {"document"});
  orderKeys(j["camera"], {"camera"});
  if (j.contains("views"))
    for (auto& [name, view] : j["views"].items()) orderKeys(view, {"camera"});
  orderKeys(j["render"], {"render"});
  return j;
}

std::string dumpScene(const SceneDocument& doc, const std::filesystem::path& folder) {
  return formatJson(toJson(doc, folder));
}

}  // namespace rt
