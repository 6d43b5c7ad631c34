#include "app/cli/help_command.h"

#include "app/cli/command_table.h"
#include "app/cli/errors.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {

std::string overview_usage() {
  std::string text =
      "skinlayer: Stam's (2001) skin-layer illumination model: a rough dielectric surface over a scattering slab.\n"
      "\n"
      "Usage:\n";
  // Each command's own synopsis (its --help's first lines), so that the two cannot drift apart, and its summary.
  for (const Command& command : command_table()) {
    const std::string synopsis = usage_synopsis(command.usage());
    std::size_t at = 0;
    while (at < synopsis.size()) {
      const std::size_t end = synopsis.find('\n', at);
      text += "  " + synopsis.substr(at, end - at + 1);
      at = end + 1;
    }
    text += "      " + std::string(command.summary) + "\n";
  }
  return text +
         "  skinlayer help [COMMAND], skinlayer COMMAND --help\n"
         "      usage of a command, with every flag, its range and default.\n"
         "  skinlayer --version\n"
         "  skinlayer [--capture FILE.png [material flags]]\n"
         "      the interactive previewer (a window; F1 lists its keys). --capture opens it, saves a screenshot of\n"
         "      the whole window and exits. Without a display it says so: use skinlayer render instead.\n"
         "\n"
         "Exit status: 0 success; 1 malformed input on stdin or a failed computation; 2 a bad command line or a\n"
         "parameter out of range. Every error is one line on stderr.\n";
}

int run_help_command(std::span<const std::string_view> arguments, std::ostream& out) {
  if (arguments.empty()) {
    out << overview_usage();
    return kExitSuccess;
  }
  if (arguments.size() > 1) throw UsageError("help takes at most one command name, as in skinlayer help eval");
  const Command* command = find_command(arguments.front());
  if (command == nullptr) {
    throw UsageError("unknown command " + text::quoted(arguments.front()) + "; the commands are " + command_names());
  }
  out << command->usage();
  return kExitSuccess;
}

}  // namespace skinlayer::cli
