// writeFileAtomically and checkTemporaryFileBeside (camera/AtomicFile.h). Files are written under
// the build directory (the tests' working directory), in test-images/stage04/atomic-*/.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "TestFiles.h"
#include "camera/AtomicFile.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

/// A fresh, empty directory for one test: test-images/stage04/atomic-NAME.
fs::path testDir(const std::string& name) { return test::testDir("atomic-" + name); }
using test::entries;
using test::readFile;

/// The message of the std::runtime_error that f throws, or "(no error)".
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

/// The permission bits of the file at p (through any symbolic link), or -1 when it has none.
int modeOf(const fs::path& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 ? static_cast<int>(st.st_mode & 0777) : -1;
}

/// What the symbolic link at p points to, or "(not a link)".
std::string linkTarget(const fs::path& p) {
  std::error_code ec;
  const fs::path target = fs::read_symlink(p, ec);
  return ec ? "(not a link)" : target.string();
}

TEST(AtomicFileTests, writeFileAtomicallyWritesTheWholeContent) {
  const fs::path dir = testDir("write");
  const std::string path = (dir / "a.json").string();
  // ============ Equivalence Partitions Tests ==============
  // TC01: a new file gets the bytes, mode 0644 (not mkstemp's 0600), and no temporary file
  // remains
  writeFileAtomically(path, std::string_view("{}\n"));
  EXPECT_EQ(readFile(path), "{}\n");
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
  EXPECT_EQ(entries(dir), 1u);
  // TC02: an existing file is replaced whole, by a shorter content
  writeFileAtomically(path, std::string_view("1"));
  EXPECT_EQ(readFile(path), "1");
  EXPECT_EQ(entries(dir), 1u);
  // TC03: content written by a fill function, in pieces
  writeFileAtomically(path, [](std::FILE* f) -> std::string {
    std::fputs("ab", f);
    std::fputs("cd", f);
    return {};
  });
  EXPECT_EQ(readFile(path), "abcd");
  // TC04: a bare file name is written in the current directory (the build tree)
  const std::string bare = "rt-atomic-file-test.txt";
  writeFileAtomically(bare, std::string_view("here"));
  EXPECT_EQ(readFile(bare), "here");
  fs::remove(bare);
  // =============== Boundary Values Tests ==================
  // TC11: empty content gives an empty file
  writeFileAtomically(path, std::string_view(""));
  EXPECT_TRUE(fs::exists(path));
  EXPECT_EQ(fs::file_size(path), 0u);
}

TEST(AtomicFileTests, writeFileAtomicallyFailsWithoutTouchingTheFile) {
  const fs::path dir = testDir("failure");
  const std::string path = (dir / "kept.txt").string();
  std::ofstream(path) << "old";
  // ============ Equivalence Partitions Tests ==============
  // TC01: fill reports a failure: the error names the path and the reason, the old content
  // stays, the temporary file is removed
  EXPECT_EQ(errorOf([&] {
              writeFileAtomically(path, [](std::FILE* f) -> std::string {
                std::fputs("half", f);
                return "encoding failed";
              });
            }),
            "cannot write '" + path + "': encoding failed");
  EXPECT_EQ(readFile(path), "old");
  EXPECT_EQ(entries(dir), 1u);
  // TC02: fill throws: the exception passes through, and the same holds
  EXPECT_THROW(writeFileAtomically(
                   path, [](std::FILE*) -> std::string { throw std::logic_error("from fill"); }),
               std::logic_error);
  EXPECT_EQ(readFile(path), "old");
  EXPECT_EQ(entries(dir), 1u);
  // TC03: the directory does not exist, and is not created
  const std::string missing = (dir / "no-such-dir" / "out.txt").string();
  EXPECT_EQ(errorOf([&] { writeFileAtomically(missing, std::string_view("x")); }),
            "cannot write '" + missing + "': No such file or directory");
  EXPECT_FALSE(fs::exists(dir / "no-such-dir"));
  // TC04: the path is an existing directory: the rename fails, the directory and its content
  // are untouched, no temporary file remains
  const fs::path occupied = dir / "occupied";
  fs::create_directories(occupied);
  std::ofstream(occupied / "keep.txt") << "keep";
  EXPECT_EQ(errorOf([&] { writeFileAtomically(occupied.string(), std::string_view("x")); }),
            "cannot write '" + occupied.string() + "': Is a directory");
  EXPECT_EQ(readFile(occupied / "keep.txt"), "keep");
  EXPECT_EQ(entries(dir), 2u);  // kept.txt and occupied/
  EXPECT_EQ(entries(occupied), 1u);
  // TC05: a parent component is a regular file
  EXPECT_EQ(errorOf([&] { writeFileAtomically(path + "/out.txt", std::string_view("x")); }),
            "cannot write '" + path + "/out.txt': Not a directory");
  EXPECT_EQ(readFile(path), "old");
}

TEST(AtomicFileTests, checkTemporaryFileBeside) {
  const fs::path dir = testDir("check");
  // ============ Equivalence Partitions Tests ==============
  // TC01: a writable directory: no error, and nothing left behind
  EXPECT_EQ(errorOf([&] { checkTemporaryFileBeside((dir / "new.png").string()); }), "(no error)");
  EXPECT_EQ(entries(dir), 0u);
  // TC02: a directory that does not exist
  const std::string missing = (dir / "missing" / "new.png").string();
  EXPECT_EQ(errorOf([&] { checkTemporaryFileBeside(missing); }),
            "cannot write '" + missing + "': No such file or directory");
  // =============== Boundary Values Tests ==================
  // TC11: a directory where no file can be created, even by root (/proc)
  if (!fs::exists("/proc/version")) GTEST_SKIP() << "needs Linux /proc";
  EXPECT_NE(errorOf([] {
              checkTemporaryFileBeside("/proc/version");
            }).find("cannot write '/proc/version': "),
            std::string::npos);
}

TEST(AtomicFileTests, writeFileAtomicallyWritesThroughSymbolicLinks) {
  const fs::path dir = testDir("links");
  const fs::path renders = dir / "renders";
  const fs::path out = dir / "out";
  fs::create_directories(renders);
  fs::create_directories(out);
  const fs::path real = renders / "real.png";
  std::ofstream(real) << "old content";
  // ============ Equivalence Partitions Tests ==============
  // TC01: a link with a relative target, into another directory: the target relative to the
  // link's directory (not the working directory) gets the bytes, the link stays a link to it,
  // and no temporary file remains in either directory
  const fs::path link = out / "link.png";
  fs::create_symlink("../renders/real.png", link);
  writeFileAtomically(link.string(), std::string_view("new"));
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(linkTarget(link), "../renders/real.png");
  EXPECT_EQ(readFile(real), "new");
  EXPECT_EQ(entries(renders), 1u);
  EXPECT_EQ(entries(out), 1u);
  // TC02: a link with an absolute target
  const fs::path absolute = out / "absolute.png";
  fs::create_symlink(fs::absolute(real), absolute);
  writeFileAtomically(absolute.string(), std::string_view("absolute"));
  EXPECT_TRUE(fs::is_symlink(absolute));
  EXPECT_EQ(readFile(real), "absolute");
  EXPECT_EQ(entries(renders), 1u);
  // TC03: a chain of two links: both stay links, the file at the end gets the bytes
  const fs::path chain = dir / "chain.png";
  fs::create_symlink("out/link.png", chain);
  writeFileAtomically(chain.string(), std::string_view("through two links"));
  EXPECT_TRUE(fs::is_symlink(chain));
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(readFile(real), "through two links");
  EXPECT_EQ(entries(renders), 1u);
  EXPECT_EQ(entries(out), 2u);  // link.png and absolute.png
  // TC04: a dangling link creates its target (as cp does), mode 0644, and stays a link
  const fs::path dangling = out / "dangling.png";
  fs::create_symlink("../renders/new.png", dangling);
  writeFileAtomically(dangling.string(), std::string_view("created"));
  EXPECT_TRUE(fs::is_symlink(dangling));
  EXPECT_EQ(readFile(renders / "new.png"), "created");
  EXPECT_EQ(modeOf(renders / "new.png"), 0644);
  EXPECT_EQ(entries(renders), 2u);
  // TC05: checkTemporaryFileBeside accepts a link to a writable file and leaves both alone
  EXPECT_EQ(errorOf([&] { checkTemporaryFileBeside(link.string()); }), "(no error)");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(readFile(real), "through two links");
  EXPECT_EQ(entries(renders), 2u);
  // =============== Boundary Values Tests ==================
  // TC11: a dangling link into a directory that does not exist: refused, the error names the
  // link, the link stays, and the probe is made in the target's directory too (the link's own
  // directory is writable)
  const fs::path nowhere = out / "nowhere.png";
  fs::create_symlink("../missing/x.png", nowhere);
  EXPECT_EQ(errorOf([&] { writeFileAtomically(nowhere.string(), std::string_view("x")); }),
            "cannot write '" + nowhere.string() + "': No such file or directory");
  EXPECT_EQ(errorOf([&] { checkTemporaryFileBeside(nowhere.string()); }),
            "cannot write '" + nowhere.string() + "': No such file or directory");
  EXPECT_TRUE(fs::is_symlink(nowhere));
  EXPECT_EQ(entries(out), 4u);  // link, absolute, dangling, nowhere
  // TC12: a link to itself (a loop) is refused, and stays
  const fs::path loop = out / "loop.png";
  fs::create_symlink("loop.png", loop);
  EXPECT_EQ(errorOf([&] { writeFileAtomically(loop.string(), std::string_view("x")); }),
            "cannot write '" + loop.string() + "': Too many levels of symbolic links");
  EXPECT_TRUE(fs::is_symlink(loop));
  EXPECT_EQ(entries(out), 5u);
}

TEST(AtomicFileTests, writeFileAtomicallyKeepsTheReplacedFilesPermissions) {
  const fs::path dir = testDir("modes");
  // ============ Equivalence Partitions Tests ==============
  // TC01: an existing 0600 file stays 0600 (not reset to 0644), with the new bytes
  const fs::path secret = dir / "secret.json";
  std::ofstream(secret) << "old";
  fs::permissions(secret, static_cast<fs::perms>(0600));
  writeFileAtomically(secret.string(), std::string_view("new"));
  EXPECT_EQ(readFile(secret), "new");
  EXPECT_EQ(modeOf(secret), 0600);
  // TC02: an existing group-writable 0664 file stays 0664
  const fs::path shared = dir / "shared.png";
  std::ofstream(shared) << "old";
  fs::permissions(shared, static_cast<fs::perms>(0664));
  writeFileAtomically(shared.string(), std::string_view("new"));
  EXPECT_EQ(modeOf(shared), 0664);
  // TC03: through a symbolic link, the target's permissions are kept, and the link stays
  const fs::path link = dir / "link.json";
  fs::create_symlink("secret.json", link);
  writeFileAtomically(link.string(), std::string_view("linked"));
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(readFile(secret), "linked");
  EXPECT_EQ(modeOf(secret), 0600);
  // TC04: a new file is 0644 whatever the umask (an explicit fchmod, which the umask does not
  // limit)
  const mode_t saved = ::umask(077);
  writeFileAtomically((dir / "new.png").string(), std::string_view("new"));
  ::umask(saved);
  EXPECT_EQ(modeOf(dir / "new.png"), 0644);
  EXPECT_EQ(entries(dir), 4u);
  // TC05: root may write a read-only file, as cp and a shell's `>` may; it stays 0444. (For
  // anyone else, writeFileAtomicallyRefusesAReadOnlyFile.)
  if (::geteuid() == 0) {
    const fs::path readOnly = dir / "read-only.txt";
    std::ofstream(readOnly) << "old";
    fs::permissions(readOnly, static_cast<fs::perms>(0444));
    writeFileAtomically(readOnly.string(), std::string_view("root's"));
    EXPECT_EQ(readFile(readOnly), "root's");
    EXPECT_EQ(modeOf(readOnly), 0444);
  }
}

TEST(AtomicFileTests, writeFileAtomicallyRefusesAReadOnlyFile) {
  if (::geteuid() == 0)
    GTEST_SKIP() << "running as root, who may write a read-only file (as cp may); "
                    "writeFileAtomicallyKeepsTheReplacedFilesPermissions checks that";
  const fs::path dir = testDir("read-only");
  const fs::path path = dir / "kept.png";
  std::ofstream(path) << "old";
  fs::permissions(path, static_cast<fs::perms>(0444));
  // ============ Equivalence Partitions Tests ==============
  // TC01: refused with the system's reason; the file keeps its bytes and mode, and no
  // temporary file remains
  EXPECT_EQ(errorOf([&] { writeFileAtomically(path.string(), std::string_view("new")); }),
            "cannot write '" + path.string() + "': Permission denied");
  EXPECT_EQ(readFile(path), "old");
  EXPECT_EQ(modeOf(path), 0444);
  EXPECT_EQ(entries(dir), 1u);
  // TC02: the probe before a render refuses it too
  EXPECT_EQ(errorOf([&] { checkTemporaryFileBeside(path.string()); }),
            "cannot write '" + path.string() + "': Permission denied");
  EXPECT_EQ(entries(dir), 1u);
  // TC03: through a symbolic link: the message names the link, as the user gave it
  const fs::path link = dir / "link.png";
  fs::create_symlink("kept.png", link);
  EXPECT_EQ(errorOf([&] { writeFileAtomically(link.string(), std::string_view("new")); }),
            "cannot write '" + link.string() + "': Permission denied");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(readFile(path), "old");
  EXPECT_EQ(entries(dir), 2u);
}

}  // namespace
}  // namespace rt
