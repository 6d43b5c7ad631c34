// skinlayer-window: the interactive previewer. It links libGL (through GLFW's context) and never libOSMesa, so it
// is its own executable; `skinlayer` with no command, or with --capture, runs it (app/cli/previewer_launcher.h).
#include <iostream>
#include <string_view>
#include <vector>

#include "app/cli/error_report.h"
#include "app/cli/errors.h"
#include "app/process/heap_retention.h"
#include "app/window/previewer.h"
#include "app/window/window_options.h"

int main(int argc, char** argv) {
  skinlayer::retain_freed_heap_memory();
  skinlayer::limit_heap_arenas(1);  // a long session on several threads: one arena (heap_retention.h)
  const std::vector<std::string_view> arguments(argv + 1, argv + argc);
  return skinlayer::cli::run_reporting_errors(std::cerr, [&arguments] {
    const skinlayer::WindowOptions options = skinlayer::parse_window_options(arguments);
    if (options.help) {
      std::cout << skinlayer::window_usage();
      return skinlayer::cli::kExitSuccess;
    }
    return skinlayer::run_previewer(options, std::cout);
  });
}
