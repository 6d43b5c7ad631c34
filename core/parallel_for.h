// The caller's parallel-for, through which core runs independent work side by side without starting threads.
#pragma once

#include <functional>

namespace skinlayer {

// Runs body(0) ... body(count - 1), each once, possibly side by side, and returns when all have (rethrowing the first
// exception). Empty = one after another.
using ParallelFor = std::function<void(int count, const std::function<void(int)>& body)>;

}  // namespace skinlayer
