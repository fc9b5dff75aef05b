#pragma once
// Internal to mini2's part of rt: where `rt bench`'s table goes (stdout, or each -o file) and in
// which format, chosen and checked before any work; and the machine's name for its caption.

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "BenchTable.h"
#include "camera/AtomicFile.h"
#include "cli/Commands.h"

namespace rt::cli {

struct BenchArgs;

/// Where the table goes: stdout, or each -o file, in its format.
struct Destinations {
  TableFormat stdoutFormat = TableFormat::Markdown;  ///< when there is no -o
  std::vector<std::pair<std::string, TableFormat>> files;
};

/// The table's destinations: stdout in --csv's or --json's format (Markdown without either), or
/// every -o file in its own (the flag's, whose ending the name must have, else its ending's),
/// each path checked writable and no two naming the same file ("x" and "./x", two hard links to
/// one file: sameFile). @throws UsageError.
Destinations chooseDestinations(const BenchArgs& args);

/// Prints the table, or writes it to each -o file (whole or not at all). format turns the
/// table into text in a format.
template <typename Format>
void emit(const Destinations& d, const Format& format, const Io& io) {
  if (d.files.empty()) {
    io.out << format(d.stdoutFormat) << std::flush;
    return;
  }
  for (const auto& [path, f] : d.files) {
    writeFileAtomically(path, format(f));
    io.err << "rt bench: wrote " << path << "\n";
  }
}

/// "AMD EPYC 7B13, 2 CPUs": /proc/cpuinfo's first model name and the CPUs std::thread sees.
std::string machineName();

}  // namespace rt::cli
