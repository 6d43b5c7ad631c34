// Process-wide allocator setting for executables that solve repeatedly (the previewer's worker, the CLI, the
// benchmarks). Called once at the top of main, before any thread starts.
#pragma once

namespace skinlayer {

// Keeps freed heap memory mapped instead of handing it back to the kernel after every solve. A default solve
// allocates and frees ~1.4 MB of tables and projection scratch; with glibc's defaults the heap is trimmed and
// grown again ~12 times per solve, and every regrown page is faulted in anew. On the project's 2-core VM that is
// ~350 page faults and ~4 ms of a ~12 ms solve (bench_core, BM_SolveDefault: 12 ms with the defaults, 8 ms with
// this). Sets glibc's M_MMAP_THRESHOLD to 32 MB (its maximum: larger blocks are still mapped on their own) and
// M_TRIM_THRESHOLD to 256 MB. The cost is resident memory: the process keeps its peak heap. A no-op elsewhere.
void retain_freed_heap_memory();

}  // namespace skinlayer
