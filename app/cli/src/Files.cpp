// Output paths: the check before a render starts, and the temporary-file-and-rename write.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "cli/ArgParser.h"
#include "cli/Commands.h"

namespace rt::cli {

namespace fs = std::filesystem;

namespace {

fs::path directoryOf(const fs::path& path) {
  const fs::path dir = path.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

/// Creates a unique file in dir from a template; returns its descriptor (or -1, errno set) and
/// stores its name in name.
int makeTempFile(const fs::path& dir, const std::string& stem, std::string& name) {
  name = (dir / ("." + stem + ".rt-tmp-XXXXXX")).string();
  return ::mkstemp(name.data());
}

}  // namespace

void checkOutputWritable(const std::string& path, std::string_view what) {
  const std::string prefix = std::string(what) + ": cannot write '" + path + "': ";
  const fs::path p(path);
  if (path.empty() || !p.has_filename()) throw UsageError(prefix + "it names no file");
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw UsageError(prefix + "it is a directory");
  const fs::path dir = directoryOf(p);
  const fs::file_status st = fs::status(dir, ec);
  if (!fs::exists(st))
    throw UsageError(prefix + "the directory '" + dir.string() + "' does not exist");
  if (!fs::is_directory(st)) throw UsageError(prefix + "'" + dir.string() + "' is not a directory");
  // Permissions, read-only file systems, ACLs, root: only creating a file tells for sure.
  std::string probe;
  const int fd = makeTempFile(dir, "probe", probe);
  if (fd < 0) throw UsageError(prefix + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

void writeFileAtomically(const std::string& path, std::string_view text) {
  const fs::path p(path);
  std::string temp;
  const int fd = makeTempFile(directoryOf(p), p.filename().string(), temp);
  if (fd < 0) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  const int writeErrno = errno;
  const bool closed = ::close(fd) == 0;
  if (written != text.size() || !closed) {
    ::unlink(temp.c_str());
    throw std::runtime_error("cannot write '" + path +
                             "': " + std::strerror(written != text.size() ? writeErrno : errno));
  }
  // mkstemp creates the file 0600; a scene file is an ordinary document.
  ::chmod(temp.c_str(), 0644);
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int renameErrno = errno;
    ::unlink(temp.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(renameErrno));
  }
}

}  // namespace rt::cli
