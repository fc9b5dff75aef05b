// Image, PngImageWriter and readPng, and the camera's image operations (renderImage, printGrid,
// writeToImage) with their error cases. Files are written under the build directory (the
// tests' working directory), in test-images/stage04/.

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>

#include "TestFiles.h"
#include "camera/Camera.h"
#include "camera/Image.h"
#include "camera/ImageWriter.h"
#include "camera/RayTracer.h"
#include "camera/Scene.h"

namespace rt {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<unsigned char, 3>;

const Rgb RED8{255, 0, 0};
const Rgb YELLOW8{255, 255, 0};

using test::entries;
using test::readFile;
using test::testDir;

template <typename E, typename F>
void expectThrowWith(F&& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no exception thrown";
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
        << "message \"" << e.what() << "\" lacks \"" << fragment << "\"";
  }
}

/// Counts the pixels of a read-back image that differ from the course's grid: red where x or y
/// is a multiple of 50, yellow elsewhere.
int gridMismatches(const Rgb8Image& img) {
  int bad = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.at(x, y) != ((x % 50 == 0 || y % 50 == 0) ? RED8 : YELLOW8)) ++bad;
  return bad;
}

// ---------------------------------------------------------------------------------------------
// Image

TEST(ImageTests, SizeBounds) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an ordinary size, black pixels
  const Image image(800, 500);
  EXPECT_EQ(image.nX(), 800);
  EXPECT_EQ(image.nY(), 500);
  EXPECT_EQ(image.pixel(799, 499), Color::BLACK);
  // TC02: negative sides
  expectThrowWith<std::invalid_argument>([] { Image(-5, 10); }, "nX must be in [1, 32768], got -5");
  expectThrowWith<std::invalid_argument>([] { Image(10, -5); }, "nY must be in [1, 32768], got -5");
  // =============== Boundary Values Tests ==================
  // TC11: 1x1 is the smallest image
  EXPECT_EQ(Image(1, 1).nX(), 1);
  // TC12: zero sides
  EXPECT_THROW(Image(0, 1), std::invalid_argument);
  EXPECT_THROW(Image(1, 0), std::invalid_argument);
  // TC13: one above 2^15 on either side, rejected before anything is allocated
  expectThrowWith<std::invalid_argument>([] { Image(Image::MAX_SIDE + 1, 1); }, "got 32769");
  expectThrowWith<std::invalid_argument>([] { Image(1, Image::MAX_SIDE + 1); }, "got 32769");
  // TC14: the largest side, in a thin image
  EXPECT_EQ(Image(Image::MAX_SIDE, 1).nX(), Image::MAX_SIDE);
}

TEST(ImageTests, PixelsAreStoredUnclamped) {
  // TC01: a colour above 255 is kept as it is; (x, y) = (column, row)
  Image image(3, 2);
  image.setPixel(2, 1, Color(300, 20, 20));
  EXPECT_EQ(image.pixel(2, 1), Color(300, 20, 20));
  EXPECT_EQ(image.pixel(1, 2 - 1), Color::BLACK);
}

// ---------------------------------------------------------------------------------------------
// PngImageWriter and readPng

TEST(ImageWriterTests, CourseGridWrittenAndReadBack) {
  // TC01: the course's test: 800x500, yellow with red lines every 50 pixels (16x10 squares)
  const fs::path dir = testDir("grid");
  Image image(800, 500);
  for (int y = 0; y < 500; ++y)
    for (int x = 0; x < 800; ++x)
      image.setPixel(x, y, (x % 50 == 0 || y % 50 == 0) ? Color::RED : Color::YELLOW);
  const std::string path = (dir / "yellow-red-grid.png").string();
  PngImageWriter().write(image, path);

  const Rgb8Image back = readPng(path);
  ASSERT_EQ(back.width, 800);
  ASSERT_EQ(back.height, 500);
  EXPECT_EQ(gridMismatches(back), 0);
  // spot checks: the corner and the last lines are red, the squares' insides yellow
  EXPECT_EQ(back.at(0, 0), RED8);
  EXPECT_EQ(back.at(750, 123), RED8);  // the 16th vertical line
  EXPECT_EQ(back.at(321, 450), RED8);  // the 10th horizontal line
  EXPECT_EQ(back.at(799, 499), YELLOW8);
  EXPECT_EQ(back.at(25, 25), YELLOW8);
  EXPECT_EQ(back.at(751, 451), YELLOW8);
  EXPECT_EQ(back.at(49, 49), YELLOW8);
  // nothing but the image is left in the directory (no temporary file)
  EXPECT_EQ(entries(dir), 1u);
}

TEST(ImageWriterTests, ColoursClampedAndRoundedAtWriteTime) {
  // TC01: above 255 -> 255; fractional -> nearest; (300,20,20) -> (255,20,20)
  const fs::path dir = testDir("clamp");
  Image image(2, 1);
  image.setPixel(0, 0, Color(300, 20, 20));
  image.setPixel(1, 0, Color(0.4, 127.5, 254.6));
  const std::string path = (dir / "clamp.png").string();
  PngImageWriter().write(image, path);
  const Rgb8Image back = readPng(path);
  EXPECT_EQ(back.at(0, 0), (Rgb{255, 20, 20}));
  EXPECT_EQ(back.at(1, 0), (Rgb{0, 128, 255}));
  // the image itself still holds the unclamped colour
  EXPECT_EQ(image.pixel(0, 0), Color(300, 20, 20));
}

TEST(ImageWriterTests, OverwritesAnExistingImage) {
  // TC02: writing again replaces the old file completely
  const fs::path dir = testDir("overwrite");
  const std::string path = (dir / "image.png").string();
  Image red(4, 4), yellow(2, 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) red.setPixel(x, y, Color::RED);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 2; ++x) yellow.setPixel(x, y, Color::YELLOW);
  PngImageWriter().write(red, path);
  PngImageWriter().write(yellow, path);
  const Rgb8Image back = readPng(path);
  EXPECT_EQ(back.width, 2);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.at(1, 2), YELLOW8);
  EXPECT_EQ(entries(dir), 1u);
}

TEST(ImageWriterTests, FailureThrowsNamingThePath) {
  const Image image(2, 2);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the directory does not exist
  const fs::path dir = testDir("failure");
  const std::string missing = (dir / "no-such-dir" / "out.png").string();
  expectThrowWith<std::runtime_error>([&] { PngImageWriter().write(image, missing); },
                                      "cannot write '" + missing + "'");
  EXPECT_FALSE(fs::exists(dir / "no-such-dir"));
  // TC02: the path is an existing directory: the temporary file is written, the rename fails,
  // the temporary file is removed and the directory with its content is untouched
  const fs::path occupied = dir / "occupied.png";
  fs::create_directories(occupied);
  std::ofstream(occupied / "keep.txt") << "keep";
  expectThrowWith<std::runtime_error>([&] { PngImageWriter().write(image, occupied.string()); },
                                      "cannot write '" + occupied.string() + "'");
  EXPECT_TRUE(fs::is_directory(occupied));
  EXPECT_EQ(readFile(occupied / "keep.txt"), "keep");
  EXPECT_EQ(entries(dir), 1u);  // only occupied.png/, no temporary file left
  // TC03: a parent component is a regular file; that file is untouched
  const fs::path file = dir / "plain.txt";
  std::ofstream(file) << "plain";
  EXPECT_THROW(PngImageWriter().write(image, (file / "out.png").string()), std::runtime_error);
  EXPECT_EQ(readFile(file), "plain");
  // =============== Boundary Values Tests ==================
  // TC11: an empty (default) image cannot be written
  EXPECT_THROW(PngImageWriter().write(Image(), (dir / "empty.png").string()),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir / "empty.png"));
}

TEST(ImageWriterTests, ExistingFileUntouchedWhenItsDirectoryRefusesNewFiles) {
  // TC04: an existing file in a directory where no file can be created (even by root):
  // /proc/version. The write fails and the file keeps its content.
  const fs::path target = "/proc/version";
  if (!fs::exists(target)) GTEST_SKIP() << "needs Linux /proc";
  const std::string before = readFile(target);
  expectThrowWith<std::runtime_error>([&] { PngImageWriter().write(Image(2, 2), target.string()); },
                                      "'/proc/version'");
  EXPECT_EQ(readFile(target), before);
}

TEST(ImageWriterTests, ReadPngErrors) {
  const fs::path dir = testDir("read");
  // TC01: no such file
  expectThrowWith<std::runtime_error>([&] { (void)readPng((dir / "absent.png").string()); },
                                      "absent.png");
  // TC02: not an image
  std::ofstream(dir / "text.png") << "not a png";
  EXPECT_THROW((void)readPng((dir / "text.png").string()), std::runtime_error);
  // TC11: a pixel outside the read-back image
  Rgb8Image img;
  img.width = 1;
  img.height = 1;
  img.rgb = {1, 2, 3};
  EXPECT_EQ(img.at(0, 0), (Rgb{1, 2, 3}));
  EXPECT_THROW((void)img.at(1, 0), std::out_of_range);
  EXPECT_THROW((void)img.at(0, -1), std::out_of_range);
}

// ---------------------------------------------------------------------------------------------
// Camera: renderImage, printGrid, writeToImage

/// A camera looking at nothing: with an empty scene every pixel is the background.
Camera::Builder emptyView(int nX, int nY) {
  return Camera::builder()
      .setLocation(Point::ZERO)
      .setDirection(Vector(0, 0, -1), Vector(0, 1, 0))
      .setVpSize(nX, nY)
      .setVpDistance(1)
      .setResolution(nX, nY);
}

TEST(CameraImageTests, CourseGridThroughTheCamera) {
  // TC01: render an empty scene with a yellow background, print a red grid every 50 pixels,
  // write it and read it back: the same 800x500 grid as the course's ImageWriter test
  const fs::path dir = testDir("camera-grid");
  Scene scene;
  scene.background = Color::YELLOW;
  Camera camera = emptyView(800, 500)
                      .setRayTracer(std::make_shared<AmbientTracer>(scene))
                      .setImageWriter(std::make_shared<PngImageWriter>())
                      .build();
  const std::string path = (dir / "grid.png").string();
  camera.renderImage().printGrid(50, Color::RED).writeToImage(path);
  const Rgb8Image back = readPng(path);
  ASSERT_EQ(back.width, 800);
  ASSERT_EQ(back.height, 500);
  EXPECT_EQ(gridMismatches(back), 0);
}

TEST(CameraImageTests, PrintGridInterval) {
  Camera camera = emptyView(4, 3).build();
  // TC01: interval 1 paints every pixel
  camera.printGrid(1, Color::WHITE);
  EXPECT_EQ(camera.image().pixel(3, 2), Color::WHITE);
  // TC02: interval 2 on 4x3: columns 0, 2 and rows 0, 2
  Camera two = emptyView(4, 3).build();
  two.printGrid(2, Color::RED);
  EXPECT_EQ(two.image().pixel(2, 1), Color::RED);
  EXPECT_EQ(two.image().pixel(1, 2), Color::RED);
  EXPECT_EQ(two.image().pixel(1, 1), Color::BLACK);
  EXPECT_EQ(two.image().pixel(3, 1), Color::BLACK);
  // TC11: interval 0 and below
  expectThrowWith<std::invalid_argument>([&] { camera.printGrid(0, Color::RED); }, "got 0");
  EXPECT_THROW(camera.printGrid(-50, Color::RED), std::invalid_argument);
}

TEST(CameraImageTests, MissingTracerOrWriter) {
  // TC01: renderImage without a tracer names rayTracer
  Camera camera = emptyView(2, 2).build();
  expectThrowWith<std::logic_error>([&] { camera.renderImage(); }, "'rayTracer'");
  // TC02: writeToImage without a writer names imageWriter, and writes nothing
  const fs::path dir = testDir("missing-writer");
  const std::string path = (dir / "x.png").string();
  expectThrowWith<std::logic_error>([&] { camera.writeToImage(path); }, "'imageWriter'");
  EXPECT_FALSE(fs::exists(path));
}

/// Counts its rays and raises the stop flag after the first one.
class StoppingTracer final : public RayTracer {
 public:
  StoppingTracer(const Scene& scene, std::atomic<bool>& stop) : RayTracer(scene), stop_(stop) {}
  using RayTracer::traceRay;
  Color traceRay(const Ray&, SampleContext&) const override {
    ++calls;
    stop_ = true;
    return Color::WHITE;
  }
  mutable std::atomic<int> calls{0};

 private:
  std::atomic<bool>& stop_;
};

TEST(CameraImageTests, StopFlag) {
  const Scene scene;
  // TC01: stop raised during the first row: that row is finished, then RenderInterrupted
  std::atomic<bool> stop{false};
  auto tracer = std::make_shared<StoppingTracer>(scene, stop);
  Camera camera = emptyView(7, 5).setRayTracer(tracer).build();
  EXPECT_THROW(camera.renderImage(&stop), RenderInterrupted);
  EXPECT_EQ(tracer->calls.load(), 7);
  EXPECT_EQ(camera.image().pixel(6, 0), Color::WHITE);
  EXPECT_EQ(camera.image().pixel(0, 1), Color::BLACK);
  // TC11: stop already raised: nothing is traced
  std::atomic<bool> raised{true};
  auto idle = std::make_shared<StoppingTracer>(scene, raised);
  Camera other = emptyView(3, 3).setRayTracer(idle).build();
  EXPECT_THROW(other.renderImage(&raised), RenderInterrupted);
  EXPECT_EQ(idle->calls.load(), 0);
  // TC12: no flag given: the whole image is rendered
  std::atomic<bool> ignored{false};
  auto all = std::make_shared<StoppingTracer>(scene, ignored);
  Camera full = emptyView(3, 2).setRayTracer(all).build();
  full.renderImage();
  EXPECT_EQ(all->calls.load(), 6);
}

}  // namespace
}  // namespace rt
