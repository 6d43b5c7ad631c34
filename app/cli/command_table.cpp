#include "app/cli/command_table.h"

#include <array>

#include "app/cli/albedo_command.h"
#include "app/cli/errors.h"
#include "app/cli/eval_command.h"
#include "app/cli/export_command.h"
#include "app/cli/figures_command.h"
#include "app/cli/fit_command.h"
#include "app/cli/flag_parser.h"
#include "app/cli/match_command.h"
#include "app/cli/material_command.h"
#include "app/cli/profile_command.h"
#include "app/cli/render_command.h"
#include "app/cli/spectrum_command.h"
#include "app/cli/validate_command.h"

namespace skinlayer::cli {
namespace {

using Arguments = std::span<const std::string_view>;

const std::array kCommands{
    Command{"eval", eval_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_eval_command(arguments, s.in, s.out); }},
    Command{"albedo", albedo_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_albedo_command(arguments, s.out); }},
    Command{"profile", profile_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_profile_command(arguments, s.out, s.err); }},
    Command{"spectrum", spectrum_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_spectrum_command(arguments, s.out); }},
    Command{"match", match_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_match_command(arguments, s.out, s.err); }},
    Command{"render", render_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_render_command(arguments, s.out, s.err); }},
    Command{"material", material_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_material_command(arguments, s.out); }},
    Command{"presets", presets_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_presets_command(arguments, s.out); }},
    Command{"figures", figures_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_figures_command(arguments, s.out); }},
    Command{"fit", fit_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_fit_command(arguments, s.out); }},
    Command{"export", export_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_export_command(arguments, s.out, s.err); }},
    Command{"validate", validate_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_validate_command(arguments, s.out); }},
};

}  // namespace

std::span<const Command> command_table() { return kCommands; }

const Command* find_command(std::string_view name) {
  for (const Command& command : kCommands) {
    if (command.name == name) return &command;
  }
  return nullptr;
}

std::string command_names() {
  std::string names;
  for (std::size_t i = 0; i < kCommands.size(); ++i) {
    if (i > 0) names += i + 1 == kCommands.size() ? " and " : ", ";
    names += kCommands[i].name;
  }
  return names;
}

int run_command(const Command& command, std::span<const std::string_view> arguments, const CommandStreams& streams) {
  if (wants_help(arguments)) {
    streams.out << command.usage();
    return kExitSuccess;
  }
  return command.run(arguments, streams);
}

}  // namespace skinlayer::cli
