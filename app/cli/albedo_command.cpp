#include "app/cli/albedo_command.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/numbers.h"
#include "app/cli/numeric_table.h"
#include "app/cli/quoted.h"
#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer::cli {
namespace {

constexpr std::string_view kThetaFlag = "theta-i";
constexpr std::string_view kDefaultThetas = "0,30,60,80";

// The comma-separated list of incidence angles in degrees, each a number in [0, 90].
std::vector<double> parse_theta_list(std::string_view list) {
  std::vector<double> thetas;
  for (const std::string_view item : split_list(list, ',')) {
    const std::optional<double> value = parse_number(item);
    if (!value) {
      throw UsageError(std::string(kThetaFlag) + " = " + quoted(item) + " " + number_rejection(item) +
                       "; give a comma-separated list of angles in [0, 90] degrees, as in "
                       "--theta-i 0,30,60,80");
    }
    if (!(*value >= 0.0 && *value <= 90.0)) {
      throw UsageError(std::string(kThetaFlag) + " = " + format_number(*value) +
                       " is out of range; valid range is [0, 90] (degrees)");
    }
    thetas.push_back(*value);
  }
  return thetas;
}

}  // namespace

std::string albedo_usage() {
  return "Usage: skinlayer albedo [material flags] [--theta-i LIST]\n"
         "\n"
         "Writes, one row per incidence angle, in the order given:\n"
         "  theta_i,reflectance_surface,reflectance_subsurface,reflectance,transmittance,absorptance\n"
         "Directional-hemispherical fractions of the incident flux: reflectance = reflectance_surface +\n"
         "reflectance_subsurface, and reflectance + transmittance + absorptance = 1. transmittance includes any\n"
         "unscattered beam. A stack (--layer, repeated) adds absorptance_layer1, absorptance_layer2, ...: what\n"
         "each layer's medium absorbs; the rest of absorptance is lost to the interfaces' shadowing and to a\n"
         "Lambertian base.\n"
         "\n"
         "  --theta-i LIST\n"
         "      comma-separated incidence angles in degrees from the normal, each in [0, 90]; default " +
         std::string(kDefaultThetas) + ".\n\n" + material_flags_usage() +
         "\n"
         "Example:\n"
         "  skinlayer albedo --albedo 0.9 --g 0.5 --bottom lambert:0.3 --theta-i 0,45,85\n"
         "  skinlayer albedo --layer tau=0.3,albedo=0.95,g=0.8 --layer T=0,albedo=0.99,g=0.7\n";
}

int run_albedo_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const std::vector<std::string_view> flag_names = material_flags_and({kThetaFlag});
  const ParsedFlags flags = ParsedFlags::parse(arguments, flag_names, "skinlayer albedo");
  const Material material = material_from_flags(flags);
  const std::vector<double> thetas_degrees = parse_theta_list(flags.value(kThetaFlag).value_or(kDefaultThetas));

  std::vector<double> thetas_radians;
  for (const double theta : thetas_degrees) thetas_radians.push_back(degrees_to_radians(theta));
  const std::vector<DirectionalAlbedo> albedos = directional_albedo(material, thetas_radians);
  if (albedos.size() != thetas_degrees.size()) {
    throw std::runtime_error("the solver returned " + std::to_string(albedos.size()) + " albedo rows for " +
                             std::to_string(thetas_degrees.size()) + " angles");
  }

  // A stack adds what each of its layers absorbs, after the columns a single layer has.
  std::vector<std::string> layer_columns;
  for (int i = 1; material.layer_count() > 1 && i <= material.layer_count(); ++i) {
    layer_columns.push_back("absorptance_layer" + std::to_string(i));
  }
  std::vector<std::string_view> columns = {"reflectance_surface", "reflectance_subsurface", "reflectance",
                                           "transmittance", "absorptance"};
  columns.insert(columns.end(), layer_columns.begin(), layer_columns.end());
  NumericTable table({"theta_i"}, columns);
  for (std::size_t index = 0; index < albedos.size(); ++index) {
    const DirectionalAlbedo& albedo = albedos[index];
    std::vector<double> row = {thetas_degrees[index], albedo.reflectance_surface, albedo.reflectance_subsurface,
                               albedo.reflectance(),  albedo.transmittance,       albedo.absorptance};
    if (!layer_columns.empty()) row.insert(row.end(), albedo.layer_absorptance.begin(), albedo.layer_absorptance.end());
    table.add_row(row);
  }
  table.require_finite();
  table.write_csv(out);
  return kExitSuccess;
}

}  // namespace skinlayer::cli
