// Runs a program as a child process with the given text on stdin, and captures its exit status, stdout and stderr.
// run_skinlayer runs the real skinlayer executable (path from the SKINLAYER_EXECUTABLE compile definition of the
// test target that includes this header).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skinlayer::test {

struct ProcessResult {
  int exit_code = 0;  // the exit status, or -N when the process was killed by signal N
  std::string out;
  std::string err;
};

// argv[0] is the program, looked up in PATH when it has no slash. Throws std::runtime_error if it cannot be started.
ProcessResult run_process(const std::vector<std::string>& argv, std::string_view stdin_text = "");

// The program's full path if an executable of that name is in PATH.
std::optional<std::string> find_in_path(const std::string& program);

// The command names in an unknown-command error's list ("...; the commands are a, b and c"), in order; empty when
// the text has no such list.
std::vector<std::string> command_names_in(std::string_view error);

#ifdef SKINLAYER_EXECUTABLE
inline ProcessResult run_skinlayer(const std::vector<std::string>& arguments, std::string_view stdin_text = "") {
  std::vector<std::string> argv = {SKINLAYER_EXECUTABLE};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_process(argv, stdin_text);
}

// The commands, as the executable names them in its error for an unknown one.
inline std::vector<std::string> skinlayer_command_names() {
  return command_names_in(run_skinlayer({"help", "no-such-command"}).err);
}
#endif

}  // namespace skinlayer::test
