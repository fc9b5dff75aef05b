// rt compare A.png B.png [--diff OUT.png] [--tolerance T]: how far two images are apart.
#include "cli/Compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "CommandRegistration.h"

namespace rt::cli {

namespace {

void requireSameSize(const Rgb8Image& a, const Rgb8Image& b, const char* operation) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument(std::string(operation) + ": the images differ in size (" +
                                std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
                                std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
}

/// The largest of a pixel's three channel differences, and the sum of their squares.
struct PixelDifference {
  int largest = 0;
  std::uint64_t squares = 0;
};

PixelDifference pixelDifference(const Rgb8Image& a, const Rgb8Image& b, std::size_t pixel) {
  PixelDifference d;
  for (std::size_t c = 0; c < 3; ++c) {
    const int delta = std::abs(int{a.rgb[3 * pixel + c]} - int{b.rgb[3 * pixel + c]});
    d.largest = std::max(d.largest, delta);
    d.squares += static_cast<std::uint64_t>(delta * delta);
  }
  return d;
}

/// The file at path, read as an image; what names the argument ("A") in the messages.
Rgb8Image readImageArgument(const std::string& path, std::string_view what) {
  const std::string prefix = std::string(what) + ": cannot read '" + path + "'";
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw UsageError(prefix + ": it is a directory");
  if (!std::filesystem::exists(path, ec)) throw UsageError(prefix + ": no such file");
  try {
    return readPng(path);
  } catch (const std::runtime_error& e) {
    // readPng says "readPng: cannot read 'PATH' as an image: REASON"; keep the reason.
    const std::string message = e.what();
    const std::size_t reason = message.rfind(": ");
    throw UsageError(prefix + " as an image" +
                     (reason == std::string::npos ? "" : message.substr(reason)));
  }
}

/// "48.13 dB", or "inf dB" for identical images.
std::string formatPsnr(double psnr) {
  if (std::isinf(psnr)) return "inf dB";
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(2);
  os << psnr << " dB";
  return os.str();
}

/// A share as a percentage with four significant digits: "1%", "0.0004%", "33.33%".
std::string formatShare(std::uint64_t part, std::uint64_t whole) {
  std::ostringstream os;
  os.precision(4);
  os << 100.0 * static_cast<double>(part) / static_cast<double>(whole) << "%";
  return os.str();
}

/// rt compare's arguments, as the command line binds them.
struct CompareArgs {
  std::string a, b;
  std::optional<std::string> diff;
  int tolerance = 0;
};

int compare(const CompareArgs& args, const Io& io) {
  // The output first, as rt render does: a mistake costs no work.
  if (args.diff) checkOutputWritable(*args.diff, PNG_IMAGE, "--diff");
  const Rgb8Image a = readImageArgument(args.a, "A");
  const Rgb8Image b = readImageArgument(args.b, "B");
  const auto size = [](const Rgb8Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
  };
  if (a.width != b.width || a.height != b.height)
    throw UsageError("the images differ in size: A '" + args.a + "' is " + size(a) + ", B '" +
                     args.b + "' is " + size(b) +
                     " (render both at the same --width and --height)");
  const ImageDifference d = compareImages(a, b, args.tolerance);
  const std::string tolerance = std::to_string(args.tolerance);
  io.out << "A: " << args.a << ", " << size(a) << "\n"
         << "B: " << args.b << ", " << size(b) << "\n"
         << "PSNR: " << formatPsnr(d.psnr) << "\n"
         << "largest channel difference: " << d.largest;
  if (d.largest > 0) io.out << ", first at pixel (" << d.largestX << ", " << d.largestY << ")";
  io.out << "\npixels differing by more than " << tolerance << ": " << d.beyondTolerance << " of "
         << d.pixels << " (" << formatShare(d.beyondTolerance, d.pixels) << ")\n";
  if (args.diff) {
    PngImageWriter().write(differenceMap(a, b), *args.diff);
    io.out << "difference map: " << *args.diff
           << (d.largest == 0 ? " (black: every pixel is equal)"
                              : " (black: equal; blue to red: a difference of 1 to " +
                                    std::to_string(d.largest) + ")")
           << "\n";
  }
  io.out << "result: " << (d.withinTolerance() ? "same within" : "different beyond")
         << " tolerance " << tolerance << "\n";
  return d.withinTolerance() ? EXIT_OK : EXIT_FAILURE_RUNTIME;
}

}  // namespace

ImageDifference compareImages(const Rgb8Image& a, const Rgb8Image& b, int tolerance) {
  requireSameSize(a, b, "compareImages");
  if (tolerance < 0 || tolerance > 255)
    throw std::invalid_argument("compareImages: the tolerance must be from 0 to 255, got " +
                                std::to_string(tolerance));
  ImageDifference out;
  out.width = a.width;
  out.height = a.height;
  out.pixels = static_cast<std::uint64_t>(a.width) * static_cast<std::uint64_t>(a.height);
  std::uint64_t squares = 0;
  for (std::size_t i = 0; i < out.pixels; ++i) {
    const PixelDifference d = pixelDifference(a, b, i);
    squares += d.squares;
    if (d.largest > tolerance) ++out.beyondTolerance;
    if (d.largest > out.largest) {
      out.largest = d.largest;
      out.largestX = static_cast<int>(i % static_cast<std::size_t>(a.width));
      out.largestY = static_cast<int>(i / static_cast<std::size_t>(a.width));
    }
  }
  // PSNR = 10·log10(255² / MSE), MSE over every channel of every pixel.
  const double mse = static_cast<double>(squares) / (3.0 * static_cast<double>(out.pixels));
  out.psnr =
      squares == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
  return out;
}

Color differenceColor(int d, int largest) {
  if (d <= 0) return Color::BLACK;
  // The ramp's five stops at t = 0, 1/4, 1/2, 3/4, 1: blue, cyan, green, yellow, red.
  static constexpr double STOPS[5][3] = {
      {0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}};
  const double t = std::clamp(static_cast<double>(d) / std::max(largest, 1), 0.0, 1.0);
  const int k = std::min(3, static_cast<int>(t * 4));  // the segment [k/4, (k+1)/4]
  const double f = t * 4 - k;
  const auto mix = [&](int c) { return STOPS[k][c] + (STOPS[k + 1][c] - STOPS[k][c]) * f; };
  return Color(mix(0), mix(1), mix(2));
}

Image differenceMap(const Rgb8Image& a, const Rgb8Image& b) {
  requireSameSize(a, b, "differenceMap");
  const std::size_t pixels = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
  int largest = 0;
  for (std::size_t i = 0; i < pixels; ++i)
    largest = std::max(largest, pixelDifference(a, b, i).largest);
  Image map(a.width, a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(a.width) + x;
      map.setPixel(x, y, differenceColor(pixelDifference(a, b, i).largest, largest));
    }
  return map;
}

void addCompareCommand(CommandLine& rt) {
  const auto [command, args] = rt.addCommand(
      "compare", "compare two images pixel by pixel (a render with a reference image)",
      "Prints both sizes, the PSNR (dB; inf for identical images), the largest channel\n"
      "difference and the share of pixels whose largest channel difference exceeds the\n"
      "tolerance. --diff writes a heat map: black where the pixels are equal, blue to red\n"
      "for small to the largest differences.\n\n"
      "Check a render against the repository's reference images (docs/images/, made by\n"
      "scripts/render-docs-images.sh with --width 500):\n"
      "  rt render light-sphere-spot --width 500 -o mine.png\n"
      "  rt compare mine.png docs/images/light-sphere-spot.png\n\n"
      "Exit codes: 0 the same within the tolerance (every pixel's difference <= T), 1 not,\n"
      "2 bad usage, an image that cannot be read, or images of different sizes.\n",
      compare);
  command->add_option("A", args->a, "an image (PNG)");
  command->add_option("B", args->b, "the image to compare it with");
  addOptional(*command, "--diff", args->diff,
              "write the difference heat map there (black: equal; blue to red: larger)", "OUT.png");
  command
      ->add_option("--tolerance", args->tolerance,
                   "the largest channel difference a pixel may have, 0..255 (default: 0, exact)")
      ->type_name("T")
      ->transform(integerValidator(0, 255));
}

}  // namespace rt::cli
