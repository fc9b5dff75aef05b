// rt compare A.png B.png [--diff OUT.png] [--tolerance T]: how far two images are apart.
#include "cli/Compare.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include "CommandRegistration.h"

namespace rt::cli {

namespace {

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
  if (args.diff) {
    checkOutputWritable(*args.diff, PNG_IMAGE, "--diff");
    // An input that is not there is not overwritten: reading it says it is missing.
    std::error_code ec;
    for (const auto& [input, name] : {std::pair{&args.a, "A"}, std::pair{&args.b, "B"}})
      if (std::filesystem::exists(*input, ec) && sameFile(*args.diff, *input))
        throw UsageError("--diff: '" + *args.diff + "' is " + name + " ('" + *input +
                         "'): the difference map would overwrite an image it compares; give "
                         "another file");
  }
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
      "2 bad usage, an image that cannot be read, images of different sizes, or an answer\n"
      "that could not be printed (standard output could not be written).\n",
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
