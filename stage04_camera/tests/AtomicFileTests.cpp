// writeFileAtomically and checkTemporaryFileBeside (camera/AtomicFile.h). Files are written under
// the build directory (the tests' working directory), in test-images/stage04/atomic-*/.

#include <gtest/gtest.h>
#include <sys/stat.h>

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

}  // namespace
}  // namespace rt
