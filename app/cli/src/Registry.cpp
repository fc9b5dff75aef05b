#include "cli/Registry.h"

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef RT_COURSE_STAGES
#error "RT_COURSE_STAGES must be defined (the root CMakeLists.txt's RT_STAGES, comma-separated)"
#endif

namespace rt::cli {

void registerCli(CliRegistry& registry);  // generated: one call per stage present

int courseStageRank(std::string_view stage) {
  // The course's stages in order, as CMake lists them: "stage01_primitives,...,mini2_bvh".
  std::string_view stages = RT_COURSE_STAGES;
  for (int rank = 0; !stages.empty(); ++rank) {
    const std::size_t comma = stages.find(',');
    if (stages.substr(0, comma) == stage) return rank;
    stages = comma == std::string_view::npos ? std::string_view() : stages.substr(comma + 1);
  }
  throw std::logic_error("the registry: '" + std::string(stage) +
                         "' is not a stage of the course (" RT_COURSE_STAGES ")");
}

const CliRegistry& cliRegistry() {
  static const CliRegistry registry = [] {
    CliRegistry r;
    registerCli(r);
    std::set<std::string_view> names;
    for (const BuiltinScene& s : r.scenes)
      if (!names.insert(s.name).second)
        throw std::logic_error("built-in scenes: the name '" + s.name + "' is used twice");
    return r;
  }();
  return registry;
}

}  // namespace rt::cli
