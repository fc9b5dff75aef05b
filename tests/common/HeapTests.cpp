// keepLargeBlocksOutOfTheHeap: large blocks come from the system and go back to it when freed.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>

#include "common/Heap.h"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

namespace rt {
namespace {

#if defined(__GLIBC__) && defined(M_MMAP_THRESHOLD) && !defined(__SANITIZE_ADDRESS__) && \
    !defined(__SANITIZE_THREAD__)
/// Bytes the process holds in blocks mapped from the system (glibc's count).
std::size_t mappedBytes() { return mallinfo2().hblkhd; }

TEST(HeapTests, aLargeBlockFreedIsGivenBackAndTheNextOneIsMappedAgain) {
  keepLargeBlocksOutOfTheHeap();
  // TC01: a 4 MiB block is mapped, and unmapped when freed
  constexpr std::size_t BIG = 4u << 20, NEXT = 1u << 20;
  const std::size_t before = mappedBytes();
  void* big = std::malloc(BIG);
  ASSERT_NE(big, nullptr);
  std::memset(big, 1, BIG);
  EXPECT_GE(mappedBytes(), before + BIG);
  std::free(big);
  EXPECT_EQ(mappedBytes(), before);
  // TC02: after it, a 1 MiB block is mapped too (glibc's default would have raised the
  // threshold to 4 MiB at the free above and carved this one out of the heap, to stay there)
  void* next = std::malloc(NEXT);
  ASSERT_NE(next, nullptr);
  EXPECT_GE(mappedBytes(), before + NEXT);
  std::free(next);
  EXPECT_EQ(mappedBytes(), before);
}
#else
TEST(HeapTests, aLargeBlockFreedIsGivenBackAndTheNextOneIsMappedAgain) {
  keepLargeBlocksOutOfTheHeap();  // a no-op here: nothing to observe
  GTEST_SKIP() << "glibc's own allocator only (not under a sanitizer's allocator)";
}
#endif

}  // namespace
}  // namespace rt
