#include "app/cli/command_table.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <iostream>

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
            [](Arguments arguments, const CommandStreams& s) {
              // On a terminal nothing would show that eval waits for its rows.
              if (&s.in == &std::cin && ::isatty(STDIN_FILENO) == 1) {
                s.err << "skinlayer: eval: reading rows theta_i,theta_o,phi (degrees) from the terminal; end them with "
                         "Ctrl-D, or give a file: skinlayer eval ... < angles.csv\n"
                      << std::flush;
              }
              return run_eval_command(arguments, s.in, s.out);
            },
            "BRDF and BTDF at direction pairs: CSV rows theta_i,theta_o,phi (degrees) in, values (1/sr) out."},
    Command{"albedo", albedo_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_albedo_command(arguments, s.out); },
            "reflectance, transmittance and absorptance for light from each incidence angle."},
    Command{"profile", profile_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_profile_command(arguments, s.out, s.err); },
            "where a pencil beam's light leaves the layer, per unit area: the spatial profile (BSSRDF)."},
    Command{"spectrum", spectrum_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_spectrum_command(arguments, s.out); },
            "reflectance, transmittance and absorptance per wavelength, of a skin or a grey material."},
    Command{"match", match_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_match_command(arguments, s.out, s.err); },
            "pick the colour (or a measured spectrum), get the parameters: the material that reproduces it."},
    Command{"render", render_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_render_command(arguments, s.out, s.err); },
            "the previewer's sphere and polar lobes, rendered offscreen (no display needed) to a PNG or HDR."},
    Command{"material", material_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_material_command(arguments, s.out); },
            "the complete material as a material file, which --material FILE reads back (every command)."},
    Command{"presets", presets_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_presets_command(arguments, s.out); },
            "the named presets (--preset NAME): the paper's settings, skin, leaf, paper, wax, jade, paint;\n      "
            "--colors gives each one's colour at normal incidence."},
    Command{"figures", figures_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_figures_command(arguments, s.out); },
            "the results figures (lobe plots, model spheres, skin profiles): a PNG and a CSV each, and index.html."},
    Command{"fit", fit_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_fit_command(arguments, s.out); },
            "a renderer's shader nearest the material: Blender's Principled BSDF (4.2-5.x, or 3.4), OpenPBR\n      "
            "Surface (MaterialX) or glTF's metallic-roughness with its KHR extensions, with the fit's error."},
    Command{"export", export_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_export_command(arguments, s.out, s.err); },
            "the solved material as a tabulated Fourier BSDF (pbrt-v3, layerlab), a MERL BRDF table, an RGL\n      "
            "tensor file (pbrt-v4, Mitsuba 3), or a fitted shader: a Blender script, MaterialX or glTF."},
    Command{"validate", validate_usage,
            [](Arguments arguments, const CommandStreams& s) { return run_validate_command(arguments, s.out); },
            "the solver against an independent Monte Carlo walk over a grid of layers: tables and a report."},
};

}  // namespace

std::span<const Command> command_table() { return kCommands; }

const Command* find_command(std::string_view name) {
  for (const Command& command : kCommands) {
    if (command.name == name) return &command;
  }
  return nullptr;
}

std::string usage_synopsis(std::string_view usage) {
  constexpr std::string_view kUsage = "Usage: ";
  std::string synopsis;
  std::size_t at = 0;
  while (at < usage.size()) {
    const std::size_t end = std::min(usage.find('\n', at), usage.size());
    std::string_view line = usage.substr(at, end - at);
    if (line.empty()) break;
    if (line.starts_with(kUsage)) {
      line.remove_prefix(kUsage.size());
    } else if (line.starts_with(std::string(kUsage.size(), ' '))) {
      line.remove_prefix(kUsage.size());
    }
    synopsis.append(line).push_back('\n');
    at = end + 1;
  }
  return synopsis;
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
