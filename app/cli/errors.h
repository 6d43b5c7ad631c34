// The command line's failure kinds and the exit status each one maps to.
//
//   0  success
//   1  bad input data or a failed computation: malformed CSV on stdin, no data rows, a non-finite result
//   2  a bad command line: unknown command or flag, missing or repeated value, conflicting flags, or a parameter
//      out of range (skinlayer::ParameterError)
#pragma once

#include <stdexcept>

namespace skinlayer::cli {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// A mistake on the command line. Exit status 2. The message names the flag or argument at fault.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Malformed or missing data on stdin. Exit status 1. The message names the line at fault.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace skinlayer::cli
