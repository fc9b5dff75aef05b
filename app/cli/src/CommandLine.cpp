#include "cli/CommandLine.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>

// The whole of CLI11 here: constructing a CLI::App needs its formatter and its config parser.
#include <CLI/CLI.hpp>

#include "cli/Values.h"
#include "common/Integers.h"
#include "common/NearestName.h"

namespace rt::cli {

namespace {

/// "rt" for the program, "rt render" for a command.
std::string commandLabel(const CLI::App& app) {
  const CLI::App* parent = app.get_parent();
  return parent ? commandLabel(*parent) + " " + app.get_name() : app.get_name();
}

std::string seeHelp(const CLI::App& app) { return " (see " + commandLabel(app) + " --help)"; }

/// CLI11's rule: "--x..." and "-x" are options, "-1", "-" and "--" are not.
bool looksLikeOption(std::string_view arg) {
  if (arg.size() < 2 || arg[0] != '-' || arg == "--") return false;
  return arg[1] == '-' || !std::isdigit(static_cast<unsigned char>(arg[1]));
}

/// "-o, --output FILE.png" or "    --width W": the left column of an option's help line.
std::string optionColumn(const CLI::Option& o) {
  std::string left;
  for (const std::string& s : o.get_snames()) left += "-" + s + ", ";
  if (left.empty()) left = "    ";
  const std::vector<std::string>& longNames = o.get_lnames();
  left += longNames.empty() ? "" : "--" + longNames.front();
  if (o.get_items_expected_max() > 0) left += " " + o.get_type_name();
  return left;
}

/// Rows of a two-column table, the left column padded to its widest entry.
std::string table(const std::vector<std::pair<std::string, std::string>>& rows) {
  std::size_t width = 0;
  for (const auto& [left, right] : rows) width = std::max(width, left.size());
  std::string out;
  for (const auto& [left, right] : rows)
    out += "  " + left + std::string(width - left.size() + 2, ' ') + right + "\n";
  return out;
}

/// The one layout of every help text. A command's: usage line, summary, options (--help last),
/// details. The program's: description, usage line, commands, options, footer.
class HelpFormatter : public CLI::FormatterBase {
 public:
  std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode) const override {
    std::ostringstream os;
    const bool program = app->get_parent() == nullptr;
    if (program) {
      os << app->get_description() << "\n\nUsage: " << commandLabel(*app)
         << " COMMAND [ARGUMENTS] [OPTIONS]\n\nCommands:\n";
      std::vector<std::pair<std::string, std::string>> commands;
      for (const CLI::App* c :
           app->get_subcommands([](const CLI::App* c) { return !c->get_group().empty(); }))
        commands.emplace_back(c->get_name(), c->get_description());
      os << table(commands);
    } else {
      os << "Usage: " << commandLabel(*app);
      for (const CLI::Option* p :
           app->get_options([](const CLI::Option* o) { return o->get_positional(); }))
        os << ' ' << (p->get_default_str().empty() ? p->get_name() : "[" + p->get_name() + "]");
      os << " [OPTIONS]\n\n" << app->get_description() << "\n";
    }
    std::vector<std::pair<std::string, std::string>> options;
    for (const CLI::Option* o : app->get_options()) {
      if (!o->get_positional() && o != app->get_help_ptr())
        options.emplace_back(optionColumn(*o), o->get_description());
    }
    if (const CLI::Option* help = app->get_help_ptr())
      options.emplace_back(optionColumn(*help), help->get_description());
    os << "\nOptions:\n" << table(options);
    if (const std::string footer = app->get_footer(); !footer.empty())
      os << "\n" << footer << (footer.ends_with('\n') ? "" : "\n");
    return os.str();
  }
};

/// app's help in HelpFormatter's layout. (CLI::App::help() would show the help of a command
/// parsed below app instead: for `rt help`, the help command's own.)
std::string helpOf(const CLI::App& app) {
  return app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
}

/// The option an argument of the command line names: "--width", "--width=3", "-o", "-ofile";
/// nullptr for a value or an unknown name.
const CLI::Option* optionNamed(const CLI::App& app, const std::string& arg) {
  if (!looksLikeOption(arg)) return nullptr;
  const std::string name = arg.starts_with("--") ? arg.substr(0, arg.find('=')) : arg.substr(0, 2);
  const CLI::Option* o = app.get_option_no_throw(name);
  return o != nullptr && !o->get_positional() ? o : nullptr;
}

/// The values an option holds: CLI11's results without the empty one that "--width=" leaves.
std::size_t valuesGiven(const CLI::Option& o) {
  const std::vector<std::string>& results = o.results();
  return static_cast<std::size_t>(std::count_if(results.begin(), results.end(),
                                                [](const std::string& r) { return !r.empty(); }));
}

/// A CLI::ArgumentMismatch: CLI11 found an option with the wrong number of values. Which option,
/// and how, is read from the command's options and the arguments, in the order given: a flag
/// given a value (--quiet=yes), an option given more values than it takes (twice), or fewer.
std::optional<std::string> argumentMismatch(const CLI::App& command,
                                            std::span<const std::string> args) {
  const auto end = std::find(args.begin(), args.end(), "--");
  for (auto it = args.begin(); it != end; ++it) {
    const CLI::Option* o = optionNamed(command, *it);
    if (o == nullptr) continue;
    const std::string name = o->get_name();
    const int most = o->get_items_expected_max();
    if (most == 0) {
      if (it->find('=') != std::string::npos)
        return "option " + name + " takes no value, got '" + *it + "'" + seeHelp(command);
      continue;
    }
    const std::size_t given = valuesGiven(*o);
    if (given > static_cast<std::size_t>(most))
      return "option " + name + " given twice" + seeHelp(command);
    if (given < static_cast<std::size_t>(o->get_items_expected_min()))
      return "option " + name + " expects " + o->get_type_name() + seeHelp(command);
    // Its values, which may look like options (`-o --width`), are not names: one occurrence
    // takes all of a fixed count, or one group of a repeatable option's.
    const int taken = o->get_expected_max() == CLI::detail::expected_max_vector_size
                          ? o->get_type_size_max()
                          : most;
    if (it->find('=') == std::string::npos && !(it->size() > 2 && (*it)[1] != '-'))
      it += std::min<std::ptrdiff_t>(taken, end - it - 1);
  }
  return std::nullopt;
}

/// A CLI::ValidationError: one of the command's values failed a validator. The message is the
/// validator's own (rt's: "expected an integer from 1 to 32768, got 'wide'"), found by running
/// each given option's validators again on its values, after the option's name.
std::optional<std::string> validationFailure(CLI::App& command) {
  for (CLI::Option* o : command.get_options()) {
    for (std::string value : o->results()) {  // a copy: a transformer rewrites it
      for (int i = 0;; ++i) {
        const CLI::Validator* validator = nullptr;
        try {
          validator = o->get_validator(i);
        } catch (const CLI::OptionNotFound&) {
          break;  // past the last
        }
        std::string message;
        try {
          message = (*validator)(value);
        } catch (const CLI::ValidationError& e) {  // CLI11's own validators may throw theirs
          message = e.what();
        }
        if (!message.empty()) return o->get_name() + ": " + message;
      }
    }
  }
  return std::nullopt;
}

/// rt's words for what CLI11 refused while parsing args for command (or the program), from the
/// exception's type and the command's options. CLI11's own text (e.what()) is shown only for an
/// error rt's settings do not produce (a conversion error: every value is a string or an
/// integer a validator has rewritten to digits).
std::string describe(const CLI::ParseError& e, CLI::App& command,
                     std::span<const std::string> args) {
  std::optional<std::string> message;
  if (dynamic_cast<const CLI::ValidationError*>(&e))
    message = validationFailure(command);
  else if (dynamic_cast<const CLI::ArgumentMismatch*>(&e))
    message = argumentMismatch(command, args);
  else if (dynamic_cast<const CLI::RequiredError*>(&e))
    for (const CLI::Option* o : command.get_options())
      if (o->get_required() && o->count() == 0 && !message)
        message = "missing " + o->get_name() + " for " + commandLabel(command) + seeHelp(command);
  return message ? *message : e.what() + seeHelp(command);
}

/// `--pixel 1 2`: a value that should be a comma-separated list, given without a comma and
/// followed by a stray argument, was most likely split by a space. Says so, or returns nothing.
std::optional<std::string> splitValueHint(const CLI::App& command,
                                          std::span<const std::string> args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (!looksLikeOption(args[i])) continue;
    const CLI::Option* o = command.get_option_no_throw(args[i]);
    if (o == nullptr || o->get_positional()) continue;
    const std::size_t n = static_cast<std::size_t>(std::max(o->get_items_expected_max(), 0));
    const std::string form = o->get_type_name();
    if (n == 0 || form.find(',') == std::string::npos || i + n + 1 >= args.size()) continue;
    const auto values = args.subspan(i + 1, n);
    const std::string& stray = args[i + n + 1];
    if (looksLikeOption(stray) || std::all_of(values.begin(), values.end(), [](const auto& v) {
          return v.find(',') != std::string::npos;
        }))
      continue;
    std::string got;
    for (const std::string& v : values) got += (got.empty() ? "'" : " '") + v + "'";
    return o->get_name() + " takes " + form + " (" +
           (n == 1 ? "one argument, " : std::to_string(n) + " arguments, each ") +
           "comma-separated), got " + got + " and an extra '" + stray + "'" + seeHelp(command);
  }
  return std::nullopt;
}

/// "unknown option '--widht' for rt render; did you mean '--width'? (see rt render --help)".
std::string unknownOption(const CLI::App& app, std::string_view arg) {
  const std::string name(arg.starts_with("--") ? arg.substr(0, arg.find('=')) : arg);
  std::vector<std::string> longNames;
  for (const CLI::Option* o : app.get_options())
    for (const std::string& l : o->get_lnames()) longNames.push_back("--" + l);
  const std::vector<std::string_view> known(longNames.begin(), longNames.end());
  return "unknown option '" + name + "' for " + commandLabel(app) + didYouMean(name, known) +
         seeHelp(app);
}

/// Whether a left-over argument is an unknown option rather than a stray value: it looks like
/// one, and the command line has it before any "--" (after which everything is positional).
bool isUnknownOption(const std::string& arg, std::span<const std::string> args) {
  if (!looksLikeOption(arg)) return false;
  const auto end = std::find(args.begin(), args.end(), "--");
  return std::find(args.begin(), end, arg) != end;
}

/// What CLI11 left over (without the "--" it keeps), in order.
std::vector<std::string> leftovers(const CLI::App& app) {
  std::vector<std::string> rest = app.remaining();
  std::erase(rest, "--");
  return rest;
}

/// The checks CLI11 leaves to us, in the order of the command line: unknown commands and
/// options, stray arguments, then missing positional arguments.
void checkWhatIsLeft(const CLI::App& program, const CLI::App* command,
                     std::span<const std::string> args) {
  std::vector<std::string> stray;
  const auto commandAt =
      command ? std::find(args.begin(), args.end(), command->get_name()) : args.end();
  for (const std::string& arg : leftovers(program)) {
    if (isUnknownOption(arg, args)) throw UsageError(unknownOption(program, arg));
    // A word before the command, or no command at all: a command that does not exist. After
    // the command (CLI11 hands a second command's name back to the program): a stray argument.
    if (std::find(args.begin(), commandAt, arg) != commandAt) {
      std::vector<std::string_view> names;
      for (const CLI::App* c :
           program.get_subcommands([](const CLI::App* c) { return !c->get_group().empty(); }))
        names.push_back(c->get_name());
      throw UsageError("unknown command '" + arg + "'" + didYouMean(arg, names) + seeHelp(program));
    }
    stray.push_back(arg);
  }
  if (command == nullptr) throw UsageError("missing COMMAND" + seeHelp(program));
  std::vector<std::string> rest = leftovers(*command);
  rest.insert(rest.end(), stray.begin(), stray.end());
  for (const std::string& arg : rest) {
    if (isUnknownOption(arg, args)) throw UsageError(unknownOption(*command, arg));
    if (std::optional<std::string> hint = splitValueHint(*command, args)) throw UsageError(*hint);
    throw UsageError("unexpected argument '" + arg + "' for " + commandLabel(*command) +
                     seeHelp(*command));
  }
  // A positional argument with a default (CLI11's default_str, shown in the help as [NAME]) may
  // be left out: `rt bench` is `rt bench galaxy`.
  for (const CLI::Option* p :
       command->get_options([](const CLI::Option* o) { return o->get_positional(); }))
    if (p->count() == 0 && p->get_default_str().empty())
      throw UsageError("missing " + p->get_name() + " for " + commandLabel(*command) +
                       seeHelp(*command));
}

}  // namespace

CommandLine::CommandLine(std::string name, std::string description, std::string footer,
                         std::string version)
    : app_(std::make_unique<CLI::App>(std::move(description), std::move(name))) {
  // An option given twice is an error, and a flag takes no value ("--quiet=no" would turn it
  // off). Set first: options get the defaults when they are added, commands inherit them.
  app_->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::Throw);
  app_->option_defaults()->disable_flag_override();
  app_->formatter(std::make_shared<HelpFormatter>());
  app_->footer(std::move(footer));
  app_->set_help_flag("-h,--help", "show this help; rt COMMAND --help shows a command's");
  app_->set_version_flag("--version", std::move(version), "print the version");
  // Unknown options and stray arguments are left over rather than refused, so that the
  // messages about them are ours (checkWhatIsLeft).
  app_->allow_extras();
  // One command at a time: a second command's name after the first is a stray argument.
  app_->require_subcommand(0, 1);
  // `rt help` is `rt --help` (hidden: no group).
  app_->add_subcommand("help", "show this help")->group("");
}

CLI::App& CommandLine::addCommand(const std::string& name, const std::string& summary,
                                  const std::string& details, CommandRun run) {
  CLI::App* command = app_->add_subcommand(name, summary);
  command->footer(details);  // not the program's, which it would inherit
  command->set_help_flag("-h,--help", "show this help");
  runs_.emplace_back(command, std::move(run));
  return *command;
}

CommandLine::Parsed CommandLine::parse(std::span<const std::string> args) {
  const auto chosen = [this]() -> CLI::App* {
    const std::vector<CLI::App*> parsed = app_->get_subcommands();
    return parsed.empty() ? nullptr : parsed.front();
  };
  try {
    // CLI11 takes the arguments last first.
    app_->parse(std::vector<std::string>(args.rbegin(), args.rend()));
  } catch (const CLI::CallForHelp&) {
    return {helpOf(chosen() ? *chosen() : *app_), {}};
  } catch (const CLI::CallForVersion& e) {
    return {std::string(e.what()) + "\n", {}};
  } catch (const CLI::ParseError& e) {
    throw UsageError(describe(e, chosen() ? *chosen() : *app_, args));
  }
  checkWhatIsLeft(*app_, chosen(), args);
  if (chosen()->get_name() == "help") return {helpOf(*app_), {}};
  for (const auto& [command, run] : runs_)
    if (command == chosen()) return {{}, run};
  throw std::logic_error("CommandLine: no run function for command '" + chosen()->get_name() + "'");
}

CLI::Validator integerValidator(int lo, int hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const std::optional<int> value = integerInText(text, lo, hi);
        if (!value) return integerError(text, lo, hi);
        text = std::to_string(*value);
        return {};
      },
      "");  // no description: CLI11 would append it to the value's name in the help ("W:...")
}

CLI::Validator numberValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        const char* const end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value))
          return "expected a number, got '" + text + "'";
        return {};
      },
      "");  // no description, as integerValidator's
}

}  // namespace rt::cli
