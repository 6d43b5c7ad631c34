// A shader fit's report as JSON: what `skinlayer fit` writes, and what the exported Blender script and MaterialX file
// carry beside their material. The parameters by the shader's own names; errors per channel, [red, green, blue].
#pragma once

#include <nlohmann/json.hpp>

#include "app/solution/gltf_fit_document.h"
#include "app/solution/principled_fit_document.h"
#include "app/solution/shader_fit.h"

namespace skinlayer {

// {"target": "principled", "renderer", "parameters": {base_color, metallic, roughness, ior, ..., "distribution"},
//  "subsurface_radius_source", "albedo_matched_at_normal_incidence", "albedo_miss_at_normal_incidence",
//  "errors": {lobe_rms, lobe_worst, albedo_rms, albedo_worst}}: Blender 4.x-5.x's node, its inputs by the sockets'
// names in snake_case ("Specular IOR Level" is specular_ior_level; colours as [r, g, b]).
nlohmann::ordered_json principled_fit_json(const DocumentFit<CyclesPrincipledFit>& fit);

// The same for "principled-3.4": Blender 3.4's node, its inputs by its own names (specular, clearcoat, ...).
nlohmann::ordered_json principled_3_4_fit_json(const DocumentFit<PrincipledFit>& fit);

// The same for "openpbr", its parameters by OpenPBR Surface 1.1's input names (subsurface_radius in millimetres).
nlohmann::ordered_json openpbr_fit_json(const DocumentFit<OpenPbrFit>& fit);

// The same for "gltf", its parameters by glTF's names (the metallic-roughness factors and the KHR extensions').
nlohmann::ordered_json gltf_fit_json(const DocumentFit<GltfFit>& fit);

}  // namespace skinlayer
