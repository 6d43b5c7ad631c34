#include "app/window/window_options.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/skin_flag.h"
#include "core/solver.h"

namespace skinlayer {

WindowOptions parse_window_options(std::span<const std::string_view> arguments) {
  WindowOptions options;
  if (cli::wants_help(arguments)) {
    options.help = true;
    return options;
  }
  std::vector<std::string_view> known =
      cli::material_flags_and({"capture", "view", cli::kModelFlag, cli::kSkinFlag, "test-actions"});
  for (std::string_view name : cli::lighting_flag_names()) known.push_back(name);
  const cli::ParsedFlags flags = cli::ParsedFlags::parse(arguments, known, "skinlayer");
  options.lighting = cli::lighting_from_flags(flags);
  const MaterialDocument document = cli::material_document_from_flags(flags, cli::AlbedoFlag::GreyOrRgb);
  options.material = color_material(document);
  if (options.material.layer.ordinates) choose_resolution(options.material.layer);  // checks the material's minimum
  options.material.model = cli::model_from_flags(flags, document.model);
  options.document = document;
  options.material_path = std::string(flags.value("material").value_or(""));
  options.preset = std::string(flags.value("preset").value_or(""));
  if (const std::optional<std::string_view> value = flags.value("test-actions")) {
    // "@FILE": the list is that file's text (a soak's thousands of actions are past what argv should carry).
    std::string actions(*value);
    if (actions.starts_with('@')) {
      std::ifstream file(actions.substr(1), std::ios::binary);
      if (!file) throw cli::UsageError("test-actions = '" + actions + "': cannot read " + actions.substr(1));
      actions.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
      std::replace(actions.begin(), actions.end(), '\n', ';');  // a line ends an action too
    }
    for (const std::string_view action : cli::split_list(actions, ';')) {
      if (!action.empty()) options.test_actions.emplace_back(action);
    }
  }
  if (const std::optional<std::string_view> view = flags.value("view")) {
    const std::optional<ViewKind> kind = parse_view_kind(*view);
    if (!kind) throw cli::UsageError("view = '" + std::string(*view) + "' is not one of sphere, polar, both, compare");
    options.view = *kind;
  }
  if (const std::optional<std::string_view> path = flags.value("capture")) {
    if (path->empty()) throw cli::UsageError("capture needs a file name, as in --capture shot.png");
    options.capture_path = std::string(*path);
  }
  return options;
}

std::string window_usage() {
  return "Usage: skinlayer [--capture FILE.png] [--view sphere|polar|both|compare] [--model stam|lambert|hk]\n"
         "                 [--env E ...] [--material FILE | --preset NAME] [--albedo A | r,g,b] [material flags]\n"
         "\n"
         "Opens the previewer: a lit sphere of the material beside polar plots of its BRDF and BTDF, with controls\n"
         "for every parameter (press F1 in the window for the keys). Needs a display; without one, use\n"
         "`skinlayer render -o out.png`, which takes the same material flags.\n"
         "  --capture FILE.png   render until the material is solved (and, under --env, the estimate has its\n"
         "                       --samples), save a screenshot of the whole window (framebuffer resolution)\n"
         "                       to FILE.png, print its size and exit\n"
         "  --view V             the views shown first: sphere, polar, both, or compare (three spheres:\n"
         "                       Lambert | Hanrahan-Krueger | the layer model)\n"
         "  --model M            the subsurface model of the sphere and plots: stam, lambert, hk\n"
         "  --albedo A | r,g,b   single-scattering albedo, grey or per color channel, each in [0, 1]\n"
         "  --test-actions LIST  for tests: ';'-separated actions (@FILE: those in FILE, one a line or\n"
         "                       ';'-separated) run once the first solve is shown\n"
         "                       (set NAME VALUE, undo, redo, drop PATH, save PATH, preset NAME, quit, discard, "
         "title,\n"
         "                       layer add, layer remove|up|down I, export-merl PATH, export-bsdf PATH,\n"
         "                       export-rgl PATH, export-blender PATH, export-mtlx PATH, lighting\n"
         "                       env|env-rotate|env-ev|light VALUE, pin, pin-fit principled|openpbr, unpin,\n"
         "                       split FRACTION, skin on|off, match R,G,B, drag NAME V1,V2,... (a slider\n"
         "                       dragged, one value a frame), rest (waits until nothing is in flight), memory\n"
         "                       (the resident memory, at rest); with a skin, set KEY VALUE sets a skin slider)\n" +
         cli::lighting_flags_usage() + "\n" + cli::skin_flags_usage(false) + "\n" + cli::material_flags_usage();
}

}  // namespace skinlayer
