// Where `rt bench`'s table goes and in which format: stdout or each -o file, checked before any
// work; and the machine's name for the caption.
#include "BenchOutput.h"

#include <algorithm>
#include <fstream>
#include <optional>
#include <thread>

#include "Bench.h"

namespace rt::cli {

namespace {

/// A format's file ending, and the rule a file named with another breaks when the format is
/// asked for by its flag.
OutputKind outputKindOf(TableFormat format) {
  switch (format) {
    case TableFormat::Csv:
      return {".csv", "--csv writes CSV, so the name must end in .csv"};
    case TableFormat::Json:
      return {".json", "--json writes JSON, so the name must end in .json"};
    case TableFormat::Markdown:
      break;
  }
  return {".md", "Markdown is the default, so the name must end in .md"};
}

/// The format of one -o file: the flag's (its ending must agree), else its ending's; the path
/// checked writable before any work. @throws UsageError.
TableFormat fileFormat(const std::string& path, std::optional<TableFormat> flag) {
  if (flag) {
    checkOutputWritable(path, outputKindOf(*flag));
    return *flag;
  }
  for (const TableFormat f : {TableFormat::Markdown, TableFormat::Csv, TableFormat::Json}) {
    const OutputKind kind = outputKindOf(f);
    if (path.ends_with(kind.ending)) {
      checkOutputWritable(path, kind);
      return f;
    }
  }
  // A directory, a missing parent, or the ending: checkOutputWritable names what is wrong.
  checkOutputWritable(path, {".md",
                             "the table's format follows the name's ending, which must be .md "
                             "(Markdown), .csv or .json"});
  return TableFormat::Markdown;  // not reached: the path does not end in .md
}

}  // namespace

Destinations chooseDestinations(const BenchArgs& args) {
  if (args.csv && args.json)
    throw UsageError("--csv and --json: give one of them (Markdown without either)");
  const std::optional<TableFormat> flag = args.csv    ? std::optional(TableFormat::Csv)
                                          : args.json ? std::optional(TableFormat::Json)
                                                      : std::nullopt;
  Destinations d;
  d.stdoutFormat = flag.value_or(TableFormat::Markdown);
  // One table a run: a file named twice ("x" and "./x", two hard links to it) would be written
  // twice.
  for (const std::string& path : args.outputs) {
    const TableFormat format = fileFormat(path, flag);
    for (const auto& file : d.files) {
      const std::string& earlier = file.first;
      if (sameFile(earlier, path))
        throw UsageError(earlier == path
                             ? "-o: '" + path + "' is given twice"
                             : "-o: '" + earlier + "' and '" + path + "' name the same file");
    }
    d.files.emplace_back(path, format);
  }
  return d;
}

std::string machineName() {
  std::string model;
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; model.empty() && std::getline(in, line);) {
    if (!line.starts_with("model name")) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    model = line.substr(line.find_first_not_of(" \t", colon + 1));
  }
  if (model.empty()) model = "unknown CPU";
  const unsigned cpus = std::max(1u, std::thread::hardware_concurrency());
  return model + ", " + std::to_string(cpus) + (cpus == 1 ? " CPU" : " CPUs");
}

}  // namespace rt::cli
