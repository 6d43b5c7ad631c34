// A material exported as a renderer's own shader, with fitted parameters instead of tables: the one path that
// `skinlayer export --format blender|blender-3.4|mtlx|gltf` and the previewer's buttons take.
//   Blender (.py): a script that builds the Principled BSDF of Blender 4.2-5.x, or of Blender 3.x
//   (app/export/blender_script.h);
//   MaterialX (.mtlx): an OpenPBR Surface material (app/export/openpbr_materialx.h);
//   glTF (.gltf): a sphere wearing a glTF 2.0 material with the KHR extensions it needs (app/export/gltf_export.h).
#pragma once

#include <string>
#include <string_view>

#include "app/material/material_document.h"
#include "core/parallel_for.h"

namespace skinlayer {

enum class FittedFormat { BlenderScript, BlenderScript34, MaterialX, Gltf };

struct FittedExportSettings {
  FittedFormat format = FittedFormat::BlenderScript;
  bool scene = false;  // Blender (either): also build a preview scene
};

// "Blender script, Principled BSDF", "MaterialX, OpenPBR Surface", ...
std::string_view fitted_format_label(FittedFormat format);

// Fits the document's layer model (Stam's, whatever model it names; app/solution/shader_fit.h) and writes the
// file's text, whose material names that model. Throws ParameterError for a material out of range.
std::string fitted_export_text(const MaterialDocument& document, const FittedExportSettings& settings,
                               const ParallelFor& parallel_for);

}  // namespace skinlayer
