#include "app/process/heap_retention.h"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

namespace skinlayer {

void retain_freed_heap_memory() {
#if defined(__GLIBC__) && defined(M_MMAP_THRESHOLD) && defined(M_TRIM_THRESHOLD)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}

void limit_heap_arenas([[maybe_unused]] int arenas) {
#if defined(__GLIBC__) && defined(M_ARENA_MAX)
  mallopt(M_ARENA_MAX, arenas);
#endif
}

void release_freed_heap_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace skinlayer
