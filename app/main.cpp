// The skinlayer executable: dispatches to one command. Each command lives in app/cli/.
#include <iostream>
#include <span>
#include <string_view>
#include <vector>

#include "app/cli/command_table.h"
#include "app/cli/error_report.h"
#include "app/cli/errors.h"
#include "app/cli/help_command.h"
#include "app/cli/previewer_launcher.h"
#include "app/process/heap_retention.h"
#include "app/text/quoted.h"

namespace {

int dispatch(std::span<const std::string_view> arguments, int argc, char** argv) {
  using namespace skinlayer::cli;
  if (is_previewer_invocation(arguments)) exec_previewer(argc, argv);  // returns only by throwing
  const std::string_view command = arguments.front();
  const std::span<const std::string_view> rest = arguments.subspan(1);
  if (const Command* found = find_command(command)) {
    return run_command(*found, rest, CommandStreams{std::cin, std::cout, std::cerr});
  }
  if (command == "help" || command == "--help" || command == "-h") return run_help_command(rest, std::cout);
  if (command == "--version") {
    std::cout << "skinlayer " << SKINLAYER_VERSION << '\n';
    return kExitSuccess;
  }
  throw UsageError("unknown command " + skinlayer::text::quoted(command) + "; see skinlayer --help");
}

}  // namespace

int main(int argc, char** argv) {
  skinlayer::retain_freed_heap_memory();
  const std::vector<std::string_view> arguments(argv + 1, argv + argc);
  return skinlayer::cli::run_reporting_errors(std::cerr,
                                              [&arguments, argc, argv] { return dispatch(arguments, argc, argv); });
}
