// `skinlayer` with no command, or with flags and no command (`skinlayer --sigma 0.3`, `skinlayer --preset wax
// --capture shot.png`), runs the previewer: the separate
// executable skinlayer-window in the same folder as skinlayer. The window links libGL and skinlayer links
// libOSMesa, and one process must never load both (docs/platform-notes.md), hence two executables.
#pragma once

#include <span>
#include <string_view>

namespace skinlayer::cli {

// True for the arguments that start the previewer: none, or a first argument that is a flag ("--sigma",
// "--capture=FILE", ...) other than skinlayer's own --help, -h and --version.
bool is_previewer_invocation(std::span<const std::string_view> arguments);

// Replaces this process with skinlayer-window (from the folder of /proc/self/exe), passing arguments
// (argv[1..argc)) unchanged. Returns only on failure, by throwing std::runtime_error with a one-line message: the
// executable is missing, or it could not be started.
[[noreturn]] void exec_previewer(int argc, char** argv);

}  // namespace skinlayer::cli
