#pragma once
/// @file HugePages.h
/// Large arrays of the structures' builds (the BVH's records and nodes, a million stars' worth:
/// tens of MiB each) backed by 2 MiB pages where the system offers them.
///
/// Every 4 KiB page of a fresh array costs a page fault the first time it is written: for 10^6
/// stars some 33 000 of them, a third of the BVH's build on this project's virtual machine on
/// the days its page faults are slow. Linux backs an anonymous range with transparent
/// huge pages of 2 MiB where the process asks for them (madvise(MADV_HUGEPAGE), the setting
/// "madvise" of /sys/kernel/mm/transparent_hugepage/enabled, this project's machine's) or
/// everywhere (the setting "always", the kernel's own default): one fault per 2 MiB. The advice
/// is a hint: nothing changes but the time where the system says no (the setting "never",
/// another system, no 2 MiB page free), and only the 2 MiB-aligned part of an array inside it is
/// advised, so no other allocation's pages are. Where the pages stay small, an array written
/// whole has its pages made in one call (populatePages) rather than one fault each.
///
///     array:     |----:---------------:---------------:------|
///     2 MiB:     :    :               :               :      :
///     advised:        [-------------------------------)          hugePageRange(begin, bytes)
///
/// Memory: a huge page holds 2 MiB once any of it is written. The arrays advised here are
/// written from their start, so one reserved for more than it fills (address space, as the
/// binary BVH's node array on one thread) takes at most one 2 MiB page beyond its written part.
/// Arrays reserved far beyond what they fill, several at once (the parallel build's subtrees),
/// are advised for small pages instead (adviseSmallPages), which the setting "always" would
/// otherwise back with 2 MiB pages too.

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

/// v.reserve(n), then advised(data, capacity in bytes) when the reservation made it anew.
template <typename T, typename Advise>
void reserveAdvised(std::vector<T>& v, std::size_t n, const Advise& advised) {
  const T* before = v.data();
  v.reserve(n);
  if (v.data() != before) advised(v.data(), v.capacity() * sizeof(T));
}

/// v.reserve(n), its storage advised for huge pages when the reservation made it anew.
template <typename T>
void reserveHuge(std::vector<T>& v, std::size_t n) {
  reserveAdvised(v, n, adviseHugePages);
}

/// Makes the pages of [data, data + bytes) at once, as if each were written (Linux's
/// MADV_POPULATE_WRITE, 5.14 on), for an array about to be written whole: one system call
/// instead of a page fault per page where the pages are small (the setting "never", or the
/// array's ends). On this project's virtual machine a fault costs some microseconds: with
/// "never", the 10^6-star galaxy's build took 0.45 s instead of 0.56 (docs/benchmarks.md, "Star
/// scaling"). True when the system did it (false: nothing to do, an older kernel, not Linux);
/// the array's contents are unchanged either way.
bool populatePages(const void* data, std::size_t bytes) noexcept;

/// reserveHuge(v, n), and the pages of its first n elements made at once (populatePages): for
/// an array that will hold n elements, written soon.
template <typename T>
void reserveHugeWritten(std::vector<T>& v, std::size_t n) {
  reserveAdvised(v, n, [n](const void* data, std::size_t bytes) {
    adviseHugePages(data, bytes);
    populatePages(data, n * sizeof(T));
  });
}

/// Asks for 4 KiB pages only on the whole pages of [data, data + bytes), before they are
/// written: for an array reserved far beyond what it may fill, and freed soon. Where the
/// system's setting is "always", each such array would otherwise take 2 MiB pages as it is
/// written, up to 2 MiB beyond its written part; with several at once (the parallel build's
/// subtrees), the build's peak grows by that much (docs/benchmarks.md, "Star scaling"). True when
/// the system took the advice.
bool adviseSmallPages(const void* data, std::size_t bytes) noexcept;

/// v.reserve(n), its storage advised for small pages when the reservation made it anew.
template <typename T>
void reserveSmall(std::vector<T>& v, std::size_t n) {
  reserveAdvised(v, n, adviseSmallPages);
}

}  // namespace rt
