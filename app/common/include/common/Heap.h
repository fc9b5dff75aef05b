#pragma once
/// @file Heap.h
/// How the programs (rt, rt-mpi) ask the C library to manage their heap.

namespace rt {

/// Makes every block of 128 KiB or more come straight from the system and go back to it when
/// freed, for the whole process; call it first thing in main.
///
/// glibc's default starts the same way but raises the threshold to the size of each large
/// block freed (up to 32 MiB), after which such blocks are carved out of the heap or of a
/// thread's arena, where freed memory stays resident. A scene's build frees large arrays as
/// it goes (the BVH's build records, each build thread's subtrees, the binary nodes once
/// collapsed), so with the default its peak holds them all at once: for the galaxy of 10^6
/// stars, `rt bench --scaling --stars 1000000` peaks at 230 to 236 MiB with the default and at
/// 199 MiB with this (docs/benchmarks.md, "Star scaling"). The per-ray path allocates nothing, so
/// the setting costs the render nothing. A no-op outside glibc.
void keepLargeBlocksOutOfTheHeap() noexcept;

}  // namespace rt
