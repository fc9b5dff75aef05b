#include "cli/BuiltinScenes.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/CommandLine.h"
#include "common/NearestName.h"

namespace rt::cli {

std::span<const BuiltinScene> builtinScenes() { return cliRegistry().scenes; }

const BuiltinScene* findBuiltinScene(std::string_view name) {
  for (const BuiltinScene& s : builtinScenes())
    if (s.name == name) return &s;
  return nullptr;
}

SceneDocument makeBuiltinScene(const BuiltinScene& scene, std::span<const std::string> params) {
  std::vector<std::string_view> known;
  for (const SceneParam& p : scene.params) known.push_back(p.name);
  SceneParams values;
  for (const std::string& given : params) {
    const std::size_t eq = given.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--param: expected NAME=VALUE, got '" + given + "'");
    const std::string name = given.substr(0, eq);
    if (known.empty())
      throw UsageError("--param: the scene '" + scene.name + "' has no parameters, got '" + given +
                       "'");
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      const std::string list = joinNames(known);
      throw UsageError("--param: the scene '" + scene.name + "' has no parameter '" + name + "'" +
                       didYouMean(name, known) + " (its parameters: " + list + ")");
    }
    if (!values.emplace(name, given.substr(eq + 1)).second)
      throw UsageError("--param: '" + name + "' is given twice");
  }
  for (const SceneParam& p : scene.params) values.emplace(p.name, p.defaultValue);
  try {
    return scene.make(values);
  } catch (const std::invalid_argument& e) {
    // The scene's own checks refused what the parameters asked for (arms x perArm beyond the
    // galaxy's stars, a teapot floor too large for its triangles): the defaults make every scene,
    // so the values given are the cause; say which.
    if (params.empty()) throw;
    std::string given;
    for (const std::string& p : params) given += (given.empty() ? "--param " : " --param ") + p;
    throw UsageError(given + ": " + e.what());
  }
}

}  // namespace rt::cli
