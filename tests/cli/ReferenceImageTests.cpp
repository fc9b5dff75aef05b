// The reference images of docs/images/ (label cli; in every course cut from stage 4 on): each
// course scene of the build, rendered as scripts/render-docs-images.sh renders it and as a student
// is told to (`rt render NAME --width 500`), is the committed image exactly (rt compare, tolerance
// 0). One test per scene; and one per line of docs/images/render-options.txt whose scene is a
// course scene of the build (IMAGE.png is `rt render SCENE OPTION...`: the debugging views of
// stages 1 and 3). When a change of the engine alters an image on purpose, run
// scripts/render-docs-images.sh and commit the new images.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/BuiltinScenes.h"
#include "cli/Commands.h"

#ifndef RT_DOCS_IMAGES_DIR
#error "RT_DOCS_IMAGES_DIR must name docs/images of the sources"
#endif

namespace rt::cli {
namespace {

namespace fs = std::filesystem;

/// The built-in scenes of the course's stages (stage04_camera ... stage07_reflections) in this
/// build; the mini projects' (the galaxy) are sampled and long to render: not references here.
std::vector<std::string> courseScenes() {
  std::vector<std::string> names;
  for (const BuiltinScene& s : builtinScenes())
    if (s.stage.starts_with("stage")) names.push_back(s.name);
  return names;
}

/// A reference image: docs/images/IMAGE.png is `rt render SCENE OPTION...`.
struct Reference {
  std::string image;
  std::string scene;
  std::vector<std::string> options;
};

void PrintTo(const Reference& r, std::ostream* os) { *os << r.image; }

/// Each course scene at --width 500, under its own name.
std::vector<Reference> sceneReferences() {
  std::vector<Reference> references;
  for (const std::string& name : courseScenes())
    references.push_back({name, name, {"--width", "500"}});
  return references;
}

/// The lines of render-options.txt (IMAGE SCENE OPTION..., # a comment) whose scene is a course
/// scene of this build.
std::vector<Reference> optionReferences() {
  const std::vector<std::string> scenes = courseScenes();
  std::vector<Reference> references;
  std::ifstream in(std::string(RT_DOCS_IMAGES_DIR) + "/render-options.txt");
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    Reference r;
    if (!(words >> r.image) || r.image.starts_with("#") || !(words >> r.scene)) continue;
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) continue;
    for (std::string option; words >> option;) r.options.push_back(option);
    references.push_back(std::move(r));
  }
  return references;
}

class ReferenceImageTest : public testing::TestWithParam<Reference> {};

TEST_P(ReferenceImageTest, aFreshRenderIsTheCommittedImage) {
  const Reference& r = GetParam();
  const std::string reference = std::string(RT_DOCS_IMAGES_DIR) + "/" + r.image + ".png";
  // TC01: the course scene has a reference image
  ASSERT_TRUE(fs::is_regular_file(reference))
      << reference << " is missing: run scripts/render-docs-images.sh and commit it";
  const fs::path dir = fs::path("cli-test-output") / "reference-images";
  fs::create_directories(dir);
  const std::string mine = (dir / (r.image + ".png")).string();
  std::ostringstream out, err;
  // TC02: rendered as documented, it compares exactly (exit 0: every channel equal)
  std::vector<std::string> render{"render", r.scene};
  render.insert(render.end(), r.options.begin(), r.options.end());
  render.insert(render.end(), {"-o", mine, "--silent"});
  ASSERT_EQ(runRt(render, Io{out, err}), EXIT_OK) << err.str();
  const std::vector<std::string> compare{"compare", mine, reference};
  EXPECT_EQ(runRt(compare, Io{out, err}), EXIT_OK)
      << out.str() << err.str()
      << "if the change is intended, run scripts/render-docs-images.sh and commit docs/images";
}

/// gtest names: letters, digits, _.
std::string testName(const testing::TestParamInfo<Reference>& param) {
  std::string id = param.param.image;
  for (char& c : id)
    if (c == '-') c = '_';
  return id;
}

INSTANTIATE_TEST_SUITE_P(CourseScenes, ReferenceImageTest, testing::ValuesIn(sceneReferences()),
                         testName);
INSTANTIATE_TEST_SUITE_P(RenderOptions, ReferenceImageTest, testing::ValuesIn(optionReferences()),
                         testName);

}  // namespace
}  // namespace rt::cli
