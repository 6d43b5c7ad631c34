#include "app/cli/fit_command.h"

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/export_flags.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/skin_flag.h"
#include "app/material/atomic_file.h"
#include "app/material/color_channels.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_albedo.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"
#include "core/fit/principled_fit.h"
#include "core/material.h"

namespace skinlayer::cli {

std::string fit_usage() {
  return "Usage: skinlayer fit --target principled [material flags] [--albedo A | r,g,b] [-o FILE]\n"
         "\n"
         "Finds the parameters of Blender 3.4's Principled BSDF that best reproduce the material's BRDF, and says\n"
         "how far they are from it. The metric is the cosine-weighted BRDF (surface and subsurface) on fixed pairs\n"
         "of directions: light at 0-80 degrees, the view over the hemisphere (docs/model.md section 22.2). The\n"
         "directional albedo at normal incidence is matched exactly, through the base colour. Fitted: base colour,\n"
         "roughness, specular, sheen, clearcoat and clearcoat roughness; metallic and the tints stay 0, and\n"
         "transmission and subsurface scattering are not fitted yet.\n"
         "Writes JSON: the parameters, whether the albedo could be matched and by how much it misses where not (a\n"
         "dark channel whose specular alone reflects more than it does), and the errors per channel (red, green,\n"
         "blue): the lobe's RMS and worst difference relative to its largest value, and the directional albedo's\n"
         "RMS and worst relative error at 0, 20, 40, 60 and 80 degrees.\n"
         "\n"
         "  --target T\n"
         "      principled (Blender 3.4's Principled BSDF, its \"GGX\" distribution); openpbr is not built yet.\n"
         "  -o, --output FILE\n"
         "      write the JSON there instead of to standard output.\n" +
         rgb_albedo_usage() + "\n" + skin_flags_usage() + "\n" + material_flags_usage() +
         "\n"
         "Example:\n"
         "  skinlayer fit --target principled --preset jade\n";
}

namespace {

nlohmann::json channels(const Rgb& values) { return {values(0), values(1), values(2)}; }

// The material's BRDF on the fit's pairs and its directional albedo at 0, 20, ..., 80 degrees, in RGB.
PrincipledFitTarget fit_target(const MaterialDocument& document) {
  PrincipledFitTarget target;
  target.pairs = principled_fit_pairs();
  std::vector<double> theta_i, theta_o, phi;
  for (const DirectionPair& pair : target.pairs) {
    theta_i.push_back(radians_to_degrees(std::acos(pair.omega_i.z())));
    theta_o.push_back(radians_to_degrees(std::acos(pair.omega_o.z())));
    phi.push_back(radians_to_degrees(std::atan2(pair.omega_o.y(), pair.omega_o.x())));  // the light is at azimuth 0
  }
  const SolvedDocument solved = solve_document(document, SubsurfaceModel::Stam, parallel_for_threads);
  const std::size_t n = target.pairs.size(), width = static_cast<std::size_t>(value_channels(solved));
  std::vector<double> surface(n), subsurface(n * width), brdf(n * width), btdf(n * width);
  evaluate_pairs(solved, theta_i, theta_o, phi, {surface, subsurface, brdf, btdf}, parallel_for_threads);
  for (std::size_t k = 0; k < n; ++k) {
    Rgb value;
    for (int c = 0; c < 3; ++c) value(c) = brdf[k * width + (width == 1 ? 0 : static_cast<std::size_t>(c))];
    target.brdf_cosine.push_back(value * target.pairs[k].omega_i.z());
  }
  for (int degrees = 0; degrees <= 80; degrees += 20) target.albedo_angles.push_back(degrees_to_radians(degrees));
  const std::vector<std::vector<DirectionalAlbedo>> albedo =
      document_albedo(document, target.albedo_angles, parallel_for_threads);
  for (std::size_t a = 0; a < target.albedo_angles.size(); ++a) {
    Rgb value;
    for (int c = 0; c < 3; ++c)
      value(c) = albedo[albedo.size() == 1 ? 0 : static_cast<std::size_t>(c)][a].reflectance();
    target.albedo.push_back(value);
  }
  return target;
}

}  // namespace

int run_fit_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const ParsedFlags flags = ParsedFlags::parse(
      arguments, material_flags_and({kSkinFlag, kWavelengthFlag, "target", "output"}), "skinlayer fit");
  const std::optional<std::string_view> target_name = flags.value("target");
  if (!target_name) throw UsageError("fit needs --target principled (the shader whose parameters to find)");
  if (*target_name == "openpbr") throw ParameterError("fit: --target openpbr is not built yet; principled is");
  if (*target_name != "principled") {
    throw ParameterError("--target '" + std::string(*target_name) + "' is not one of principled, openpbr");
  }
  const std::optional<std::string_view> output = flags.value("output");
  if (output) {
    if (const std::optional<std::string> missing = missing_output_folder(std::string(*output))) {
      throw std::runtime_error(*missing);
    }
  }
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  if (const std::optional<double> wavelength = wavelength_from_flags(flags)) {
    document = document_at_wavelength(document, *wavelength);
  }
  const PrincipledFit fit = fit_principled(fit_target(document));
  const PrincipledParameters& p = fit.parameters;
  const nlohmann::json result = {{"target", "principled"},
                                 {"renderer", "Blender 3.4 (Cycles), Principled BSDF, distribution GGX"},
                                 {"parameters",
                                  {{"base_color", channels(p.base_color)},
                                   {"metallic", p.metallic},
                                   {"specular", p.specular},
                                   {"specular_tint", p.specular_tint},
                                   {"roughness", p.roughness},
                                   {"sheen", p.sheen},
                                   {"sheen_tint", p.sheen_tint},
                                   {"clearcoat", p.clearcoat},
                                   {"clearcoat_roughness", p.clearcoat_roughness},
                                   {"transmission", p.transmission},
                                   {"subsurface", p.subsurface}}},
                                 {"albedo_matched_at_normal_incidence", fit.albedo_matched},
                                 {"albedo_miss_at_normal_incidence", channels(fit.albedo_miss)},
                                 {"errors",
                                  {{"lobe_rms", channels(fit.lobe_rms)},
                                   {"lobe_worst", channels(fit.lobe_worst)},
                                   {"albedo_rms", channels(fit.albedo_rms)},
                                   {"albedo_worst", channels(fit.albedo_worst)}}}};
  const std::string text = result.dump(2) + "\n";
  if (output) {
    write_file_atomically(std::string(*output), text);
    out << "wrote " << *output << "\n";
  } else {
    out << text;
  }
  return kExitSuccess;
}

}  // namespace skinlayer::cli
