// What the allocator does with the memory a run frees. The cell sorts (every 10 steps) and, in a
// decomposed run, the halo builds give every particle array a new block and free the old one.
// With glibc's defaults a block above the mmap threshold (128 KiB, raised to the size of each
// mapped block freed) is mapped for itself and unmapped when freed, and the top of the heap is
// given back once twice that is free there: each new block then faults in every page again. On the 2D benchmark
// dam break (20,000 particles, 2 ranks) that took the halo builds from 0.2 s to 0.65-0.73 s of a
// 3.3-4 s run, and the serial neighbour search from 0.26 s to 0.40-0.44 s (doc/performance.md,
// "Memory the allocator keeps"). Kept in the heap, a freed block serves the next one; the peak
// resident memory is unchanged (it is the largest the arrays reach either way).
#pragma once

namespace sph {

// Blocks up to 32 MiB (glibc's largest mmap threshold) from the heap, and the heap kept when
// freed, unless the user chose the allocator's settings (GLIBC_TUNABLES naming glibc.malloc, or
// MALLOC_MMAP_THRESHOLD_ / MALLOC_TRIM_THRESHOLD_ set). Returns whether it set them. Call first
// thing in main.
bool keepFreedMemoryForReuse();

}  // namespace sph
