// Turns a command's exceptions into the command line's error contract: one line on stderr and an exit status.
#pragma once

#include <functional>
#include <ostream>

namespace skinlayer::cli {

// Runs command and returns its exit status. If it throws, writes "skinlayer: error: <message>" as a single line to
// err (control characters in the message become spaces) and returns the status errors.h gives the exception:
// 2 for skinlayer::ParameterError and UsageError, 1 for anything else.
int run_reporting_errors(std::ostream& err, const std::function<int()>& command);

}  // namespace skinlayer::cli
