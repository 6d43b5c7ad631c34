#include "app/export/material_export.h"

#include "app/export/color_export.h"
#include "app/export/rgl_channels.h"
#include "app/material/material_json.h"

namespace skinlayer {
namespace {

bool needs_own_spectrum(const ColorMaterial& material, TabulatedFormat format) {
  return format == TabulatedFormat::RglSpectral && material.skin.has_value();
}

std::string rgl_bytes(const RglChannels& channels, const ExportSettings& settings, const ExportProgress& progress) {
  return rgl_file(channels, settings.rgl, settings.description, [&](int done, int total) {
    if (progress) progress(done, total, "theta_o slices");
  });
}

}  // namespace

std::string_view tabulated_format_label(TabulatedFormat format) {
  switch (format) {
    case TabulatedFormat::Scatfun:
      return "SCATFUN";
    case TabulatedFormat::Merl:
      return "MERL";
    case TabulatedFormat::RglSpectral:
      return "RGL tensor, spectral";
    case TabulatedFormat::RglRgb:
      return "RGL tensor, rgb";
  }
  return "";
}

std::string rgl_description(const MaterialDocument& document) { return "skinlayer " + material_json_text(document); }

std::string export_bytes(const ColorTables& tables, const ExportSettings& settings, const SolveOptions& options,
                         const ExportProgress& progress) {
  const auto rows = [&progress](std::string_view unit) {
    return [&progress, unit](int done, int total) {
      if (progress) progress(done, total, unit);
    };
  };
  switch (settings.format) {
    case TabulatedFormat::Scatfun:
      return scatfun_file(tables, settings.nodes, options, rows("polar rows"));
    case TabulatedFormat::Merl:
      return merl_file(tables, rows("theta_h rows"), options.parallel_for);
    case TabulatedFormat::RglRgb:
      return rgl_bytes(rgl_rgb_channels(tables), settings, progress);
    case TabulatedFormat::RglSpectral:
      break;
  }
  // A skin's spectral file needs its wavelengths' own tables, not their colour mix.
  const RglChannels channels =
      tables.material.skin ? rgl_skin_channels(tables.material, options) : rgl_uplifted_channels(tables);
  return rgl_bytes(channels, settings, progress);
}

std::string export_bytes(const ColorMaterial& material, const ExportSettings& settings, const SolveOptions& options,
                         const ExportProgress& progress) {
  if (needs_own_spectrum(material, settings.format)) {
    ColorTables unsolved;
    unsolved.material = material;
    return export_bytes(unsolved, settings, options, progress);
  }
  return export_bytes(solve_color(material, 0.0, options), settings, options, progress);
}

}  // namespace skinlayer
