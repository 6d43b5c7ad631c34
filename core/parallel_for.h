// The caller's parallel-for, through which core runs independent work side by side without starting threads.
#pragma once

#include <functional>

namespace skinlayer {

// Runs body(0) ... body(count - 1), each once, possibly side by side, and returns when all have (rethrowing the first
// exception). Empty = one after another.
using ParallelFor = std::function<void(int count, const std::function<void(int)>& body)>;

// body(0) ... body(count - 1) through parallel_for, or one after another where it is empty or there is one index.
inline void run_parallel(const ParallelFor& parallel_for, int count, const std::function<void(int)>& body) {
  if (parallel_for && count > 1) {
    parallel_for(count, body);
  } else {
    for (int index = 0; index < count; ++index) body(index);
  }
}

}  // namespace skinlayer
