#include "app/cli/albedo_command.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/numeric_table.h"
#include "app/cli/skin_flag.h"
#include "app/cli/theta_list.h"
#include "app/material/color_channels.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_albedo.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"
#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer::cli {

std::string albedo_usage() {
  return "Usage: skinlayer albedo [material flags] [--albedo A | r,g,b] [--theta-i LIST]\n"
         "\n"
         "Writes, one row per incidence angle, in the order given:\n"
         "  theta_i,reflectance_surface,reflectance_subsurface,reflectance,transmittance,absorptance\n"
         "Directional-hemispherical fractions of the incident flux: reflectance = reflectance_surface +\n"
         "reflectance_subsurface, and reflectance + transmittance + absorptance = 1. transmittance includes any\n"
         "unscattered beam. A stack (--layer, repeated) adds absorptance_layer1, absorptance_layer2, ...: what\n"
         "each layer's medium absorbs; the rest of absorptance is lost to the interfaces' shadowing and to a\n"
         "Lambertian base.\n"
         "An RGB albedo (--albedo r,g,b, a preset, a material file or a stack's albedo=r:g:b) writes one column per\n"
         "channel for what depends on colour: reflectance_surface, then reflectance_subsurface_r, _g, _b,\n"
         "reflectance_*, transmittance_*, absorptance_* (and a stack's absorptance_layerK_*), each with _r, _g and\n"
         "_b. Each channel is the grey solve with that channel's albedo. --albedo A makes any material grey.\n"
         "A --skin writes the same RGB columns: each the spectrum's linear sRGB under D65 (CIE 1931 2-degree\n"
         "observer), from one solve per wavelength, 400-700 nm in 10 nm steps; --wavelength NM gives one\n"
         "wavelength's grey columns instead. `skinlayer spectrum` writes the spectrum itself.\n"
         "\n"
         "  --theta-i LIST\n"
         "      comma-separated incidence angles in degrees from the normal, each in [0, 90]; default " +
         std::string(kDefaultThetas) + ".\n" + rgb_albedo_usage() + "\n" + skin_flags_usage() + "\n" +
         material_flags_usage() +
         "\n"
         "Example:\n"
         "  skinlayer albedo --albedo 0.9 --g 0.5 --bottom lambert:0.3 --theta-i 0,45,85\n"
         "  skinlayer albedo --layer tau=0.3,albedo=0.95,g=0.8 --layer T=0,albedo=0.99,g=0.7\n"
         "  skinlayer albedo --preset skin-fair --theta-i 0,60\n";
}

namespace {

// A stack's absorptance_layer1, absorptance_layer2, ...: what each layer's medium absorbs. None for one layer.
std::vector<std::string> layer_absorptance_columns(const Material& material) {
  std::vector<std::string> columns;
  for (int i = 1; material.layer_count() > 1 && i <= material.layer_count(); ++i) {
    columns.push_back("absorptance_layer" + std::to_string(i));
  }
  return columns;
}

// One channel's values at one angle that depend on colour, in column order after reflectance_surface.
std::vector<double> colour_dependent_values(const DirectionalAlbedo& albedo) {
  std::vector<double> values = {albedo.reflectance_subsurface, albedo.reflectance(), albedo.transmittance,
                                albedo.absorptance};
  values.insert(values.end(), albedo.layer_absorptance.begin(), albedo.layer_absorptance.end());
  return values;
}

// The table: reflectance_surface (the surface term has no albedo in it: one column), then each quantity that
// depends on colour, as one column for a grey material (one channel) or as _r, _g and _b (three channels).
// channels[c] are channel c's rows, one per angle.
NumericTable albedo_table(const Material& material, std::span<const double> thetas_degrees,
                          const std::vector<const std::vector<DirectionalAlbedo>*>& channels) {
  std::vector<std::string> quantities = {"reflectance_subsurface", "reflectance", "transmittance", "absorptance"};
  const std::vector<std::string> layer_columns = layer_absorptance_columns(material);
  quantities.insert(quantities.end(), layer_columns.begin(), layer_columns.end());
  std::vector<std::string> columns = {"reflectance_surface"};
  for (const std::string& quantity : quantities) {
    const std::vector<std::string> names = channels.size() == 1 ? std::vector{quantity} : channel_columns(quantity);
    columns.insert(columns.end(), names.begin(), names.end());
  }
  NumericTable table({"theta_i"}, columns);
  for (std::size_t index = 0; index < thetas_degrees.size(); ++index) {
    std::vector<std::vector<double>> values;
    for (const std::vector<DirectionalAlbedo>* rows : channels) {
      values.push_back(colour_dependent_values((*rows)[index]));
    }
    std::vector<double> row = {thetas_degrees[index], (*channels.front())[index].reflectance_surface};
    for (std::size_t q = 0; q < quantities.size(); ++q) {
      for (const std::vector<double>& channel : values) row.push_back(channel[q]);
    }
    table.add_row(row);
  }
  return table;
}

}  // namespace

int run_albedo_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const std::vector<std::string_view> flag_names = material_flags_and({kThetaFlag, kSkinFlag, kWavelengthFlag});
  const ParsedFlags flags = ParsedFlags::parse(arguments, flag_names, "skinlayer albedo");
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  if (const std::optional<double> wavelength = wavelength_from_flags(flags)) {
    document = document_at_wavelength(document, *wavelength);
  }
  const std::vector<double> thetas_degrees = parse_theta_list(flags.value(kThetaFlag).value_or(kDefaultThetas));

  std::vector<double> thetas_radians;
  for (const double theta : thetas_degrees) thetas_radians.push_back(degrees_to_radians(theta));
  const std::vector<std::vector<DirectionalAlbedo>> channels =
      document_albedo(document, thetas_radians, parallel_for_threads);
  std::vector<const std::vector<DirectionalAlbedo>*> rows;
  for (const std::vector<DirectionalAlbedo>& channel : channels) rows.push_back(&channel);
  const Material& material = document.grey() ? document.layer : color_channels(document).materials.front();
  NumericTable table = albedo_table(material, thetas_degrees, rows);
  table.require_finite();
  table.write_csv(out);
  return kExitSuccess;
}

}  // namespace skinlayer::cli
