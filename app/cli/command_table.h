// The table of skinlayer's commands: each command's name, its usage text and how to run it. The executable's
// dispatch and `skinlayer help COMMAND` both read it, so a command's `--help` and its entry in `help` are the same
// text by construction, and a new command cannot be given one without the other.
#pragma once

#include <istream>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

// The process's streams, as a command sees them: CSV rows on in, results on out, progress on err.
struct CommandStreams {
  std::istream& in;
  std::ostream& out;
  std::ostream& err;
};

struct Command {
  std::string_view name;
  std::string (*usage)();
  int (*run)(std::span<const std::string_view> arguments, const CommandStreams& streams);
  // What it does, for the overview under the usage's own synopsis (each line up to 110 columns).
  std::string_view summary;
};

// The synopsis of a usage text: its lines up to the first blank one, "Usage: " and its indent taken off.
std::string usage_synopsis(std::string_view usage);

// Every command, in the order the overview lists them. `help` itself is not among them.
std::span<const Command> command_table();

// The command of that name, or nullptr.
const Command* find_command(std::string_view name);

// "eval, albedo, ... and validate": the names for error messages.
std::string command_names();

// Runs the command on its arguments (after its name). With "--help" or "-h" among them it writes the command's usage
// to out instead and returns success. Errors are thrown (see errors.h).
int run_command(const Command& command, std::span<const std::string_view> arguments, const CommandStreams& streams);

}  // namespace skinlayer::cli
