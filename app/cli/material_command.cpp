#include "app/cli/material_command.h"

#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/skin_flag.h"
#include "app/cli/model_flag.h"
#include "app/material/material_file.h"
#include "app/material/material_json.h"
#include "app/material/presets.h"

namespace skinlayer::cli {

std::string material_usage() {
  return "Usage: skinlayer material [material flags] [--albedo A | r,g,b] [--model M] [--name N]\n"
         "                          [--description D] [-o FILE.json]\n"
         "\n"
         "Writes the complete material, every value explicit, as a material file (JSON, described in\n"
         "docs/guide/material-files.md) to FILE.json or to stdout. Start from --material FILE or --preset NAME and\n"
         "change values with flags, as in\n"
         "  skinlayer material --preset skin-fair --sigma 0.3 -o my-skin.json\n"
         "Any command then reads it back with --material my-skin.json.\n" +
         rgb_albedo_usage() + skin_flags_usage(false) +
         "  --model M            subsurface model stored in the file: stam (default), lambert or hk\n"
         "  --name N             the material's name (default: the file's or preset's)\n"
         "  --description D      a one-line description (default: the file's or preset's)\n"
         "  -o, --output FILE    where to write it (atomically); default stdout\n"
         "\n" +
         material_flags_usage();
}

int run_material_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const std::vector<std::string_view> known =
      material_flags_and({kModelFlag, kSkinFlag, "name", "description", "output"});
  const ParsedFlags flags = ParsedFlags::parse(arguments, known, "skinlayer material");
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  document.model = model_from_flags(flags, document.model);
  if (const auto name = flags.value("name")) document.name = std::string(*name);
  if (const auto description = flags.value("description")) document.description = std::string(*description);
  if (const auto path = flags.value("output")) {
    if (path->empty()) throw UsageError("output needs a file name, as in -o skin.json");
    write_material_file(document, std::string(*path));
  } else {
    out << material_json_text(document);
  }
  return kExitSuccess;
}

std::string presets_usage() {
  return "Usage: skinlayer presets\n"
         "\n"
         "Lists the named presets (name, then a one-line description). Any command that takes material flags takes\n"
         "--preset NAME; `skinlayer material --preset NAME` prints one as a material file.\n";
}

int run_presets_command(std::span<const std::string_view> arguments, std::ostream& out) {
  if (!arguments.empty()) throw UsageError("presets takes no arguments; see skinlayer presets --help");
  std::size_t width = 0;
  const std::vector<PresetInfo> presets = preset_list();
  for (const PresetInfo& preset : presets) width = std::max(width, preset.name.size());
  for (const PresetInfo& preset : presets) {
    out << preset.name << std::string(width + 2 - preset.name.size(), ' ') << preset.description << '\n';
  }
  return kExitSuccess;
}

}  // namespace skinlayer::cli
