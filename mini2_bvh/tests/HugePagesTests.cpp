// mini2: the build's large arrays advised for 2 MiB pages (HugePages.h): which part of an array
// is advised, and that the advice, where the system takes it, marks exactly that part; and the
// parallel build's subtree arrays advised for small pages.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bvh/HugePages.h"

#if defined(__linux__)
#include <unistd.h>
#endif

namespace rt {
namespace {

constexpr std::uintptr_t MIB = std::uintptr_t{1} << 20;

TEST(HugePagesTests, rangeIsTheWholeAlignedPagesInside) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: an array that starts and ends on 2 MiB: all of it
  EXPECT_EQ(hugePageRange(4 * MIB, 4 * MIB).first, 4 * MIB);
  EXPECT_EQ(hugePageRange(4 * MIB, 4 * MIB).last, 8 * MIB);
  // TC02: an array off the 2 MiB grid at both ends: the whole pages inside it
  EXPECT_EQ(hugePageRange(4 * MIB + 16, 6 * MIB).first, 6 * MIB);
  EXPECT_EQ(hugePageRange(4 * MIB + 16, 6 * MIB).last, 10 * MIB);
  // TC03: a small array: nothing
  const HugePageRange small = hugePageRange(4 * MIB + 4096, 64 * 1024);
  EXPECT_EQ(small.first, small.last);
  // =============== Boundary Values Tests ==================
  // TC11: one byte short of a whole page inside: nothing
  const HugePageRange shy = hugePageRange(4 * MIB + 1, 4 * MIB - 2);
  EXPECT_EQ(shy.first, 6 * MIB);
  EXPECT_EQ(shy.last, 6 * MIB);
  // TC12: exactly one whole page inside
  EXPECT_EQ(hugePageRange(4 * MIB + 1, 4 * MIB - 1).first, 6 * MIB);
  EXPECT_EQ(hugePageRange(4 * MIB + 1, 4 * MIB - 1).last, 8 * MIB);
  // TC13: no bytes: nothing
  EXPECT_EQ(hugePageRange(2 * MIB, 0).first, hugePageRange(2 * MIB, 0).last);
}

TEST(HugePagesTests, reserveHugeReservesAndKeepsTheElements) {
  // TC01: a fresh vector: at least the capacity asked for
  std::vector<double> v;
  reserveHuge(v, 1'000'000);
  EXPECT_GE(v.capacity(), 1'000'000u);
  EXPECT_TRUE(v.empty());
  // TC02: a vector with elements: they are kept through the reallocation
  std::vector<int> w{1, 2, 3};
  reserveHuge(w, 2'000'000);
  EXPECT_GE(w.capacity(), 2'000'000u);
  EXPECT_EQ(w, (std::vector<int>{1, 2, 3}));
  // TC11: a capacity that suffices: no reallocation, the same storage
  const int* before = w.data();
  reserveHuge(w, 10);
  EXPECT_EQ(w.data(), before);
}

TEST(HugePagesTests, nothingToAdviseInASmallArray) {
  // TC01: 4 KiB hold no whole 2 MiB page wherever they lie
  const std::vector<char> small(4096);
  EXPECT_FALSE(adviseHugePages(small.data(), small.size()));
  // TC11: nothing at all
  EXPECT_FALSE(adviseHugePages(small.data(), 0));
}

#if defined(__linux__)
/// Calls visit(lo, hi, line) for each line of /proc/self/smaps that describes the mapping
/// [lo, hi) (its fields after the header line).
template <typename Visit>
void forEachMappingLine(const Visit& visit) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  std::uintptr_t lo = 0, hi = 0;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-') {
      lo = begin;
      hi = end;
      continue;
    }
    visit(lo, hi, line);
  }
}

/// The VmFlags of the mapping that starts at address `start` in /proc/self/smaps, or "".
std::string mappingFlags(std::uintptr_t start) {
  std::string flags;
  forEachMappingLine([&](std::uintptr_t lo, std::uintptr_t, const std::string& line) {
    if (lo == start && line.rfind("VmFlags:", 0) == 0) flags = line;
  });
  return flags;
}

/// The resident KiB of the mappings that overlap [lo, hi) in /proc/self/smaps.
long residentKiB(std::uintptr_t lo, std::uintptr_t hi) {
  long kib = 0;
  forEachMappingLine([&](std::uintptr_t begin, std::uintptr_t end, const std::string& line) {
    if (begin < hi && lo < end && line.rfind("Rss:", 0) == 0) kib += std::stol(line.substr(4));
  });
  return kib;
}

TEST(HugePagesTests, theAdvisedPagesAreMarkedOnLinux) {
  // TC01: 8 MiB of fresh pages: where the kernel takes the advice, the mapping that starts at
  // the first whole 2 MiB page carries the flag "hg" (and the array is still usable)
  std::vector<char> big;
  big.reserve(8 * MIB);
  const HugePageRange range = hugePageRange(reinterpret_cast<std::uintptr_t>(big.data()), 8 * MIB);
  ASSERT_LT(range.first, range.last);
  if (!adviseHugePages(big.data(), 8 * MIB))
    GTEST_SKIP() << "this kernel has no transparent huge pages (madvise refused the advice)";
  EXPECT_NE(mappingFlags(range.first).find(" hg"), std::string::npos) << mappingFlags(range.first);
  big.assign(8 * MIB, 'x');
  EXPECT_EQ(big[8 * MIB - 1], 'x');
}

TEST(HugePagesTests, theWrittenArraysPagesAreMadeAtOnceOnLinux) {
  // TC01: 16 MiB reserved to be written whole: before any element is written, its pages are
  // resident (where the kernel has MADV_POPULATE_WRITE), and the array keeps its elements
  std::vector<std::uint64_t> v{5, 6};
  reserveHugeWritten(v, 2 * MIB);  // 16 MiB
  ASSERT_GE(v.capacity(), 2 * MIB);
  EXPECT_EQ(v, (std::vector<std::uint64_t>{5, 6}));
  const auto lo = reinterpret_cast<std::uintptr_t>(v.data());
  const long resident = residentKiB(lo, lo + 16 * MIB);  // before anything else touches them
  if (!populatePages(v.data(), 2 * MIB * sizeof(std::uint64_t)))  // again: nothing changes
    GTEST_SKIP() << "this kernel cannot populate pages (MADV_POPULATE_WRITE, Linux 5.14)";
  EXPECT_GE(resident, 16 * 1024);
  EXPECT_EQ(v, (std::vector<std::uint64_t>{5, 6}));
  // TC11: nothing to make
  EXPECT_FALSE(populatePages(v.data(), 0));
}

TEST(HugePagesTests, theSmallPagesAdviceMarksTheWholeArrayOnLinux) {
  // TC01: 8 MiB reserved for small pages: the mapping that starts at the array's first whole 4
  // KiB page carries the flag "nh" (no huge pages), the array keeps its elements and is usable
  std::vector<int> v{1, 2, 3};
  reserveSmall(v, 2 * MIB);  // 8 MiB of ints
  ASSERT_EQ(v.capacity(), 2 * MIB);
  EXPECT_EQ(v, (std::vector<int>{1, 2, 3}));
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto data = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t first = (data + page - 1) & ~(page - 1);
  if (!adviseSmallPages(v.data(), v.capacity() * sizeof(int)))  // again: the same advice
    GTEST_SKIP() << "this kernel has no transparent huge pages (madvise refused the advice)";
  EXPECT_NE(mappingFlags(first).find(" nh"), std::string::npos) << mappingFlags(first);
  v.assign(2 * MIB, 7);
  EXPECT_EQ(v[2 * MIB - 1], 7);
  // TC11: nothing to advise in less than one whole page
  const std::vector<char> small(100);
  EXPECT_FALSE(adviseSmallPages(small.data(), small.size()));
}
#endif

}  // namespace
}  // namespace rt
