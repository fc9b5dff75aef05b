// A scene far from the origin and as large: the scene files' coordinates go up to MAX_COORDINATE
// (10^75, app/scenefile/src/Readers.h), where the shapes' solvers and checks still work, and no
// farther. Before the bound, a sphere at 10^155 vanished from the image (its solver's squares
// overflowed into NaN) and a square polygon at 10^78 was refused as collinear.

#include <gtest/gtest.h>

#include <string>

#include "InProcess.h"

namespace rt::cli::test {
namespace {

/// Every shape, two lights and a mirror-like floor, each coordinate, radius and height the
/// mantissa given followed by `exponent` ("" for the scene at its own size, "e75" for 10^75
/// times as far and as large). The lights have no distance attenuation, so the image does not
/// change with the scale.
std::string scaledScene(const std::string& exponent) {
  const auto c = [&](const char* mantissa) { return std::string(mantissa) + exponent; };
  return R"({"camera": {"location": [0, 0, 0], "target": [0, 0, -1], "up": [0, 1, 0],
            "vpDistance": 1, "vpSize": [1, 0.5625], "resolution": [64, 36]},
 "background": [10, 10, 30],
 "geometries": [
  {"type": "sphere", "center": [0, 0, -)" +
         c("1") + R"(], "radius": )" + c("0.1") + R"(, "emission": [255, 0, 0]},
  {"type": "cylinder", "axis": {"origin": [)" +
         c("0.5") + ", -" + c("0.05") + ", -" + c("1") +
         R"(], "direction": [0, 1, 0]}, "radius": )" + c("0.1") + R"(, "height": )" + c("0.1") +
         R"(, "emission": [0, 255, 0]},
  {"type": "tube", "axis": {"origin": [-)" +
         c("0.5") + ", 0, -" + c("1") + R"(], "direction": [0, 1, 0]}, "radius": )" + c("0.05") +
         R"(, "emission": [255, 255, 0]},
  {"type": "polygon", "vertices": [[-)" +
         c("0.5") + ", -" + c("0.25") + ", -" + c("1") + "], [-" + c("0.25") + ", -" + c("0.25") +
         ", -" + c("1") + "], [-" + c("0.25") + ", -" + c("0.125") + ", -" + c("1") + "], [-" +
         c("0.5") + ", -" + c("0.125") + ", -" + c("1") + R"(]], "emission": [0, 0, 255]},
  {"type": "triangle", "vertices": [[)" +
         c("0.25") + ", " + c("0.125") + ", -" + c("1") + "], [" + c("0.5") + ", " + c("0.125") +
         ", -" + c("1") + "], [" + c("0.5") + ", " + c("0.25") + ", -" + c("1") +
         R"(]], "emission": [255, 0, 255]},
  {"type": "plane", "point": [0, -)" +
         c("0.5") + R"(, 0], "normal": [0, 1, 0], "emission": [20, 20, 20],
   "material": {"kD": 0.5, "kS": 0.5, "shininess": 20, "kR": 0.3}}],
 "lights": [
  {"type": "point", "intensity": [100, 100, 100], "position": [0, )" +
         c("0.5") + ", -" + c("0.5") + R"(]},
  {"type": "spot", "intensity": [100, 50, 100], "position": [)" +
         c("0.3") + ", " + c("0.5") + ", -" + c("0.5") + R"(], "direction": [0, -1, -1]}],
 "render": {"tracer": "whitted"}}
)";
}

TEST(FarSceneTest, RendersAt1e75AsAtItsOwnSize) {
  const std::string dir = freshTestDirectory("far-scene");
  const std::string near = writeText(dir + "/near.json", scaledScene(""));
  const std::string far = writeText(dir + "/far.json", scaledScene("e75"));
  const Outcome a = run({"render", near, "-o", dir + "/near.png", "--silent"});
  const Outcome b = run({"render", far, "-o", dir + "/far.png", "--silent"});
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const std::string nearImage = readFile(dir + "/near.png");
  ASSERT_FALSE(nearImage.empty());
  EXPECT_EQ(readFile(dir + "/far.png"), nearImage);
  // The image is not the background alone: every shape is in it (rt probe names each).
  for (const char* ray : {"0,0,-1", "0.5,0,-1", "-0.5,0,-1", "-0.375,-0.1875,-1", "0.45,0.15,-1"}) {
    const Outcome p = run({"probe", far, "--ray", "0,0,0", ray});
    EXPECT_EQ(p.code, 0) << p.err;
    EXPECT_NE(p.out.find("\"geometry\""), std::string::npos) << ray << ": " << p.out;
  }
}

TEST(FarSceneTest, RefusesACoordinateBeyond1e75) {
  const std::string dir = freshTestDirectory("far-scene-refused");
  const std::string beyond = writeText(dir + "/beyond.json", scaledScene("e76"));
  const Outcome r = run({"render", beyond, "-o", dir + "/beyond.png"});
  EXPECT_EQ(r.code, 2);
  // The first value read beyond the bound, with its place (the lights are read before the
  // shapes)
  EXPECT_EQ(r.err, "rt: " + beyond +
                       ":13:67: lights[0].position[1]: expected a coordinate from -1e+75 to "
                       "1e+75, got 0.5e76\n");
  EXPECT_TRUE(readFile(dir + "/beyond.png").empty());
}

}  // namespace
}  // namespace rt::cli::test
