// Runs the real skinlayer executable (path from the SKINLAYER_EXECUTABLE compile definition) as a child process,
// with the given text on stdin, and captures its exit status, stdout and stderr.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace skinlayer::test {

struct ProcessResult {
  int exit_code = 0;  // the exit status, or -N when the process was killed by signal N
  std::string out;
  std::string err;
};

// Throws std::runtime_error if the process cannot be started.
ProcessResult run_skinlayer(const std::vector<std::string>& arguments, std::string_view stdin_text = "");

}  // namespace skinlayer::test
