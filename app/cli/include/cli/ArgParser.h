#pragma once
/// @file ArgParser.h
/// The command line of `rt`, parsed from small tables: every command lists its positional
/// arguments and its options (name, alias, how many values, help text), and one parser and one
/// help formatter serve them all. A new option (a mini project's --threads, say) is one more row.

#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rt::cli {

/// Bad usage or bad input: `rt` prints the message after "rt: " and exits with code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One option of a command.
struct OptionSpec {
  std::string_view name;     ///< long form, "--width"
  std::string_view alias;    ///< short form, "-o", or empty
  int arity = 0;             ///< how many values follow it: 0 for a flag
  std::string_view metavar;  ///< the values' names in the help, "W" or "OX,OY,OZ DX,DY,DZ"
  std::string_view help;     ///< one line
};

/// One command: its name, positional arguments and options, and its help text.
struct CommandSpec {
  std::string_view name;                     ///< "render"
  std::string_view summary;                  ///< one line, shown by `rt --help`
  std::vector<std::string_view> positional;  ///< names of the required positional arguments
  std::vector<OptionSpec> options;           ///< --help is implicit
  std::string details;                       ///< paragraphs shown after the options
};

/// What the parser found. Options are keyed by their long name ("--width").
struct ParsedArgs {
  bool help = false;  ///< --help or -h was given: nothing else was checked
  std::vector<std::string> positional;
  std::map<std::string, std::vector<std::string>, std::less<>> options;

  bool has(std::string_view name) const { return options.find(name) != options.end(); }
  /// The single value of an option of arity 1, or nullptr when it was not given.
  const std::string* value(std::string_view name) const;
  /// The values of an option, or nullptr when it was not given.
  const std::vector<std::string>* values(std::string_view name) const;
};

/// Parses the arguments that follow the command's name.
///
/// - `--name value`, `--name=value` (arity 1) and `-o value` are accepted; an option with arity
///   n takes the next n arguments as they are, so `--ray -1,0.5,-2 0,0,1` works.
/// - An argument that starts with '-' followed by a digit or '.' is a value, never an option.
/// - `--` ends the options; everything after it is positional.
/// @throws UsageError naming the command and the bad argument (an unknown option, with the
///         nearest known one suggested; a missing value; an option given twice; a missing or an
///         unexpected positional argument).
ParsedArgs parseArgs(const CommandSpec& command, std::span<const std::string> args);

/// `rt COMMAND --help`: usage line, summary, options, details.
std::string formatHelp(const CommandSpec& command);

}  // namespace rt::cli
