// Output paths: the check before any work starts, whether two paths name one file, and an output
// that would overwrite a file its scene reads. (The write itself is stage04's
// writeFileAtomically, which the PNG writer uses too.)
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

#include "camera/AtomicFile.h"
#include "cli/CommandLine.h"
#include "cli/Commands.h"
#include "scenefile/MeshDocument.h"

namespace rt::cli {

namespace fs = std::filesystem;

namespace {

/// How many symbolic links a chain may have before it is taken for a loop: Linux's own limit
/// (MAXSYMLINKS), as writeFileAtomically's.
constexpr int kMaxLinks = 40;

/// path with the symbolic links at its end followed, as writing it follows them
/// (writeFileAtomically writes through a link, and a dangling one creates its target): a chain
/// too, a relative target starting from its link's folder. A loop ends after kMaxLinks links.
fs::path throughLinks(fs::path path) {
  for (int links = 0; links < kMaxLinks; ++links) {
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(path, error))) return path;
    const fs::path target = fs::read_symlink(path, error);
    if (error) return path;
    path = path.parent_path() / target;  // an absolute target replaces the folder
  }
  return path;
}

/// The file path names, when it may not exist yet: its absolute path with the symbolic links at
/// its end followed (throughLinks), those of the part that exists resolved and the rest
/// lexically normal. (Made absolute first: a relative path none of which exists, "x" for a new
/// file, would stay relative. One the system cannot resolve, through a directory it may not
/// search say, is made absolute and normal only.)
fs::path fileNamed(const std::string& path) {
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  if (error) return fs::path(path).lexically_normal();  // no current directory
  const fs::path followed = throughLinks(absolute);
  if (fs::path file = fs::weakly_canonical(followed, error); !error) return file;
  return followed.lexically_normal();
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
  // One yet to be made (or one the system cannot look at): the names, through their links.
  return fileNamed(x) == fileNamed(y);
}

void checkOutputIsNoInput(const std::string& output, std::string_view what,
                          std::string_view written, std::string_view scene,
                          const SceneDocument& doc) {
  // An input that is not there is not overwritten (a rank of rt-mpi reads it from memory).
  const auto overwrites = [&](const std::string& input) {
    std::error_code ec;
    return fs::exists(input, ec) && sameFile(output, input);
  };
  const std::string prefix = std::string(what) + ": '" + output + "' is ";
  const std::string advice = "; give another file";
  if (!isSceneFileArgument(scene)) return;  // a built-in scene reads no file
  if (overwrites(std::string(scene)))
    throw UsageError(prefix + "SCENE ('" + std::string(scene) + "'): " + std::string(written) +
                     " would overwrite the scene file it reads" + advice);
  for (const MeshEntry& entry : meshEntries(doc).entries) {
    if (!entry.model) continue;
    // The path as the scene read it: relative to the scene file's folder.
    const fs::path given(entry.model->file);
    const std::string read =
        given.is_absolute() ? given.string() : (fs::path(scene).parent_path() / given).string();
    if (overwrites(read))
      throw UsageError(prefix + "a model file of SCENE ('" + read + "'): " + std::string(written) +
                       " would overwrite a file the scene reads" + advice);
  }
}

}  // namespace rt::cli
