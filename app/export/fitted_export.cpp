#include "app/export/fitted_export.h"

#include "app/export/blender_script.h"
#include "app/export/gltf_export.h"
#include "app/export/openpbr_materialx.h"
#include "app/solution/gltf_fit_document.h"
#include "app/solution/principled_fit_document.h"
#include "app/solution/shader_fit.h"

namespace skinlayer {

std::string_view fitted_format_label(FittedFormat format) {
  switch (format) {
    case FittedFormat::BlenderScript:
      return "Blender script, Principled BSDF of Blender 4.2-5.x";
    case FittedFormat::BlenderScript34:
      return "Blender script, Principled BSDF of Blender 3.4";
    case FittedFormat::MaterialX:
      return "MaterialX, OpenPBR Surface";
    case FittedFormat::Gltf:
      return "glTF 2.0, metallic-roughness with KHR extensions";
  }
  return "";
}

std::string fitted_export_text(const MaterialDocument& document, const FittedExportSettings& settings,
                               const ParallelFor& parallel_for) {
  MaterialDocument fitted = document;
  fitted.model = SubsurfaceModel::Stam;  // the fit is of the layer model, as the file's material then says
  BlenderScriptSettings script;
  script.scene = settings.scene;
  switch (settings.format) {
    case FittedFormat::BlenderScript:
      return blender_script(fitted, fit_cycles_principled(fitted, parallel_for), script);
    case FittedFormat::BlenderScript34:
      return blender_3_4_script(fitted, fit_principled(fitted, parallel_for), script);
    case FittedFormat::MaterialX:
      return openpbr_materialx(fitted, fit_openpbr(fitted, parallel_for));
    case FittedFormat::Gltf:
      return gltf_export(fitted, fit_gltf(fitted, parallel_for));
  }
  return "";
}

}  // namespace skinlayer
