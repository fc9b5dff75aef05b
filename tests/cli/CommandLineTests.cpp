// Unit tests of rt's command line on CLI11 (cli/CommandLine.h): what it accepts, what it
// refuses and in which words, and the help layout, on a sample command declared the way the
// real commands declare theirs.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/CommandLine.h"
#include "cli/Commands.h"

namespace rt::cli {
namespace {

/// The values a sample command's options are bound to.
struct SampleValues {
  std::string scene;
  std::optional<std::string> output;
  std::optional<int> width;
  std::optional<std::pair<std::string, std::string>> ray;
  std::optional<std::string> pixel;
  bool quiet = false;
};

/// A program "rt" with one command, "sample": a positional SCENE, an option with a short
/// alias, an integer option, an option of two values, a comma-separated one, and a flag.
class SampleLine {
 public:
  SampleLine() {
    CLI::App& c = line.addCommand("sample", "a command for the tests", "Details.\n",
                                  [](const Io&) { return 7; });
    c.add_option("SCENE", values.scene, "the scene");
    c.add_option_function<std::string>(
         "-o,--output", [this](const std::string& o) { values.output = o; }, "where")
        ->type_name("FILE");
    c.add_option_function<int>(
         "--width", [this](const int& w) { values.width = w; }, "width")
        ->type_name("W")
        ->transform(integerValidator(1, 32768));
    c.add_option_function<std::pair<std::string, std::string>>(
         "--ray", [this](const auto& r) { values.ray = r; }, "a ray")
        ->type_name("O,O D,D");
    c.add_option_function<std::string>(
         "--pixel", [this](const std::string& p) { values.pixel = p; }, "a pixel")
        ->type_name("X,Y");
    c.add_flag("-q,--quiet", values.quiet, "quiet");
  }
  SampleLine(const SampleLine&) = delete;
  SampleLine& operator=(const SampleLine&) = delete;

  SampleValues values;
  CommandLine line{"rt", "rt 9.9: a program for the tests", "Footer.\n", "rt 9.9"};
};

/// The values bound by parsing `rt sample ARGS...` (the command must be found and runnable).
SampleValues parseSample(std::vector<std::string> args) {
  SampleLine sample;
  args.insert(args.begin(), "sample");
  const CommandLine::Parsed parsed = sample.line.parse(args);
  EXPECT_TRUE(parsed.run) << "printed instead: " << parsed.text;
  return sample.values;
}

/// What parsing `rt ARGS...` prints (a help, the version), or "(runs)".
std::string printed(const std::vector<std::string>& args) {
  SampleLine sample;
  const CommandLine::Parsed parsed = sample.line.parse(args);
  return parsed.run ? "(runs)" : parsed.text;
}

/// The UsageError's message for `rt ARGS...`, or "(no error)".
std::string usageError(const std::vector<std::string>& args) {
  SampleLine sample;
  try {
    sample.line.parse(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CommandLineTests, parseAcceptsEveryForm) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a positional argument and a long option with a separate value; what is not given
  // stays unset
  SampleValues v = parseSample({"scene", "--width", "640"});
  EXPECT_EQ(v.scene, "scene");
  EXPECT_EQ(v.width, 640);
  EXPECT_EQ(v.output, std::nullopt);
  EXPECT_FALSE(v.quiet);
  // TC02: the short alias, before the positional argument
  v = parseSample({"-o", "x.png", "scene"});
  EXPECT_EQ(v.output, "x.png");
  EXPECT_EQ(v.scene, "scene");
  // TC03: --name=value
  EXPECT_EQ(parseSample({"scene", "--width=320"}).width, 320);
  // TC04: a flag, in both forms
  EXPECT_TRUE(parseSample({"scene", "-q"}).quiet);
  EXPECT_TRUE(parseSample({"scene", "--quiet"}).quiet);
  // TC05: an option of two values takes the next two arguments as they are, minus signs
  // included
  v = parseSample({"scene", "--ray", "-1,0.5,-2", "0,0,1"});
  EXPECT_EQ(v.ray, (std::pair<std::string, std::string>{"-1,0.5,-2", "0,0,1"}));
  EXPECT_EQ(v.scene, "scene");
  // TC06: an argument that starts with a minus and a digit is a value, not an option
  EXPECT_EQ(parseSample({"-1"}).scene, "-1");
  // TC07: after --, an argument that looks like an option is positional
  v = parseSample({"--", "--width"});
  EXPECT_EQ(v.scene, "--width");
  EXPECT_EQ(v.width, std::nullopt);
  // TC08: an integer in any JSON number form (the one rule for integers)
  EXPECT_EQ(parseSample({"s", "--width", "1e3"}).width, 1000);
  EXPECT_EQ(parseSample({"s", "--width", "1000.0"}).width, 1000);
  EXPECT_EQ(parseSample({"s", "--width", "2.5e2"}).width, 250);
  // TC09: a flag may be repeated
  EXPECT_TRUE(parseSample({"s", "-q", "--quiet"}).quiet);
  // TC10: the command's run function is what parse returns
  SampleLine sample;
  std::ostringstream out, err;
  EXPECT_EQ(sample.line.parse(std::vector<std::string>{"sample", "s"}).run(Io{out, err}), 7);

  // =============== Boundary Values Tests ==================
  // TC11: "-" alone is a value (the usual name of stdin/stdout)
  EXPECT_EQ(parseSample({"-"}).scene, "-");
  // TC12: the integer range's ends
  EXPECT_EQ(parseSample({"s", "--width", "1"}).width, 1);
  EXPECT_EQ(parseSample({"s", "--width", "32768"}).width, 32768);
  // TC13: a value that starts like an option is still the value of the option before it
  EXPECT_EQ(parseSample({"s", "-o", "--width"}).output, "--width");
}

TEST(CommandLineTests, parsePrintsHelpAndVersion) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: --help after a command stops the parsing: nothing else is checked (not even the
  // missing SCENE or the unknown option)
  const std::string sampleHelp = printed({"sample", "--help", "--bogus"});
  EXPECT_TRUE(sampleHelp.starts_with("Usage: rt sample SCENE [OPTIONS]\n")) << sampleHelp;
  // TC02: -h is --help
  EXPECT_EQ(printed({"sample", "-h"}), sampleHelp);
  // TC03: rt --help, rt -h and rt help show the program's help
  const std::string programHelp = printed({"--help"});
  EXPECT_TRUE(programHelp.starts_with("rt 9.9: a program for the tests\n")) << programHelp;
  EXPECT_EQ(printed({"-h"}), programHelp);
  EXPECT_EQ(printed({"help"}), programHelp);
  // TC04: --version
  EXPECT_EQ(printed({"--version"}), "rt 9.9\n");
  // TC05: a command with its arguments runs
  EXPECT_EQ(printed({"sample", "s"}), "(runs)");
}

TEST(CommandLineTests, parseRefusesBadUsage) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an unknown option, with the nearest known one suggested
  EXPECT_EQ(usageError({"sample", "s", "--widht", "3"}),
            "unknown option '--widht' for rt sample; did you mean '--width'? "
            "(see rt sample --help)");
  // TC02: an unknown option that resembles nothing
  EXPECT_EQ(usageError({"sample", "s", "--frobnicate"}),
            "unknown option '--frobnicate' for rt sample (see rt sample --help)");
  // TC03: a missing value
  EXPECT_EQ(usageError({"sample", "s", "--width"}),
            "option --width expects W (see rt sample --help)");
  // TC04: an option given twice, under either name
  EXPECT_EQ(usageError({"sample", "s", "-o", "a.png", "--output", "b.png"}),
            "option --output given twice (see rt sample --help)");
  // TC05: a missing positional argument
  EXPECT_EQ(usageError({"sample", "-q"}), "missing SCENE for rt sample (see rt sample --help)");
  // TC06: an unexpected positional argument
  EXPECT_EQ(usageError({"sample", "a", "b"}),
            "unexpected argument 'b' for rt sample (see rt sample --help)");
  // TC07: a flag given a value
  EXPECT_EQ(usageError({"sample", "s", "--quiet=yes"}),
            "option --quiet takes no value, got '--quiet=yes' (see rt sample --help)");
  // TC08: an integer option given no integer, a fraction, or a form JSON does not have
  EXPECT_EQ(usageError({"sample", "s", "--width", "wide"}),
            "--width: expected an integer from 1 to 32768, got 'wide'");
  EXPECT_EQ(usageError({"sample", "s", "--width", "6.5"}),
            "--width: expected an integer from 1 to 32768, got '6.5'");
  EXPECT_EQ(usageError({"sample", "s", "--width", "010"}),
            "--width: expected an integer from 1 to 32768, got '010'");
  // TC09: a comma-separated value split by a space: the stray half is explained
  EXPECT_EQ(usageError({"sample", "s", "--pixel", "1", "2"}),
            "--pixel takes X,Y (one argument, comma-separated), got '1' and an extra '2' "
            "(see rt sample --help)");
  EXPECT_EQ(usageError({"sample", "s", "--ray", "1", "2", "3"}),
            "--ray takes O,O D,D (2 arguments, each comma-separated), got '1' '2' and an extra "
            "'3' (see rt sample --help)");
  // TC10: an unknown command, with a suggestion
  EXPECT_EQ(usageError({"sampel", "s"}),
            "unknown command 'sampel'; did you mean 'sample'? (see rt --help)");
  // TC11: an unknown option of the program itself, before any command
  EXPECT_EQ(usageError({"--verison"}),
            "unknown option '--verison' for rt; did you mean '--version'? (see rt --help)");
  EXPECT_EQ(usageError({"--fast", "sample", "s"}),
            "unknown option '--fast' for rt (see rt --help)");
  // TC12: a second command after the first is a stray argument
  EXPECT_EQ(usageError({"sample", "s", "sample"}),
            "unexpected argument 'sample' for rt sample (see rt sample --help)");
  // TC13: after --, an argument that looks like an option is a stray positional argument
  EXPECT_EQ(usageError({"sample", "s", "--", "--width"}),
            "unexpected argument '--width' for rt sample (see rt sample --help)");

  // =============== Boundary Values Tests ==================
  // TC21: no arguments at all
  EXPECT_EQ(usageError({}), "missing COMMAND (see rt --help)");
  // TC22: an option of two values with only one left
  EXPECT_EQ(usageError({"sample", "s", "--ray", "0,0,0"}),
            "option --ray expects O,O D,D (see rt sample --help)");
  // TC23: an unknown short option, and an unknown option given a value with = (the name is
  // what is unknown)
  EXPECT_EQ(usageError({"sample", "s", "-x"}),
            "unknown option '-x' for rt sample (see rt sample --help)");
  EXPECT_EQ(usageError({"sample", "s", "--widht=3"}),
            "unknown option '--widht' for rt sample; did you mean '--width'? "
            "(see rt sample --help)");
  // TC24: one beyond each end of the integer range
  EXPECT_EQ(usageError({"sample", "s", "--width", "0"}),
            "--width: expected an integer from 1 to 32768, got '0'");
  EXPECT_EQ(usageError({"sample", "s", "--width", "3.2769e4"}),
            "--width: expected an integer from 1 to 32768, got '3.2769e4'");
  // TC25: "--width=" with nothing after it takes no empty value: the value is missing
  EXPECT_EQ(usageError({"sample", "s", "--width="}),
            "option --width expects W (see rt sample --help)");
  // TC26: a comma-separated value followed by a stray argument, but given with its comma: no
  // hint, the stray argument is reported
  EXPECT_EQ(usageError({"sample", "s", "--pixel", "1,2", "3"}),
            "unexpected argument '3' for rt sample (see rt sample --help)");
}

TEST(CommandLineTests, helpLayout) {
  // TC01: a command's help: usage line, summary, one line per option (aliases and values'
  // names included, --help last), details
  EXPECT_EQ(printed({"sample", "--help"}),
            "Usage: rt sample SCENE [OPTIONS]\n\n"
            "a command for the tests\n\n"
            "Options:\n"
            "  -o, --output FILE  where\n"
            "      --width W      width\n"
            "      --ray O,O D,D  a ray\n"
            "      --pixel X,Y    a pixel\n"
            "  -q, --quiet        quiet\n"
            "  -h, --help         show this help\n\n"
            "Details.\n");
  // TC02: the program's help: description, usage line, the commands (not the hidden help
  // command), options, footer
  EXPECT_EQ(printed({"--help"}),
            "rt 9.9: a program for the tests\n\n"
            "Usage: rt COMMAND [ARGUMENTS] [OPTIONS]\n\n"
            "Commands:\n"
            "  sample  a command for the tests\n\n"
            "Options:\n"
            "      --version  print the version\n"
            "  -h, --help     show this help; rt COMMAND --help shows a command's\n\n"
            "Footer.\n");
}

}  // namespace
}  // namespace rt::cli
