#include "app/cli/export_command.h"

#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/export_flags.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/cli/skin_flag.h"
#include "app/export/material_export.h"
#include "app/material/atomic_file.h"
#include "app/process/parallel_for.h"
#include "app/solution/material_solve.h"

namespace skinlayer::cli {
std::string export_usage() {
  return "Usage: skinlayer export --format bsdf|merl|rgl|blender|blender-3.4|mtlx|gltf\n"
         "                        [material flags] [--albedo A | r,g,b] [--model M] -o FILE\n"
         "                        [--nodes N | --rgb --resolution N | --scene]\n"
         "\n"
         "Writes the solved material in a tabulated format that other programs read, or as a renderer's own\n"
         "shader with fitted parameters.\n"
         "  --format bsdf        the tabulated Fourier BSDF (\"SCATFUN\" v1) that layerlab writes and pbrt-v3's\n"
         "                       \"fourier\" material reads: light from above and from below, reflection and\n"
         "                       transmission, grey or RGB (Y, R, B); the material file's JSON rides along, so\n"
         "                       --material FILE.bsdf reads it back. pbrt-v4 and Mitsuba 3 do not read it.\n"
         "  --nodes N            bsdf: polar nodes per hemisphere, a whole number in [" +
         std::to_string(kMinScatfunNodes) + ", " + std::to_string(kMaxScatfunNodes) + "] (default " +
         std::to_string(kDefaultScatfunNodes) +
         "); lobes narrower\n"
         "                       than the node spacing, 162/(N-1) degrees at 45 (denser at both ends), need more\n"
         "  --format merl        the MERL BRDF .binary (90 x 90 x 180 half/difference bins, float64, RGB):\n"
         "                       reflection only (surface + subsurface), for BRDF viewers and fitting tools;\n"
         "                       34,992,012 bytes. Bins below the horizon hold -1, as the format's readers expect.\n"
         "  --format rgl         the RGL measured-BSDF tensor file (Dupuy & Jakob 2018) that pbrt-v4's and\n"
         "                       Mitsuba 3's \"measured\" material reads: reflection only (surface + subsurface),\n"
         "                       spectral. A skin writes its own spectrum (31 wavelengths, 400-700 nm, 34 MB);\n"
         "                       other materials a smooth spectrum per RGB value (Jakob & Hanika 2019, 7\n"
         "                       wavelengths, 9 MB) whose sRGB under D65 is that value. Within 2% of eval at 99%\n"
         "                       of direction pairs up to 80 degrees, and within 5% at all, for every preset\n"
         "  --rgb                rgl: the rgb form instead, for Mitsuba 3's RGB variants (5 MB)\n"
         "  --resolution N       rgl: sample nodes per side of each slice, a whole number in [" +
         std::to_string(RglOptions::kMinSamples) + ", " + std::to_string(RglOptions::kMaxSamples) + "] (default " +
         std::to_string(RglOptions{}.samples) +
         "); the\n"
         "                       file grows as N^2\n"
         "  --format blender     a Python script for Blender 4.2-5.x (blender -b --python-exit-code 1 --python\n"
         "                       FILE.py) that builds the Principled BSDF `skinlayer fit --target principled`\n"
         "                       finds, distribution Multiscatter GGX, with the material's JSON and the fit's\n"
         "                       errors as data and as custom properties of the Blender material; in Blender\n"
         "                       3.x it stops with one line (docs/examples/blender)\n"
         "  --format blender-3.4 the same for Blender 3.x's Principled BSDF (`fit --target principled-3.4`,\n"
         "                       distribution GGX); in Blender 4 and later it stops with one line\n"
         "  --scene              blender, blender-3.4: also replace the scene by a preview: a unit sphere, an\n"
         "                       orthographic camera on +z, a sun from the upper left, Cycles on the CPU\n"
         "  --format mtlx        a MaterialX 1.39 document with an OpenPBR Surface 1.1 material, the one\n"
         "                       `skinlayer fit --target openpbr` finds (Maya, Arnold, 3ds Max, Houdini, Unreal);\n"
         "                       the fit's report and the material's JSON ride along as the nodes' doc strings\n"
         "                       (docs/examples/openpbr)\n"
         "  --format gltf        a glTF 2.0 file (.gltf, its buffer embedded) with a unit sphere wearing the\n"
         "                       material `skinlayer fit --target gltf` finds: metallic-roughness with the KHR\n"
         "                       extensions it needs (three.js, Babylon.js, Godot, Blender's importer;\n"
         "                       docs/examples/gltf)\n" +
         rgb_albedo_usage() +
         "  --model M            subsurface model: stam (default), lambert or hk\n"
         "  -o, --output FILE    the file to write (required; written whole or not at all)\n"
         "Progress goes to stderr. A --skin exports its spectrum's linear sRGB (CIE 1931 2-degree, D65), as eval\n"
         "writes it; --wavelength NM exports one wavelength's grey material instead.\n"
         "\n" +
         skin_flags_usage() + "\n" + material_flags_usage();
}

int run_export_command(std::span<const std::string_view> arguments, std::ostream& out, std::ostream& progress) {
  std::vector<std::string_view> known = material_flags_and({kModelFlag, kSkinFlag, kWavelengthFlag, "output"});
  known.insert(known.end(), export_flag_names().begin(), export_flag_names().end());
  const ParsedFlags flags = ParsedFlags::parse(arguments, known, "skinlayer export", export_switch_names());
  const ExportRequest request = export_request_from_flags(flags);
  const std::optional<std::string_view> output = flags.value("output");
  if (!output || output->empty()) throw UsageError("export needs -o FILE (the file to write)");
  if (const std::optional<std::string> missing = missing_output_folder(std::string(*output))) {
    throw std::runtime_error(*missing);
  }
  MaterialDocument document = material_document_from_flags(flags, AlbedoFlag::GreyOrRgb);
  if (const std::optional<double> wavelength = wavelength_from_flags(flags)) {
    document = document_at_wavelength(document, *wavelength);
  }
  const auto start = std::chrono::steady_clock::now();
  const auto wrote = [&](std::string_view label, std::size_t bytes) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out << "wrote " << *output << " (" << label << ", " << bytes << " bytes, " << std::round(seconds * 10.0) / 10.0
        << " s)\n";
  };
  if (const auto* fitted = std::get_if<FittedExportSettings>(&request)) {
    if (model_from_flags(flags, SubsurfaceModel::Stam) != SubsurfaceModel::Stam) {
      throw UsageError(
          "--model is for the tabulated formats: the fitted formats (blender, blender-3.4, mtlx, gltf) fit the layer "
          "model (stam)");
    }
    progress << "export: fitting " << fitted_format_label(fitted->format) << "\n" << std::flush;
    const std::string text = fitted_export_text(document, *fitted, parallel_for_threads);
    write_file_atomically(std::string(*output), text);
    wrote(fitted_format_label(fitted->format), text.size());
    return kExitSuccess;
  }
  ExportSettings settings = std::get<ExportSettings>(request);
  ColorMaterial material = color_material(document);
  material.model = model_from_flags(flags, document.model);
  settings.description = rgl_description(document);

  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  if (settings.format == TabulatedFormat::RglSpectral && material.skin) {
    progress << "export: solving the skin at each of its wavelengths\n" << std::flush;
  }
  // One progress line per tenth of the rows (the rows finish on several threads).
  std::mutex progress_lock;
  int reported = 0;
  const auto report = [&](int done, int total, std::string_view rows) {
    const std::lock_guard lock(progress_lock);
    if (done * 10 / total <= reported && done != total) return;
    reported = done * 10 / total;
    progress << "export: " << done << " of " << total << " " << rows << "\n" << std::flush;
  };
  const std::string bytes = export_bytes(material, settings, options, report);
  write_file_atomically(std::string(*output), bytes);
  wrote(tabulated_format_label(settings.format), bytes.size());
  return kExitSuccess;
}

}  // namespace skinlayer::cli
