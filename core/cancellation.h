// Cooperative cancellation of a long computation: the caller hands core a check, core asks it between pieces of
// work and stops by throwing SolveCancelled. Core starts no threads and keeps no flag of its own.
#pragma once

#include <stdexcept>

namespace skinlayer {

// Thrown by a solve whose SolveOptions::cancelled returned true.
class SolveCancelled : public std::runtime_error {
 public:
  SolveCancelled() : std::runtime_error("solve cancelled") {}
};

}  // namespace skinlayer
