#include "Format.h"

#include <algorithm>

namespace rt::scenefile {

void registerFormat(SceneFormat& registry);  // generated: one call per stage present

std::vector<std::string_view> SceneFormat::tracers() const {
  std::vector<std::string_view> names;
  for (const CatalogueTracer& t : tracerCatalogue())
    if (std::find(tracers_.begin(), tracers_.end(), t.name) != tracers_.end())
      names.push_back(t.name);
  return names;
}

const SceneFormat& sceneFormat() {
  static const SceneFormat format = [] {
    SceneFormat f;
    registerFormat(f);
    return f;
  }();
  return format;
}

std::vector<AbsentKey> absentTypes(std::string_view object,
                                   std::span<const std::string_view> present) {
  std::vector<AbsentKey> absent;
  const std::string prefix = std::string(object) + " ";
  for (const CatalogueKey& k : keyCatalogue()) {
    if (!k.object.starts_with(prefix)) continue;
    const std::string_view type = k.object.substr(prefix.size());
    const bool isPresent = std::find(present.begin(), present.end(), type) != present.end();
    const bool isListed = std::any_of(absent.begin(), absent.end(),
                                      [&](const AbsentKey& a) { return a.name == type; });
    if (!isPresent && !isListed) absent.push_back({type, k.stage});
  }
  return absent;
}

void orderKeys(Json& j, std::initializer_list<std::string_view> objects) {
  if (!j.is_object()) return;
  std::vector<std::string_view> order{"type"};
  for (std::string_view object : objects)
    for (const CatalogueKey& k : keyCatalogue())
      if (k.object == object) order.push_back(k.key);
  const auto rank = [&](const std::string& key) {
    const auto it = std::find(order.begin(), order.end(), key);
    return static_cast<std::size_t>(it - order.begin());
  };
  Json sorted = Json::object();
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  std::stable_sort(keys.begin(), keys.end(),
                   [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  for (const std::string& k : keys) sorted[k] = std::move(j[k]);
  j = std::move(sorted);
}

}  // namespace rt::scenefile
