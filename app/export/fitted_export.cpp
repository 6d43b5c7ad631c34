#include "app/export/fitted_export.h"

#include "app/export/blender_script.h"
#include "app/export/openpbr_materialx.h"
#include "app/solution/shader_fit.h"

namespace skinlayer {

std::string_view fitted_format_label(FittedFormat format) {
  switch (format) {
    case FittedFormat::BlenderScript:
      return "Blender script, Principled BSDF";
    case FittedFormat::MaterialX:
      return "MaterialX, OpenPBR Surface";
  }
  return "";
}

std::string fitted_export_text(const MaterialDocument& document, const FittedExportSettings& settings,
                               const ParallelFor& parallel_for) {
  MaterialDocument fitted = document;
  fitted.model = SubsurfaceModel::Stam;  // the fit is of the layer model, as the file's material then says
  if (settings.format == FittedFormat::MaterialX) return openpbr_materialx(fitted, fit_openpbr(fitted, parallel_for));
  BlenderScriptSettings script;
  script.scene = settings.scene;
  return blender_script(fitted, fit_principled(fitted, parallel_for), script);
}

}  // namespace skinlayer
