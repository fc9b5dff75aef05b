// Output paths: the check before any work starts. (The write itself is stage04's
// writeFileAtomically, which the PNG writer uses too.)
#include <filesystem>
#include <stdexcept>
#include <string>

#include "camera/AtomicFile.h"
#include "cli/CommandLine.h"
#include "cli/Commands.h"

namespace rt::cli {

namespace fs = std::filesystem;

void checkOutputWritable(const std::string& path, const OutputKind& kind, std::string_view what) {
  const std::string prefix = std::string(what) + ": cannot write '" + path + "': ";
  const fs::path p(path);
  std::error_code ec;
  // A directory first: `-o images` says what is wrong with it, not that it lacks ".png".
  if (!path.empty() && fs::is_directory(p, ec)) throw UsageError(prefix + "it is a directory");
  if (path.empty() || !p.has_filename()) throw UsageError(prefix + "it names no file");
  if (!path.ends_with(kind.ending))
    throw UsageError(std::string(what) + ": " + std::string(kind.rule) + "; got '" + path + "'");
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  const fs::file_status st = fs::status(dir, ec);
  if (!fs::exists(st))
    throw UsageError(prefix + "the directory '" + dir.string() + "' does not exist");
  if (!fs::is_directory(st)) throw UsageError(prefix + "'" + dir.string() + "' is not a directory");
  // Permissions, read-only file systems, ACLs, root: only creating a file tells for sure.
  try {
    checkTemporaryFileBeside(path);
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string(what) + ": " + e.what());
  }
}

}  // namespace rt::cli
