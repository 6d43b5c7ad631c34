// The process's resident memory, for the previewer's soak test (--test-actions memory) and diagnostics.
#pragma once

#include <cstddef>
#include <optional>

namespace skinlayer {

// The resident set size of this process now, in bytes (Linux: /proc/self/statm's second field times the page size);
// nullopt where the system does not tell it.
std::optional<std::size_t> resident_memory_bytes();

// The bytes the heap has handed out and not had back (glibc: mallinfo2's in-use arena and mmapped bytes); nullopt
// elsewhere. Beside the resident size it tells memory held by live objects from memory the allocator keeps.
std::optional<std::size_t> heap_in_use_bytes();

}  // namespace skinlayer
