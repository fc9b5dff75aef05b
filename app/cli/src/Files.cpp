// Output paths: the check before any work starts, and whether two paths name one file. (The
// write itself is stage04's writeFileAtomically, which the PNG writer uses too.)
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

#include "camera/AtomicFile.h"
#include "cli/CommandLine.h"
#include "cli/Commands.h"

namespace rt::cli {

namespace fs = std::filesystem;

namespace {

/// The file path names, when it may not exist yet: its absolute path with the symbolic links of
/// the part that exists resolved and the rest lexically normal. (Made absolute first: a relative
/// path none of which exists, "x" for a new file, would stay relative. One the system cannot
/// resolve, through a directory it may not search say, is made absolute and normal only.)
fs::path fileNamed(const std::string& path) {
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  if (error) return fs::path(path).lexically_normal();  // no current directory
  if (fs::path file = fs::weakly_canonical(absolute, error); !error) return file;
  return absolute.lexically_normal();
}

}  // namespace

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

bool sameFile(const std::string& x, const std::string& y) {
  std::error_code ec;
  // Both there: the file itself, so that two hard links to it are one.
  if (fs::exists(x, ec) && fs::exists(y, ec)) {
    const bool same = fs::equivalent(x, y, ec);
    if (!ec) return same;
  }
  // One yet to be made (or one the system cannot look at): the names.
  return fileNamed(x) == fileNamed(y);
}

}  // namespace rt::cli
