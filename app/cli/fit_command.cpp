#include "app/cli/fit_command.h"

#include <optional>
#include <string>

#include "app/cli/errors.h"
#include "app/cli/export_flags.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/skin_flag.h"
#include "app/export/fit_report_json.h"
#include "app/export/gltf_export.h"
#include "app/figures/fit_comparison.h"
#include "app/material/atomic_file.h"
#include "app/material/picture_metadata.h"
#include "app/process/parallel_for.h"
#include "app/render/png_export.h"
#include "app/solution/gltf_fit_document.h"
#include "app/solution/principled_fit_document.h"
#include "app/solution/shader_fit.h"

namespace skinlayer::cli {
namespace {

constexpr int kPictureSphere = 256;  // --picture: each sphere's side in pixels

}  // namespace

std::string fit_usage() {
  return "Usage: skinlayer fit --target principled|principled-3.4|openpbr|gltf [material flags]\n"
         "                     [--albedo A | r,g,b] [-o FILE] [--picture FILE.png]\n"
         "\n"
         "Finds the parameters of a renderer's shader that best reproduce the material's BRDF (its layer model), and\n"
         "says how far they are from it. The metric is the cosine-weighted BRDF (surface and subsurface) on fixed\n"
         "pairs of directions: light at 0-80 degrees, the view over the hemisphere and again about the mirror\n"
         "direction (docs/model.md section 22.2). The directional albedo at normal incidence is matched exactly,\n"
         "through the diffuse colour.\n"
         "  principled  the Principled BSDF of Blender 4.2-5.x as Cycles evaluates it, its default\n"
         "              \"Multiscatter GGX\" (section 22.1.1): the material's own indices (IOR; a clear top layer\n"
         "              over a refracting interface becomes a coat of the top's index), fitted base colour,\n"
         "              roughness, Specular IOR Level, Diffuse Roughness (4.3 and later), sheen weight and\n"
         "              roughness, coat roughness. Subsurface Weight stays 0 as fitted, with its radius, scale\n"
         "              and anisotropy set.\n"
         "  principled-3.4\n"
         "              Blender 3.4's Principled BSDF, its \"GGX\" distribution (section 22.1): fitted base\n"
         "              colour, roughness, specular, sheen, clearcoat and its roughness; metallic, the tints and\n"
         "              transmission stay 0. Subsurface stays 0 as fitted, with its colour and radius set.\n"
         "  openpbr     OpenPBR Surface 1.1 (section 22.3): the material's own indices (specular_ior; a clear top\n"
         "              layer over a refracting interface becomes a coat of the top's index), fitted diffuse colour\n"
         "              and roughness, specular roughness and weight, fuzz weight and roughness, coat roughness.\n"
         "              Where the radius is known, subsurface_weight is 1 (at the BRDF's scale the same lobe).\n"
         "  gltf        glTF 2.0's metallic-roughness material with KHR_materials_ior, _specular, _sheen and\n"
         "              _clearcoat, as the Khronos specification writes it (section 22.7): the material's own\n"
         "              index, fitted base colour, roughness, specular, sheen and clearcoat roughness. glTF has\n"
         "              no subsurface radius among these extensions.\n"
         "The subsurface radius comes from the material's mean free path 1/mu_t and g (its deepest layer's; a skin's\n"
         "dermis, per channel through its spectrum): OpenPBR's is the mean free path in mm; Blender's random walk\n"
         "reads 1/((1-g) mu_t), in metres. A material without a physical length has none, and the output says so.\n"
         "Writes JSON: the parameters, where the radius came from, whether the albedo could be matched and by how\n"
         "much it misses where not, and the errors per channel (red, green, blue): the lobe's RMS and worst\n"
         "difference relative to its largest value, and the directional albedo's RMS and worst relative error at\n"
         "0, 20, 40, 60 and 80 degrees.\n"
         "\n"
         "  --target T\n"
         "      principled, principled-3.4, openpbr or gltf.\n"
         "  -o, --output FILE\n"
         "      write the JSON there instead of to standard output.\n"
         "  --picture FILE.png\n"
         "      also draw what the fit loses: the material's sphere, the fitted shader's and the map of their\n"
         "      luminance's relative difference (blue -25%, red +25%), under a light 45 degrees from the left;\n"
         "      the PNG carries the material and the fit's report.\n" +
         rgb_albedo_usage() + "\n" + skin_flags_usage() + "\n" + material_flags_usage() +
         "\n"
         "Example:\n"
         "  skinlayer fit --target principled --preset jade\n"
         "  skinlayer fit --target openpbr --preset skin-fair -o skin-fair.openpbr.json\n";
}

int run_fit_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const ParsedFlags flags = ParsedFlags::parse(
      arguments, material_flags_and({kSkinFlag, kWavelengthFlag, "target", "output", "picture"}), "skinlayer fit");
  const std::optional<std::string_view> target_name = flags.value("target");
  if (!target_name) {
    throw UsageError(
        "fit needs --target principled, principled-3.4, openpbr or gltf (the shader whose parameters to find)");
  }
  if (*target_name != "principled" && *target_name != "principled-3.4" && *target_name != "openpbr" &&
      *target_name != "gltf") {
    throw ParameterError("--target '" + std::string(*target_name) +
                         "' is not one of principled, principled-3.4, openpbr, gltf");
  }
  const std::optional<std::string_view> output = flags.value("output"), picture = flags.value("picture");
  for (const std::optional<std::string_view>& path : {output, picture}) {
    if (!path) continue;
    if (path->empty()) throw UsageError("fit: --output and --picture need a file name");
    if (const std::optional<std::string> missing = missing_output_folder(std::string(*path))) {
      throw std::runtime_error(*missing);
    }
  }
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  if (const std::optional<double> wavelength = wavelength_from_flags(flags)) {
    document = document_at_wavelength(document, *wavelength);
  }
  nlohmann::ordered_json report;
  figures::FittedBrdf fitted;
  std::string label;
  if (*target_name == "principled") {
    const DocumentFit<CyclesPrincipledFit> fit = fit_cycles_principled(document, parallel_for_threads);
    report = principled_fit_json(fit);
    fitted = fitted_brdf_cosine(fit.fit);
    label = "Blender 4 Principled";
  } else if (*target_name == "principled-3.4") {
    const DocumentFit<PrincipledFit> fit = fit_principled(document, parallel_for_threads);
    report = principled_3_4_fit_json(fit);
    fitted = fitted_brdf_cosine(fit.fit);
    label = "Blender 3.4 Principled";
  } else if (*target_name == "gltf") {
    const DocumentFit<GltfFit> fit = fit_gltf(document, parallel_for_threads);
    report = gltf_fit_json(fit);
    fitted = fitted_brdf_cosine(fit.fit);
    label = "glTF 2.0";
  } else {
    const DocumentFit<OpenPbrFit> fit = fit_openpbr(document, parallel_for_threads);
    report = openpbr_fit_json(fit);
    fitted = fitted_brdf_cosine(fit.fit);
    label = "OpenPBR Surface";
  }
  if (picture) {
    const figures::Font font;
    const figures::FitComparison comparison =
        figures::draw_fit_comparison(document, fitted, label, font, kPictureSphere, parallel_for_threads);
    write_png(comparison.image, std::string(*picture), {picture_metadata(document, report)});
  }
  const std::string text = report.dump(2) + "\n";
  if (output) {
    write_file_atomically(std::string(*output), text);
    out << "wrote " << *output << "\n";
  } else {
    out << text;
  }
  if (picture) out << "wrote " << *picture << "\n";
  return kExitSuccess;
}

}  // namespace skinlayer::cli
