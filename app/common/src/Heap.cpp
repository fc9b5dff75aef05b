#include "common/Heap.h"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

namespace rt {

void keepLargeBlocksOutOfTheHeap() noexcept {
#if defined(__GLIBC__) && defined(M_MMAP_THRESHOLD)
  // Setting the threshold also turns off glibc's raising of it (mallopt(3)).
  constexpr int LARGE_BLOCK = 128 * 1024;
  mallopt(M_MMAP_THRESHOLD, LARGE_BLOCK);
#endif
}

}  // namespace rt
