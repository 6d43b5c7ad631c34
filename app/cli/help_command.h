// `skinlayer help [COMMAND]` and `skinlayer --help`: the overview of every command, or one command's usage.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string overview_usage();

// With no arguments prints the overview; with a command name prints that command's usage. Returns the exit status;
// throws UsageError for an unknown command name or extra arguments.
int run_help_command(std::span<const std::string_view> arguments, std::ostream& out);

}  // namespace skinlayer::cli
