#pragma once
/// @file HugePages.h
/// Large arrays of the structures' builds (the BVH's records and nodes, a million stars' worth:
/// tens of MiB each) backed by 2 MiB pages where the system offers them.
///
/// Every 4 KiB page of a fresh array costs a page fault the first time it is written: for 10^6
/// stars some 33 000 of them, a third of the BVH's build on this project's virtual machine on
/// the days its page faults are slow. Linux backs an anonymous range with transparent
/// huge pages of 2 MiB where the process asks for them (madvise(MADV_HUGEPAGE), the setting
/// "madvise" of /sys/kernel/mm/transparent_hugepage/enabled, Debian's default) or everywhere
/// (the setting "always"): one fault per 2 MiB. The advice is a hint: nothing changes but the
/// time where the system says no (the setting "never", another system, no 2 MiB page free),
/// and only the 2 MiB-aligned part of an array inside it is advised, so no other allocation's
/// pages are.
///
///     array:     |----:---------------:---------------:------|
///     2 MiB:     :    :               :               :      :
///     advised:        [-------------------------------)          hugePageRange(begin, bytes)
///
/// Memory: a huge page holds 2 MiB once any of it is written. The arrays advised here are
/// written from their start, so one reserved for more than it fills (address space, as the
/// binary BVH's node array) takes at most one 2 MiB page beyond its written part.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rt {

/// The size of the huge pages asked for.
inline constexpr std::uintptr_t HUGE_PAGE_BYTES = std::uintptr_t{1} << 21;

/// The part of [begin, begin + bytes) made of whole 2 MiB-aligned pages, as [first, last)
/// addresses; first == last when there is none.
struct HugePageRange {
  std::uintptr_t first;
  std::uintptr_t last;
};
constexpr HugePageRange hugePageRange(std::uintptr_t begin, std::size_t bytes) noexcept {
  const std::uintptr_t first = (begin + HUGE_PAGE_BYTES - 1) & ~(HUGE_PAGE_BYTES - 1);
  const std::uintptr_t last = (begin + bytes) & ~(HUGE_PAGE_BYTES - 1);
  return first < last ? HugePageRange{first, last} : HugePageRange{first, first};
}

/// Asks for huge pages on the whole 2 MiB pages of [data, data + bytes), before they are
/// written; true when the system took the advice (false: nothing to advise, or not Linux, or
/// transparent huge pages off). Only the speed of the first writes depends on it.
bool adviseHugePages(const void* data, std::size_t bytes) noexcept;

/// v.reserve(n), its storage advised for huge pages when the reservation made it anew.
template <typename T>
void reserveHuge(std::vector<T>& v, std::size_t n) {
  const T* before = v.data();
  v.reserve(n);
  if (v.data() != before) adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace rt
