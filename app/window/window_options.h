// skinlayer-window's command line: [--capture FILE.png] [--view V] [--model M] [material flags]. `skinlayer` with
// no command (no arguments, or flags only) runs skinlayer-window with its arguments unchanged, so these are also
// skinlayer's previewer arguments.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/environment_flags.h"
#include "app/render/scene.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

struct WindowOptions {
  ColorMaterial material;                   // from --material/--preset and the material flags (RGB --albedo)
  MaterialDocument document;                // the same with the file's or preset's name and description
  std::string material_path;                // --material FILE (a material file or PNG), or empty
  std::string preset;                       // --preset NAME, or empty
  std::vector<std::string> test_actions;    // --test-actions "a;b;...": the tests' hook (previewer.h)
  ViewKind view = ViewKind::Both;           // --view sphere|polar|both|compare
  std::optional<std::string> capture_path;  // --capture: save the whole window there once solved, then exit
  cli::LightingFlags lighting;              // --env, --env-rotate, ... (render's lighting flags)
  bool help = false;                        // --help or -h
};

// Throws cli::UsageError or ParameterError (exit status 2) for a bad command line, naming the flag at fault; an
// --ordinates below the material's minimum is caught here too, before a window opens.
WindowOptions parse_window_options(std::span<const std::string_view> arguments);

std::string window_usage();

}  // namespace skinlayer
