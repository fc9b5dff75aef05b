#include "bvh/HugePages.h"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace rt {

namespace {

// The advice this system's headers know, or -1 (Linux's MADV_POPULATE_WRITE since 5.14).
#if defined(__linux__) && defined(MADV_HUGEPAGE) && defined(MADV_NOHUGEPAGE)
constexpr int HUGE_ADVICE = MADV_HUGEPAGE;
constexpr int SMALL_ADVICE = MADV_NOHUGEPAGE;
#else
constexpr int HUGE_ADVICE = -1;
constexpr int SMALL_ADVICE = -1;
#endif
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
constexpr int POPULATE_ADVICE = MADV_POPULATE_WRITE;
#else
constexpr int POPULATE_ADVICE = -1;
#endif

/// madvise(2) on [first, last) of the process's own allocations: the advice changes how the
/// pages are backed, never what they hold. False when the range is empty, the advice unknown
/// here, or the system refused it (EINVAL where the kernel lacks it: ignored, a hint).
bool advise(std::uintptr_t first, std::uintptr_t last, [[maybe_unused]] int advice) noexcept {
  if (first >= last || advice < 0) return false;
#if defined(__linux__)
  return madvise(reinterpret_cast<void*>(first), last - first, advice) == 0;
#else
  return false;
#endif
}

/// The system's page size (4 KiB on x86-64 Linux).
std::uintptr_t pageBytes() noexcept {
#if defined(__linux__)
  return static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
#else
  return 4096;
#endif
}

}  // namespace

bool adviseHugePages(const void* data, std::size_t bytes) noexcept {
  const HugePageRange range = hugePageRange(reinterpret_cast<std::uintptr_t>(data), bytes);
  return advise(range.first, range.last, HUGE_ADVICE);
}

bool populatePages(const void* data, std::size_t bytes) noexcept {
  // Every page the range touches, the first and last partly: they belong to the same allocation.
  if (bytes == 0) return false;
  const std::uintptr_t page = pageBytes();
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  return advise(begin & ~(page - 1), (begin + bytes + page - 1) & ~(page - 1), POPULATE_ADVICE);
}

bool adviseSmallPages(const void* data, std::size_t bytes) noexcept {
  // The whole pages inside the range: a page shared with another allocation is left as it is.
  const std::uintptr_t page = pageBytes();
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  return advise((begin + page - 1) & ~(page - 1), (begin + bytes) & ~(page - 1), SMALL_ADVICE);
}

}  // namespace rt
