// Runs a program (looked up in PATH) as a child process and captures its exit status, stdout and stderr.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace skinlayer::test {

struct ChildResult {
  int exit_code = 0;  // the exit status, or -N when the process was killed by signal N
  std::string out;
  std::string err;
};

// argv[0] is the program. Throws std::runtime_error if it cannot be started.
ChildResult run_child(const std::vector<std::string>& argv);

// The program's full path if an executable of that name is in PATH.
std::optional<std::string> find_in_path(const std::string& program);

}  // namespace skinlayer::test
