#include "cli/ArgParser.h"

#include <algorithm>
#include <sstream>

#include "common/NearestName.h"

namespace rt::cli {

namespace {

constexpr std::string_view kHelpName = "--help";
constexpr std::string_view kHelpAlias = "-h";

/// "-1,0.5,-2" and "-.5" are values; "-o" and "--width" are options; "-" alone is a value
/// (conventionally stdin/stdout).
bool looksLikeOption(std::string_view arg) {
  if (arg.size() < 2 || arg[0] != '-') return false;
  const char c = arg[1];
  return !(c >= '0' && c <= '9') && c != '.';
}

const OptionSpec* findOption(const CommandSpec& command, std::string_view name) {
  for (const OptionSpec& o : command.options)
    if (o.name == name || (!o.alias.empty() && o.alias == name)) return &o;
  return nullptr;
}

std::string commandLabel(const CommandSpec& command) { return "rt " + std::string(command.name); }

std::string seeHelp(const CommandSpec& command) {
  return " (see " + commandLabel(command) + " --help)";
}

}  // namespace

const std::string* ParsedArgs::value(std::string_view name) const {
  auto it = options.find(name);
  return it == options.end() || it->second.empty() ? nullptr : &it->second.front();
}

const std::vector<std::string>* ParsedArgs::values(std::string_view name) const {
  auto it = options.find(name);
  return it == options.end() ? nullptr : &it->second;
}

ParsedArgs parseArgs(const CommandSpec& command, std::span<const std::string> args) {
  ParsedArgs parsed;
  bool optionsEnded = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (optionsEnded || !looksLikeOption(arg)) {
      parsed.positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      optionsEnded = true;
      continue;
    }
    if (arg == kHelpName || arg == kHelpAlias) {
      parsed.help = true;
      return parsed;
    }
    // --name=value
    std::string_view name = arg;
    std::optional<std::string> inlineValue;
    if (const auto eq = name.find('='); name.starts_with("--") && eq != std::string_view::npos) {
      inlineValue = std::string(name.substr(eq + 1));
      name = name.substr(0, eq);
    }
    const OptionSpec* spec = findOption(command, name);
    if (!spec) {
      std::vector<std::string_view> known;
      for (const OptionSpec& o : command.options) known.push_back(o.name);
      known.push_back(kHelpName);
      throw UsageError("unknown option '" + std::string(name) + "' for " + commandLabel(command) +
                       didYouMean(name, known) + seeHelp(command));
    }
    const std::string key(spec->name);
    if (parsed.has(key)) throw UsageError("option " + key + " given twice" + seeHelp(command));
    std::vector<std::string> values;
    if (inlineValue) {
      if (spec->arity != 1)
        throw UsageError(
            "option " + key +
            (spec->arity == 0 ? " takes no value" : " cannot take its values after '='") +
            ", got '" + arg + "'" + seeHelp(command));
      values.push_back(*inlineValue);
    } else {
      for (int v = 0; v < spec->arity; ++v) {
        if (i + 1 >= args.size())
          throw UsageError("option " + key + " expects " + std::string(spec->metavar) +
                           seeHelp(command));
        values.push_back(args[++i]);
      }
    }
    parsed.options.emplace(key, std::move(values));
  }
  if (parsed.positional.size() < command.positional.size())
    throw UsageError(commandLabel(command) + ": missing " +
                     std::string(command.positional[parsed.positional.size()]) + seeHelp(command));
  if (parsed.positional.size() > command.positional.size())
    throw UsageError(commandLabel(command) + ": unexpected argument '" +
                     parsed.positional[command.positional.size()] + "'" + seeHelp(command));
  return parsed;
}

std::string formatHelp(const CommandSpec& command) {
  std::ostringstream os;
  os << "Usage: " << commandLabel(command);
  for (std::string_view p : command.positional) os << ' ' << p;
  if (!command.options.empty()) os << " [OPTIONS]";
  os << "\n\n" << command.summary << "\n";

  std::vector<std::pair<std::string, std::string_view>> rows;
  for (const OptionSpec& o : command.options) {
    std::string left = o.alias.empty() ? "    " : std::string(o.alias) + ", ";
    left += o.name;
    if (o.arity > 0) left += " " + std::string(o.metavar);
    rows.emplace_back(std::move(left), o.help);
  }
  rows.emplace_back("-h, --help", "show this help");
  std::size_t width = 0;
  for (const auto& [left, help] : rows) width = std::max(width, left.size());
  os << "\nOptions:\n";
  for (const auto& [left, help] : rows)
    os << "  " << left << std::string(width - left.size() + 2, ' ') << help << "\n";
  if (!command.details.empty()) os << "\n" << command.details;
  if (!command.details.empty() && !command.details.ends_with('\n')) os << "\n";
  return os.str();
}

}  // namespace rt::cli
