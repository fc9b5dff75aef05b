#include "glossy/DemoTable.h"

#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "glossy/DemoScenes.h"

namespace rt {

DemoSetup DemoScene::build() const {
  SceneSetup<LitScene> s = course.make();
  return {std::move(s.scene), s.camera, sampling};
}

std::span<const DemoScene> demoScenes() {
  // Each scene with its parameters' defaults.
  static const std::vector<DemoScene> table{
      {{"glossy-spheres",
        "Four mirror spheres whose reflected beams widen from left to right: sharp to glossy",
        [] { return demo::glossySpheres(); }},
       {}},
      {{"frosted-glass",
        "Clear glass and two panes of diffused glass, of growing radius, in front of a pattern",
        [] { return demo::frostedGlass(); }},
       {}},
      {{"soft-shadows",
        "Shapes under a light of radius 1.2: penumbrae widening away from what casts them",
        [] { return demo::softShadows(); }},
       {}},
      {{"antialiasing",
        "A checkerboard to the horizon, 4 x 4 jittered samples per pixel (samples=1: aliased)",
        &demo::antialiasing},
       {.samples = 4}},
      {{"depth-of-field", "Spheres at seven depths seen through a lens focused on the middle one",
        [] { return demo::depthOfField(); }},
       {.lensSamples = 24}},
      {{"adaptive",
        "Flat shapes with sharp edges, adaptively super-sampled: extra rays only on the edges",
        &demo::adaptiveEdges},
       {.adaptive = true, .adaptiveDepth = 3}},
      {{"super-sampling",
        "Every technique of mini project 1 in one scene, each off until a --param turns it on",
        [] { return demo::superSampling(); }},
       {}},
  };
  return table;
}

void checkDemoTable(std::span<const DemoScene> table) {
  std::vector<CourseScene> course;
  course.reserve(table.size());
  for (const DemoScene& entry : table) course.push_back(entry.course);
  checkSceneTable(course);  // so every entry has a name from here on
  for (std::size_t i = 0; i < table.size(); ++i) {
    const DemoScene& entry = table[i];
    const auto refuse = [&](const std::string& what) {
      throw std::logic_error("checkDemoTable: entry " + std::to_string(i) + " ('" +
                             entry.course.name + "'): " + what);
    };
    try {
      (void)makePixelSampler(entry.sampling);
    } catch (const std::exception& e) {
      refuse(std::string("its sampling settings are refused: ") + e.what());
    }
  }
}

}  // namespace rt
