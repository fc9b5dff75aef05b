#include "camera/AtomicFile.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace rt {

namespace {

[[noreturn]] void throwCannotWrite(const std::string& path, const std::string& reason) {
  throw std::runtime_error("cannot write '" + path + "': " + reason);
}

std::string errnoText(int err) { return std::strerror(err != 0 ? err : EIO); }

/// How many symbolic links a chain may have before it is taken for a loop: Linux's own limit
/// (MAXSYMLINKS), so a chain the system would open is followed here too.
constexpr int kMaxLinks = 40;

/// The file that writing path should replace: path itself, or, when path is a symbolic link,
/// the file at the end of its chain of links. Renaming over the link would replace the link
/// with a regular file and leave the file it points to as it was; `cp` and editors write
/// through it instead. The end of the chain need not exist (a dangling link creates its
/// target). Only the last component is followed: links among the directories are resolved by
/// the system on its own when the file is created and renamed.
std::string followLinks(const std::string& path) {
  std::filesystem::path file(path);
  for (int links = 0;; ++links) {
    struct stat st {};
    // No entry (a new file, a dangling link) or an unusable directory: creating the temporary
    // file reports the latter, with the system's reason.
    if (::lstat(file.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return file.string();
    if (links == kMaxLinks) throwCannotWrite(path, errnoText(ELOOP));
    std::error_code ec;
    const std::filesystem::path target = std::filesystem::read_symlink(file, ec);
    if (ec) throwCannotWrite(path, ec.message());
    // A relative target is relative to the link's directory; an absolute one replaces it
    // (operator/). Not normalized: ".." must go up from the directory the system finds, which
    // may itself be reached through a link.
    file = file.parent_path() / target;
  }
}

/// The permission bits a new file at target gets, or a throw when target exists and the user
/// may not write it. The rename would replace a read-only file anyway (it needs only the
/// directory's permission), so the refusal is made here, as `cp` or a shell's `>` would refuse
/// to open it. access(2) decides as open(2) would for this user (not from the mode bits alone):
/// root may write a 0444 file with `cp`, and so it may here.
mode_t modeFor(const std::string& path, const std::string& target) {
  struct stat st {};
  // A new file: mkstemp would leave it 0600, but an image or a scene file is an ordinary
  // document.
  if (::stat(target.c_str(), &st) != 0) return 0644;
  if (::access(target.c_str(), W_OK) != 0 && errno != ENOENT)
    throwCannotWrite(path, errnoText(errno));
  // A replaced file keeps its permission bits (a private 0600 file stays private), though not
  // set-user-ID and the like; anything else (a directory) is refused by the rename, with its
  // own reason.
  return S_ISREG(st.st_mode) ? (st.st_mode & 0777) : 0644;
}

/// A new, empty file in the directory of the file that path names (through any symbolic links),
/// open for writing; removed again when the object dies without commit() having renamed it over
/// that file.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& path) : path_(path), target_(followLinks(path)) {
    const mode_t mode = modeFor(path_, target_);
    // Beside the target, not the link: a rename works only within one file system.
    std::filesystem::path dir = std::filesystem::path(target_).parent_path();
    if (dir.empty()) dir = ".";
    // A short fixed pattern: a name derived from path's could exceed the file system's limit on
    // a name's length when path's own name is near it. mkstemp opens the file exclusively, so
    // two writers never share one.
    name_ = (dir / ".rt-tmp-XXXXXX").string();
    const int fd = ::mkstemp(name_.data());
    if (fd < 0) throwCannotWrite(path_, errnoText(errno));
    ::fchmod(fd, mode);
    file_ = ::fdopen(fd, "wb");
    if (file_ == nullptr) {
      const int err = errno;
      ::close(fd);
      ::unlink(name_.c_str());
      throwCannotWrite(path_, errnoText(err));
    }
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (file_ != nullptr) std::fclose(file_);
    if (!committed_) ::unlink(name_.c_str());
  }

  std::FILE* file() const { return file_; }

  /// Closes the file and renames it over the target; reason, when not empty, is why filling it
  /// failed.
  void commit(std::string reason) {
    // The stream's error flag catches an fwrite that failed unnoticed, fflush and fclose the
    // data still buffered (a full disk is often reported only there).
    if (reason.empty() && (std::fflush(file_) != 0 || std::ferror(file_)))
      reason = errnoText(errno);
    const int closed = std::fclose(file_);
    const int closeErrno = errno;
    file_ = nullptr;
    if (reason.empty() && closed != 0) reason = errnoText(closeErrno);
    if (!reason.empty()) throwCannotWrite(path_, reason);
    if (std::rename(name_.c_str(), target_.c_str()) != 0) throwCannotWrite(path_, errnoText(errno));
    committed_ = true;
  }

 private:
  std::string path_;    // as the caller gave it, for the messages
  std::string target_;  // the file replaced: path_ with its symbolic links followed
  std::string name_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

}  // namespace

void writeFileAtomically(const std::string& path,
                         const std::function<std::string(std::FILE*)>& fill) {
  TemporaryFile temp(path);
  errno = 0;
  std::string reason = fill(temp.file());
  temp.commit(std::move(reason));
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
  writeFileAtomically(path, [bytes](std::FILE* file) -> std::string {
    // A short count leaves the stream's error flag set, which commit() reports.
    std::fwrite(bytes.data(), 1, bytes.size(), file);
    return {};
  });
}

void checkTemporaryFileBeside(const std::string& path) { TemporaryFile probe(path); }

}  // namespace rt
