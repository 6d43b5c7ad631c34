// Cooperative cancellation of a long computation: the caller hands core a check, core asks it between pieces of
// work and stops by throwing SolveCancelled. Core starts no threads and keeps no flag of its own.
#pragma once

#include <functional>
#include <stdexcept>

namespace skinlayer {

// Thrown by a solve whose SolveOptions::cancelled returned true.
class SolveCancelled : public std::runtime_error {
 public:
  SolveCancelled() : std::runtime_error("solve cancelled") {}
};

// The caller's check: true asks core to stop. Core may call it from the caller's parallel-for threads at once, so
// it must be safe to call concurrently; it should be cheap (a flag or a counter under a mutex), since the interface
// kernels ask it once per incident direction. Empty = never cancelled.
using CancelCheck = std::function<bool()>;

// Throws SolveCancelled when `cancelled` is given and says stop.
inline void throw_if_cancelled(const CancelCheck& cancelled) {
  if (cancelled && cancelled()) throw SolveCancelled();
}

}  // namespace skinlayer
