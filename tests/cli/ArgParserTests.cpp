// Unit tests of the table-driven argument parser of `rt` (cli/ArgParser.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/ArgParser.h"

namespace rt::cli {
namespace {

/// A command with one option of each arity, as the real commands use them.
CommandSpec sampleCommand() {
  return {"sample",
          "a command for the tests",
          {"SCENE"},
          {{"--output", "-o", 1, "FILE", "where"},
           {"--width", "", 1, "W", "width"},
           {"--ray", "", 2, "O D", "a ray"},
           {"--quiet", "-q", 0, "", "quiet"}},
          "Details.\n"};
}

ParsedArgs parse(std::vector<std::string> args) { return parseArgs(sampleCommand(), args); }

std::string usageError(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ArgParserTests, parseArgsAcceptsEveryForm) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a positional argument and a long option with a separate value
  ParsedArgs a = parse({"scene", "--width", "640"});
  EXPECT_EQ(a.positional, std::vector<std::string>{"scene"});
  ASSERT_NE(a.value("--width"), nullptr);
  EXPECT_EQ(*a.value("--width"), "640");
  EXPECT_FALSE(a.has("--output"));
  // TC02: the short alias is stored under the long name
  a = parse({"-o", "x.png", "scene"});
  ASSERT_NE(a.value("--output"), nullptr);
  EXPECT_EQ(*a.value("--output"), "x.png");
  // TC03: --name=value
  a = parse({"scene", "--width=320"});
  EXPECT_EQ(*a.value("--width"), "320");
  // TC04: a flag has no value
  a = parse({"scene", "-q"});
  EXPECT_TRUE(a.has("--quiet"));
  EXPECT_TRUE(a.values("--quiet")->empty());
  // TC05: an option of arity 2 takes the next two arguments as they are, minus signs included
  a = parse({"scene", "--ray", "-1,0.5,-2", "0,0,1"});
  EXPECT_EQ(*a.values("--ray"), (std::vector<std::string>{"-1,0.5,-2", "0,0,1"}));
  EXPECT_EQ(a.positional, std::vector<std::string>{"scene"});
  // TC06: an argument that starts with a minus and a digit or a dot is a value, not an option
  a = parseArgs(CommandSpec{"n", "", {"A", "B"}, {}, ""}, std::vector<std::string>{"-1", "-.5"});
  EXPECT_EQ(a.positional, (std::vector<std::string>{"-1", "-.5"}));
  // TC07: after --, an argument that looks like an option is positional
  a = parse({"--", "--width"});
  EXPECT_EQ(a.positional, std::vector<std::string>{"--width"});
  EXPECT_FALSE(a.has("--width"));
  // TC08: --help stops the parsing: nothing else is checked
  a = parse({"--help", "--bogus"});
  EXPECT_TRUE(a.help);
  // TC09: -h is --help
  EXPECT_TRUE(parse({"-h"}).help);

  // =============== Boundary Values Tests ==================
  // TC11: "-" alone is a value (the usual name of stdin/stdout)
  EXPECT_EQ(parse({"-"}).positional, std::vector<std::string>{"-"});
  // TC12: an empty value after = is a value
  EXPECT_EQ(*parse({"s", "--width="}).value("--width"), "");
}

TEST(ArgParserTests, parseArgsRefusesBadUsage) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an unknown option, with the nearest known one suggested
  EXPECT_EQ(usageError({"s", "--widht", "3"}),
            "unknown option '--widht' for rt sample; did you mean '--width'? "
            "(see rt sample --help)");
  // TC02: an unknown option that resembles nothing
  EXPECT_EQ(usageError({"s", "--frobnicate"}),
            "unknown option '--frobnicate' for rt sample (see rt sample --help)");
  // TC03: a missing value
  EXPECT_EQ(usageError({"s", "--width"}), "option --width expects W (see rt sample --help)");
  // TC04: an option given twice
  EXPECT_EQ(usageError({"s", "-o", "a.png", "--output", "b.png"}),
            "option --output given twice (see rt sample --help)");
  // TC05: a missing positional argument
  EXPECT_EQ(usageError({"-q"}), "rt sample: missing SCENE (see rt sample --help)");
  // TC06: an unexpected positional argument
  EXPECT_EQ(usageError({"a", "b"}), "rt sample: unexpected argument 'b' (see rt sample --help)");
  // TC07: a flag given a value with =
  EXPECT_EQ(usageError({"s", "--quiet=yes"}),
            "option --quiet takes no value, got '--quiet=yes' (see rt sample --help)");

  // =============== Boundary Values Tests ==================
  // TC11: an option of arity 2 with only one value left
  EXPECT_EQ(usageError({"s", "--ray", "0,0,0"}), "option --ray expects O D (see rt sample --help)");
  // TC12: a short option that is unknown
  EXPECT_EQ(usageError({"s", "-x"}), "unknown option '-x' for rt sample (see rt sample --help)");
}

TEST(ArgParserTests, formatHelpListsEveryOption) {
  const std::string help = formatHelp(sampleCommand());
  // TC01: usage line, summary, one line per option (aliases and values included), details
  EXPECT_EQ(help,
            "Usage: rt sample SCENE [OPTIONS]\n\n"
            "a command for the tests\n\n"
            "Options:\n"
            "  -o, --output FILE  where\n"
            "      --width W      width\n"
            "      --ray O D      a ray\n"
            "  -q, --quiet        quiet\n"
            "  -h, --help         show this help\n\n"
            "Details.\n");
}

}  // namespace
}  // namespace rt::cli
