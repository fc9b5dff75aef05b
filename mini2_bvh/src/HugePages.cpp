#include "bvh/HugePages.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rt {

bool adviseHugePages(const void* data, std::size_t bytes) noexcept {
  const HugePageRange range = hugePageRange(reinterpret_cast<std::uintptr_t>(data), bytes);
  if (range.first == range.last) return false;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Pages of the process's own allocation: the advice changes how they are backed, never what
  // they hold (EINVAL where transparent huge pages are compiled out: ignored, a hint).
  return madvise(reinterpret_cast<void*>(range.first), range.last - range.first,
                 MADV_HUGEPAGE) == 0;
#else
  return false;
#endif
}

}  // namespace rt
