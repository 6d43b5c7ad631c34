#include "app/cli/spectrum_command.h"

#include <string>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/numeric_table.h"
#include "app/cli/skin_flag.h"
#include "app/cli/theta_list.h"
#include "app/material/color_channels.h"
#include "core/conventions.h"
#include "core/skin/skin_spectrum.h"

namespace skinlayer::cli {

std::string spectrum_usage() {
  return "Usage: skinlayer spectrum [material flags] [--skin KEY=VALUE,...] [--theta-i LIST] [--wavelength NM]\n"
         "\n"
         "Writes, one row per incidence angle and wavelength (angles in the order given, wavelengths ascending):\n"
         "  theta_i,wavelength_nm,reflectance,transmittance,absorptance\n"
         "Directional-hemispherical fractions of the incident flux at each wavelength, the surface reflection\n"
         "included; reflectance + transmittance + absorptance = 1. A stack (a --skin, or --layer repeated) adds\n"
         "absorptance_layer1, absorptance_layer2, ...: what each layer's medium absorbs.\n"
         "With --skin the layers come from the chromophores at each wavelength of 400-700 nm in 10 nm steps (or the\n"
         "one --wavelength); the top interface does not depend on the wavelength. A grey material has a flat\n"
         "spectrum: its one solve is written at every wavelength. An RGB material has no spectrum: give --albedo A\n"
         "or --skin.\n"
         "\n"
         "  --theta-i LIST\n"
         "      comma-separated incidence angles in degrees from the normal, each in [0, 90]; default " +
         std::string(kDefaultThetas) + ".\n" + skin_flags_usage() + "\n" + material_flags_usage() +
         "\n"
         "Example:\n"
         "  skinlayer spectrum --skin melanin=0.05,blood=0.02 --theta-i 8\n"
         "  skinlayer spectrum --albedo 0.9 --T 0.5 --theta-i 0,60\n";
}

int run_spectrum_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const ParsedFlags flags =
      ParsedFlags::parse(arguments, material_flags_and({kThetaFlag, kSkinFlag, kWavelengthFlag}), "skinlayer spectrum");
  MaterialDocument document = material_document_from_flags(flags);
  const std::vector<double> thetas_degrees = parse_theta_list(flags.value(kThetaFlag).value_or(kDefaultThetas));
  std::vector<double> thetas;
  for (const double theta : thetas_degrees) thetas.push_back(degrees_to_radians(theta));
  const std::optional<double> one_wavelength = wavelength_from_flags(flags);
  const std::vector<double> wavelengths =
      one_wavelength ? std::vector<double>{*one_wavelength} : skin_color_wavelengths();

  // rows[k][a]: wavelength k, angle a.
  std::vector<std::vector<DirectionalAlbedo>> rows;
  int layers = 1;
  if (document.skin) {
    rows = skin_directional_albedo(*document.skin, document.layer, wavelengths, thetas);
    layers = 2;
  } else {
    const Material material = single_channel(document);
    rows.assign(wavelengths.size(), directional_albedo(material, thetas));
    layers = material.layer_count();
  }
  std::vector<std::string> columns = {"reflectance", "transmittance", "absorptance"};
  for (int i = 1; layers > 1 && i <= layers; ++i) columns.push_back("absorptance_layer" + std::to_string(i));
  NumericTable table({"theta_i", "wavelength_nm"}, columns);
  for (std::size_t a = 0; a < thetas.size(); ++a) {
    for (std::size_t k = 0; k < wavelengths.size(); ++k) {
      const DirectionalAlbedo& row = rows[k][a];
      std::vector<double> values = {thetas_degrees[a], wavelengths[k], row.reflectance(), row.transmittance,
                                    row.absorptance};
      values.insert(values.end(), row.layer_absorptance.begin(), row.layer_absorptance.end());
      table.add_row(values);
    }
  }
  table.require_finite();
  table.write_csv(out);
  return kExitSuccess;
}

}  // namespace skinlayer::cli
