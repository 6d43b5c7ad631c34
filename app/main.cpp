// The skinlayer executable: dispatches to one command. Each command lives in app/cli/.
#include <iostream>
#include <span>
#include <string_view>
#include <vector>

#include "app/cli/albedo_command.h"
#include "app/cli/error_report.h"
#include "app/cli/errors.h"
#include "app/cli/eval_command.h"
#include "app/cli/export_command.h"
#include "app/cli/figures_command.h"
#include "app/cli/help_command.h"
#include "app/cli/material_command.h"
#include "app/cli/previewer_launcher.h"
#include "app/cli/quoted.h"
#include "app/cli/render_command.h"
#include "app/cli/validate_command.h"
#include "app/process/heap_retention.h"

namespace {

int dispatch(std::span<const std::string_view> arguments, int argc, char** argv) {
  using namespace skinlayer::cli;
  if (is_previewer_invocation(arguments)) exec_previewer(argc, argv);  // returns only by throwing
  const std::string_view command = arguments.front();
  const std::span<const std::string_view> rest = arguments.subspan(1);
  if (command == "eval") return run_eval_command(rest, std::cin, std::cout);
  if (command == "albedo") return run_albedo_command(rest, std::cout);
  if (command == "render") return run_render_command(rest, std::cout, std::cerr);
  if (command == "material") return run_material_command(rest, std::cout);
  if (command == "presets") return run_presets_command(rest, std::cout);
  if (command == "figures") return run_figures_command(rest, std::cout);
  if (command == "validate") return run_validate_command(rest, std::cout);
  if (command == "export") return run_export_command(rest, std::cout, std::cerr);
  if (command == "help" || command == "--help" || command == "-h") return run_help_command(rest, std::cout);
  if (command == "--version") {
    std::cout << "skinlayer " << SKINLAYER_VERSION << '\n';
    return kExitSuccess;
  }
  throw UsageError("unknown command " + quoted(command) + "; see skinlayer --help");
}

}  // namespace

int main(int argc, char** argv) {
  skinlayer::retain_freed_heap_memory();
  const std::vector<std::string_view> arguments(argv + 1, argv + argc);
  return skinlayer::cli::run_reporting_errors(std::cerr,
                                             [&arguments, argc, argv] { return dispatch(arguments, argc, argv); });
}
