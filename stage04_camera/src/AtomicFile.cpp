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

/// A new, empty file in the directory of path, open for writing; removed again when the object
/// dies without commit() having renamed it over path.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& path) : path_(path) {
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    if (dir.empty()) dir = ".";
    // A short fixed pattern: a name derived from path's could exceed the file system's limit on
    // a name's length when path's own name is near it. mkstemp opens the file exclusively, so
    // two writers never share one.
    name_ = (dir / ".rt-tmp-XXXXXX").string();
    const int fd = ::mkstemp(name_.data());
    if (fd < 0) throwCannotWrite(path_, errnoText(errno));
    // mkstemp creates the file 0600; an image or a scene file is an ordinary document.
    ::fchmod(fd, 0644);
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

  /// Closes the file and renames it over path; reason, when not empty, is why filling it failed.
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
    if (std::rename(name_.c_str(), path_.c_str()) != 0) throwCannotWrite(path_, errnoText(errno));
    committed_ = true;
  }

 private:
  std::string path_;
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
