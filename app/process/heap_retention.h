// Process-wide allocator settings for executables that solve repeatedly (the previewer's worker, the CLI, the
// benchmarks), and the previewer's return of freed memory when it rests. Set once at the top of main, before any
// thread starts.
#pragma once

namespace skinlayer {

// Keeps freed heap memory mapped instead of handing it back to the kernel after every solve. A default solve
// allocates and frees ~1.4 MB of tables and projection scratch; with glibc's defaults the heap is trimmed and
// grown again ~12 times per solve, and every regrown page is faulted in anew. On the project's 2-core VM that is
// ~350 page faults and ~4 ms of a ~12 ms solve (bench_core, BM_SolveDefault: 12 ms with the defaults, 8 ms with
// this). Sets glibc's M_MMAP_THRESHOLD to 32 MB (its maximum: larger blocks are still mapped on their own) and
// M_TRIM_THRESHOLD to 256 MB. The cost is resident memory: the process keeps its peak heap. A no-op elsewhere.
void retain_freed_heap_memory();

// For a process that lives long and allocates on several threads (the previewer: the UI, the solve worker, the
// parallel-for's helpers, the export job). glibc gives threads arenas of their own, up to 8 per core, and each keeps
// its own peak: in the previewer's soak (tests/app/window/window_soak_test.cpp) resident memory climbed from 270 MB
// to 516 MB over 2000 edits while the heap in use stayed at 115-150 MB. Sets M_ARENA_MAX to `arenas`. The previewer
// takes 1: release_freed_heap_memory hands back the free top of the main arena only (glibc shrinks a thread arena's
// top only when a large block is freed there and the top exceeds M_TRIM_THRESHOLD, 256 MB here), so with 2 the
// solve worker's arena kept its largest size and resident memory at rest rose 12 MB at one step of the soak, the
// heap in use unchanged. One arena cost no time there (300 edits: 61 s with 1, 63 s with 2). A no-op elsewhere.
void limit_heap_arenas(int arenas);

// Hands the heap's free pages back to the kernel (glibc's malloc_trim): the free top of the main arena, and the
// pages inside free blocks of every arena. The previewer calls it when its window comes to rest (no solve in
// flight, nothing moving), so that a resting window holds what it uses, not the largest thing it ever did; the next
// solve faults its scratch in again (a few ms). A no-op elsewhere.
void release_freed_heap_memory();

}  // namespace skinlayer
