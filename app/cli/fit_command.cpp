#include "app/cli/fit_command.h"

#include <optional>
#include <string>

#include "app/cli/errors.h"
#include "app/cli/export_flags.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/skin_flag.h"
#include "app/export/principled_fit_json.h"
#include "app/material/atomic_file.h"
#include "app/process/parallel_for.h"
#include "app/solution/shader_fit.h"

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
  const std::string text = principled_fit_json(fit_principled(document, parallel_for_threads)).dump(2) + "\n";
  if (output) {
    write_file_atomically(std::string(*output), text);
    out << "wrote " << *output << "\n";
  } else {
    out << text;
  }
  return kExitSuccess;
}

}  // namespace skinlayer::cli
