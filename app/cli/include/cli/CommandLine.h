#pragma once
/// @file CommandLine.h
/// The command line of `rt`, on CLI11 (Debian libcli11-dev): `rt` is a CLI11 application whose
/// subcommands are the commands (list, render, probe, export), each declaring its positional
/// arguments and its typed options with CLI11's own calls, so a new option (a mini project's
/// --threads, say) is one add_option. What CLI11 does not decide is the wording: CLI11 prints
/// nothing, and every bad usage becomes one UsageError in rt's words ("unknown option '--widht'
/// for rt render; did you mean '--width'? (see rt render --help)"), and every help text one
/// layout (HelpFormatter in CommandLine.cpp).
///
/// What the parsing accepts, CLI11's rules:
/// - `--name value`, `--name=value`, `-o value` (and `-ovalue`); an option with n values takes
///   the next n arguments as they are, so `--ray -1,0.5,-2 0,0,1` works;
/// - an argument that starts with '-' and a digit is a value, never an option (`-1`), and "-"
///   alone is a value;
/// - `--` ends the options: everything after it is positional;
/// - a positional argument is required, unless it has a default (CLI11's default_str, which the
///   help shows as [NAME]);
/// - a flag takes no value (`--quiet=yes` is refused), but may be repeated;
/// - `-h`/`--help` after a command shows that command's help, before the command is checked.

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <CLI/App.hpp>
#include <CLI/Validators.hpp>

namespace rt::cli {

/// Bad usage or bad input: `rt` prints the message after "rt: " and exits with code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Io;
/// What a command does once its arguments are parsed (into the variables its options are bound
/// to): returns the exit code.
using CommandRun = std::function<int(const Io&)>;

class CommandLine {
 public:
  /// @param name the program, "rt"
  /// @param description the first line of `rt --help`
  /// @param footer what `rt --help` shows after its options (examples, exit codes)
  /// @param version what `rt --version` prints
  CommandLine(std::string name, std::string description, std::string footer, std::string version);

  /// Adds a command, and returns it for its positional arguments and options (CLI11 calls:
  /// add_option, add_flag, ...; type_name sets the value's name in the help, "W").
  /// @param summary one line, in `rt --help` and under the command's usage line
  /// @param details paragraphs shown after the command's options
  CLI::App& addCommand(const std::string& name, const std::string& summary,
                       const std::string& details, CommandRun run);

  /// addCommand for a command whose arguments are bound to an Args, which lives as long as the
  /// command line, and whose work is run(args, io). Returns the command and its Args, for
  /// declaring the options: `auto [command, args] = rt.addCommand("render", ..., render);`.
  template <typename Args>
  std::pair<CLI::App*, Args*> addCommand(const std::string& name, const std::string& summary,
                                         const std::string& details,
                                         int (*run)(const Args&, const Io&)) {
    auto args = std::make_shared<Args>();
    CLI::App& command =
        addCommand(name, summary, details, [args, run](const Io& io) { return run(*args, io); });
    return {&command, args.get()};
  }

  /// What parse found: a text to print (a help, the version) or a command to run.
  struct Parsed {
    std::string text;
    CommandRun run;  ///< empty when text is the answer
  };

  /// Parses args (without the program's name) and binds the values to the commands' options.
  /// @throws UsageError with one line naming the command and the bad argument: an unknown
  ///         command or option (with the nearest name suggested), a missing or a stray
  ///         argument, a missing value, an option given twice, a flag given a value, a value an
  ///         option's validator refuses, or a comma-separated value split by a space
  ///         (`--pixel 1 2`).
  Parsed parse(std::span<const std::string> args);

 private:
  std::unique_ptr<CLI::App> app_;
  std::vector<std::pair<const CLI::App*, CommandRun>> runs_;
};

/// Adds an option whose value, when given, is stored in into (CLI11 2.1 binds no std::optional):
/// `addOptional(command, "-o,--output", args.output, "where to write it", "FILE.png")`. T is
/// what CLI11 converts the value(s) to: a string, an int, a pair of strings for two values.
/// into must live as long as command. Returns the option, for transform() or check().
template <typename T>
CLI::Option* addOptional(CLI::App& command, const std::string& names, std::optional<T>& into,
                         const std::string& help, const std::string& valueName) {
  return command
      .add_option_function<T>(
          names, [&into](const T& value) { into = value; }, help)
      ->type_name(valueName);
}

/// A transformer (Option::transform) for an integer option in [lo, hi] by the app's one rule for
/// integers (common/Integers.h: 1000, 1e3 and 1000.0 are all 1000). It rewrites the value to
/// its decimal digits for CLI11's conversion to int, which knows neither 1e3 nor 1000.0 (and
/// reads 010 as octal), and refuses anything else with "expected an integer from LO to HI, got
/// 'VALUE'" (CLI11 puts the option's name in front).
CLI::Validator integerValidator(int lo, int hi);

/// A check (Option::check) for an option read as a double: the whole value a finite number in
/// the C locale's form (std::from_chars: 30, -2.5, 1e3), else "expected a number, got 'VALUE'"
/// rather than CLI11's "Could not convert". The command checks its range.
CLI::Validator numberValidator();

}  // namespace rt::cli
