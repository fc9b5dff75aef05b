// The reference images of docs/images/ (label cli; in every course cut from stage 4 on): each
// course scene of the build, rendered as scripts/render-docs-images.sh renders it and as a student
// is told to (`rt render NAME --width 500`), is the committed image exactly (rt compare, tolerance
// 0). One test per scene. When a change of the engine alters an image on purpose, run
// scripts/render-docs-images.sh and commit the new images.
#include <gtest/gtest.h>

#include <filesystem>
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

class ReferenceImageTest : public testing::TestWithParam<std::string> {};

TEST_P(ReferenceImageTest, aFreshRenderIsTheCommittedImage) {
  const std::string& name = GetParam();
  const std::string reference = std::string(RT_DOCS_IMAGES_DIR) + "/" + name + ".png";
  // TC01: the course scene has a reference image
  ASSERT_TRUE(fs::is_regular_file(reference))
      << reference << " is missing: run scripts/render-docs-images.sh and commit it";
  const fs::path dir = fs::path("cli-test-output") / "reference-images";
  fs::create_directories(dir);
  const std::string mine = (dir / (name + ".png")).string();
  std::ostringstream out, err;
  // TC02: rendered as documented, it compares exactly (exit 0: every channel equal)
  const std::vector<std::string> render{"render", name, "--width", "500", "-o", mine, "--silent"};
  ASSERT_EQ(runRt(render, Io{out, err}), EXIT_OK) << err.str();
  const std::vector<std::string> compare{"compare", mine, reference};
  EXPECT_EQ(runRt(compare, Io{out, err}), EXIT_OK)
      << out.str() << err.str()
      << "if the change is intended, run scripts/render-docs-images.sh and commit docs/images";
}

INSTANTIATE_TEST_SUITE_P(CourseScenes, ReferenceImageTest, testing::ValuesIn(courseScenes()),
                         [](const testing::TestParamInfo<std::string>& param) {
                           std::string id = param.param;  // gtest names: letters, digits, _
                           for (char& c : id)
                             if (c == '-') c = '_';
                           return id;
                         });

}  // namespace
}  // namespace rt::cli
