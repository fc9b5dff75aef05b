// rt compare (label cli; in every course cut from stage 4 on, since it needs only stage 4's PNG
// reader and writer): the measures on images whose differences are known, the exit codes, the
// messages, and the difference heat map.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "InProcess.h"
#include "camera/ImageWriter.h"
#include "cli/Commands.h"
#include "cli/Compare.h"

namespace rt::cli {
namespace {

using test::Outcome;
using test::run;

/// A nX x nY image of one colour, (100, 150, 200), with the pixels of `changed` set apart.
struct Changed {
  int x, y;
  Color color;
};
std::string writeImage(const std::string& path, int nX, int nY,
                       const std::vector<Changed>& changed = {}) {
  Image image(nX, nY);
  for (int y = 0; y < nY; ++y)
    for (int x = 0; x < nX; ++x) image.setPixel(x, y, Color(100, 150, 200));
  for (const Changed& c : changed) image.setPixel(c.x, c.y, c.color);
  PngImageWriter().write(image, path);
  return path;
}

/// The images of most cases: 10 x 10, and the same with pixel (2, 1)'s red channel 3 higher.
struct Pair {
  std::string dir, a, b;
};
Pair onePixelOffByThree(const std::string& name) {
  const std::string dir = test::freshTestDirectory("compare-" + name);
  return {dir, writeImage(dir + "/a.png", 10, 10),
          writeImage(dir + "/b.png", 10, 10, {{2, 1, Color(103, 150, 200)}})};
}

TEST(CompareTests, identicalImages) {
  const std::string dir = test::freshTestDirectory("compare-identical");
  const std::string a = writeImage(dir + "/a.png", 10, 10), b = writeImage(dir + "/b.png", 10, 10);
  // TC01: identical images: PSNR inf, no difference, exit 0
  const Outcome r = run({"compare", a, b});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "A: " + a + ", 10x10\nB: " + b +
                       ", 10x10\n"
                       "PSNR: inf dB\n"
                       "largest channel difference: 0\n"
                       "pixels differing by more than 0: 0 of 100 (0%)\n"
                       "result: same within tolerance 0\n");
  EXPECT_EQ(r.err, "");
}

TEST(CompareTests, onePixelOffByThree) {
  const Pair p = onePixelOffByThree("off-by-three");
  // TC01: one channel of one pixel of 100 differs by 3. MSE = 3² / (3 channels × 100 pixels)
  // = 0.03, PSNR = 10·log10(255² / 0.03) = 10·log10(2167500) = 10 × 6.33596 = 63.36 dB; the
  // pixel's difference 3 exceeds the default tolerance 0: exit 1
  const Outcome r = run({"compare", p.a, p.b});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(r.out, "A: " + p.a + ", 10x10\nB: " + p.b +
                       ", 10x10\n"
                       "PSNR: 63.36 dB\n"
                       "largest channel difference: 3, first at pixel (2, 1)\n"
                       "pixels differing by more than 0: 1 of 100 (1%)\n"
                       "result: different beyond tolerance 0\n");
  EXPECT_EQ(r.err, "");
  // TC02: the measures themselves
  const ImageDifference d = compareImages(readPng(p.a), readPng(p.b), 0);
  EXPECT_EQ(d.largest, 3);
  EXPECT_EQ(d.beyondTolerance, 1u);
  EXPECT_EQ(d.pixels, 100u);
  EXPECT_DOUBLE_EQ(d.psnr, 10 * std::log10(65025 / 0.03));
}

TEST(CompareTests, toleranceBoundary) {
  const Pair p = onePixelOffByThree("tolerance");
  // TC11: a difference equal to the tolerance passes
  Outcome r = run({"compare", p.a, p.b, "--tolerance", "3"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\npixels differing by more than 3: 0 of 100 (0%)\n"
                       "result: same within tolerance 3\n"),
            std::string::npos)
      << r.out;
  // TC12: a difference one above the tolerance fails
  r = run({"compare", p.a, p.b, "--tolerance", "2"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("\npixels differing by more than 2: 1 of 100 (1%)\n"
                       "result: different beyond tolerance 2\n"),
            std::string::npos)
      << r.out;
  // TC13: the tolerance's range is 0..255
  r = run({"compare", p.a, p.b, "--tolerance", "256"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: --tolerance: expected an integer from 0 to 255, got '256'\n");
  r = run({"compare", p.a, p.b, "--tolerance", "-1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: --tolerance: expected an integer from 0 to 255, got '-1'\n");
}

TEST(CompareTests, imagesThatCannotBeCompared) {
  const std::string dir = test::freshTestDirectory("compare-bad");
  const std::string a = writeImage(dir + "/a.png", 10, 10);
  const std::string tall = writeImage(dir + "/tall.png", 10, 12);
  // TC01: images of different sizes: exit 2, naming both files and their sizes
  Outcome r = run({"compare", a, tall});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "rt: the images differ in size: A '" + a + "' is 10x10, B '" + tall +
                       "' is 10x12 (render both at the same --width and --height)\n");
  // TC02: a missing file, named with its argument
  r = run({"compare", a, dir + "/missing.png"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: B: cannot read '" + dir + "/missing.png': no such file\n");
  // TC03: a directory
  r = run({"compare", dir, a});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: A: cannot read '" + dir + "': it is a directory\n");
  // TC04: a file that is no image (stb's reason kept)
  std::ofstream(dir + "/text.png") << "not an image";
  r = run({"compare", dir + "/text.png", a});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: A: cannot read '" + dir + "/text.png' as an image: unknown image type\n");
  // TC05: a directory as --diff is refused before the images are read
  r = run({"compare", a, dir + "/missing.png", "--diff", dir});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: --diff: cannot write '" + dir + "': it is a directory\n");
  // TC06: --diff must name a PNG file
  r = run({"compare", a, a, "--diff", dir + "/d.jpg"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: --diff: the image is written as PNG, so its name must end in .png; got '" +
                       dir + "/d.jpg'\n");
  // TC07: a missing argument
  r = run({"compare", a});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: missing B for rt compare (see rt compare --help)\n");
  // TC08: compareImages itself refuses different sizes, naming both
  EXPECT_THROW((void)compareImages(readPng(a), readPng(tall), 0), std::invalid_argument);
  // TC09: --diff naming A or B (however spelt) is refused before anything is written: both
  // images stay as they were
  const std::string b = writeImage(dir + "/b.png", 10, 10, {{0, 0, Color(0, 0, 0)}});
  const std::string bytesA = test::readFile(a), bytesB = test::readFile(b);
  r = run({"compare", a, b, "--diff", a});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "rt: --diff: '" + a + "' is A ('" + a +
                       "'): the difference map would overwrite an image it compares; give "
                       "another file\n");
  r = run({"compare", a, b, "--diff", dir + "/./b.png"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: --diff: '" + dir + "/./b.png' is B ('" + b +
                       "'): the difference map would overwrite an image it compares; give "
                       "another file\n");
  // a hard link to A: another name of A's file
  const std::string hardA = dir + "/hard-a.png";
  std::filesystem::create_hard_link(a, hardA);
  r = run({"compare", a, b, "--diff", hardA});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "rt: --diff: '" + hardA + "' is A ('" + a +
                       "'): the difference map would overwrite an image it compares; give "
                       "another file\n");
  EXPECT_EQ(test::readFile(a), bytesA);
  EXPECT_EQ(test::readFile(b), bytesB);
  // a missing A named as --diff too: the missing file is what is wrong
  r = run({"compare", dir + "/missing.png", b, "--diff", dir + "/./missing.png"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "rt: A: cannot read '" + dir + "/missing.png': no such file\n");
  // nothing else written: a, tall, text, b and the link
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            5);
}

TEST(CompareTests, differenceHeatMap) {
  const std::string dir = test::freshTestDirectory("compare-heat-map");
  // Differences of 4 (the largest), 2 and 1 at three pixels; the others equal.
  const std::string a = writeImage(dir + "/a.png", 4, 3);
  const std::string b = writeImage(
      dir + "/b.png", 4, 3,
      {{0, 0, Color(104, 150, 200)}, {1, 0, Color(100, 148, 200)}, {3, 2, Color(100, 150, 201)}});
  const std::string map = dir + "/diff.png";
  // TC01: --diff writes the map and says how to read it
  const Outcome r = run({"compare", a, b, "--diff", map});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("\ndifference map: " + map +
                       " (black: equal; blue to red: a difference of 1 to 4)\n"),
            std::string::npos)
      << r.out;
  const Rgb8Image m = readPng(map);
  ASSERT_EQ(m.width, 4);
  ASSERT_EQ(m.height, 3);
  using Rgb = std::array<unsigned char, 3>;
  // TC02: the largest difference (t = 4/4) is red
  EXPECT_EQ(m.at(0, 0), (Rgb{255, 0, 0}));
  // TC03: half of it (t = 1/2) is green, a quarter (t = 1/4) cyan
  EXPECT_EQ(m.at(1, 0), (Rgb{0, 255, 0}));
  EXPECT_EQ(m.at(3, 2), (Rgb{0, 255, 255}));
  // TC04: equal pixels are black
  EXPECT_EQ(m.at(2, 0), (Rgb{0, 0, 0}));
  EXPECT_EQ(m.at(0, 2), (Rgb{0, 0, 0}));
  // TC05: identical images: an all-black map, said so
  const Outcome same = run({"compare", a, a, "--diff", dir + "/same.png"});
  EXPECT_EQ(same.code, 0) << same.err;
  EXPECT_NE(same.out.find("difference map: " + dir + "/same.png (black: every pixel is equal)\n"),
            std::string::npos)
      << same.out;
}

TEST(CompareTests, differenceColorRamp) {
  // TC01: no difference is black
  EXPECT_EQ(differenceColor(0, 8).rgb(), Double3(0, 0, 0));
  // TC02: between two stops the colour is mixed linearly: t = 1/8, half way from blue to cyan
  EXPECT_EQ(differenceColor(1, 8).rgb(), Double3(0, 127.5, 255));
  // TC03: t = 3/4 is yellow, t = 7/8 half way to red
  EXPECT_EQ(differenceColor(6, 8).rgb(), Double3(255, 255, 0));
  EXPECT_EQ(differenceColor(7, 8).rgb(), Double3(255, 127.5, 0));
  // TC11: the smallest difference of 255 levels is still blue, not black
  EXPECT_EQ(differenceColor(1, 255).rgb().x, 0);
  EXPECT_GT(differenceColor(1, 255).rgb().z, 0);
  // TC12: the largest is red
  EXPECT_EQ(differenceColor(255, 255).rgb(), Double3(255, 0, 0));
}

TEST(CompareTests, help) {
  // TC01: the command is listed, and its help shows its arguments and a reference check
  Outcome r = run({"--help"});
  EXPECT_NE(r.out.find("\n  compare "), std::string::npos) << r.out;
  r = run({"compare", "--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_TRUE(r.out.starts_with("Usage: rt compare A B [OPTIONS]\n")) << r.out;
  for (const char* text :
       {"--diff OUT.png", "--tolerance T", "rt compare mine.png docs/images/light-sphere-spot.png"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
}

}  // namespace
}  // namespace rt::cli
