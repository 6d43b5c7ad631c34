#include "app/cli/material_command.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/skin_flag.h"
#include "app/material/material_file.h"
#include "app/material/material_json.h"
#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_albedo.h"
#include "app/text/numbers.h"
#include "core/color/spectral_color.h"
#include "core/interfaces/microfacet_model.h"

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
  return "Usage: skinlayer presets [--colors [--microfacet multiple|single]]\n"
         "\n"
         "Lists the named presets (name, then a one-line description). Any command that takes material flags takes\n"
         "--preset NAME; `skinlayer material --preset NAME` prints one as a material file.\n"
         "\n"
         "  --colors             instead, each preset's colour, solved: CSV rows\n"
         "                         name,microfacet,reflectance_r,reflectance_g,reflectance_b,srgb\n"
         "                       the directional-hemispherical reflectance at normal incidence (surface and\n"
         "                       subsurface: the sphere's centre under a white furnace) in linear sRGB, and the same\n"
         "                       sRGB-encoded as #RRGGBB (clipped to [0, 1]); a skin's from its spectrum under D65\n"
         "  --microfacet M       with --colors: every preset's interfaces under model M (multiple or single) in\n"
         "                       place of its own, to see what the interfaces' multiple scattering changes\n";
}

namespace {

// "#RRGGBB" of a linear sRGB colour, each channel clipped to [0, 1] and sRGB-encoded.
std::string srgb_hex(const std::array<double, 3>& linear) {
  char text[8];
  const auto byte = [](double value) {
    return static_cast<unsigned>(std::lround(255.0 * srgb_encode(std::clamp(value, 0.0, 1.0))));
  };
  std::snprintf(text, sizeof text, "#%02X%02X%02X", byte(linear[0]), byte(linear[1]), byte(linear[2]));
  return text;
}

void write_preset_colors(const std::optional<MicrofacetModel> microfacet, std::ostream& out) {
  out << "name,microfacet,reflectance_r,reflectance_g,reflectance_b,srgb\n";
  const double normal[] = {0.0};
  for (const PresetInfo& preset : preset_list()) {
    MaterialDocument document = preset_material(preset.name);
    if (microfacet) document.layer.microfacet = *microfacet;
    const Eigen::Array3d reflectance = document_reflectance_rgb(document, normal, parallel_for_threads).front();
    const std::array<double, 3> rgb = {reflectance(0), reflectance(1), reflectance(2)};
    out << preset.name << ',' << microfacet_model_name(document.layer.microfacet);
    for (const double value : rgb) out << ',' << text::format_number(value);
    out << ',' << srgb_hex(rgb) << '\n';
  }
}

}  // namespace

int run_presets_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const std::vector<std::string_view> known = {"microfacet"};
  const std::vector<std::string_view> switches = {"colors"};
  const ParsedFlags flags = ParsedFlags::parse(arguments, known, "skinlayer presets", switches);
  std::optional<MicrofacetModel> microfacet;
  if (const auto text = flags.value("microfacet")) microfacet = microfacet_from_text(*text);
  if (flags.has("colors")) {
    write_preset_colors(microfacet, out);
    return kExitSuccess;
  }
  if (microfacet) throw UsageError("--microfacet needs --colors: the list of names does not depend on it");
  std::size_t width = 0;
  const std::vector<PresetInfo> presets = preset_list();
  for (const PresetInfo& preset : presets) width = std::max(width, preset.name.size());
  for (const PresetInfo& preset : presets) {
    out << preset.name << std::string(width + 2 - preset.name.size(), ' ') << preset.description << '\n';
  }
  return kExitSuccess;
}

}  // namespace skinlayer::cli
