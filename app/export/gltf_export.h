// A fitted glTF 2.0 material (core/fit/gltf_fit.h) as a .gltf file: what `skinlayer export --format gltf` writes,
// for three.js, Babylon.js, Godot and the engines' glTF importers. JSON (nlohmann-json), never by hand:
//   asset      {"version": "2.0", "generator": "skinlayer"}
//   scene 0    one node holding mesh 0: a UV sphere of radius 1 (POSITION, NORMAL, uint16 indices), its bytes in one
//              buffer embedded as a base64 data URI (positions, normals, indices: three bufferViews and accessors,
//              POSITION with its min and max, as the specification requires)
//   material 0 pbrMetallicRoughness's factors and, for each extension the fit uses (a factor off its default), that
//              extension: KHR_materials_ior, _specular, _sheen, _clearcoat; extensionsUsed lists exactly these.
//              Its extras: "skinlayer_fit" (the fit's report, fit_report_json's form),
//              "gltf_model_albedo_at_normal_incidence" (the fitted model's, core/targets/gltf_pbr.h: what a furnace
//              test of a renderer compares with), "gltf_model_albedo_at_degrees" (the same with the view at 30 and 60
//              degrees, keyed "30", "60") and "skinlayer_material" (the material file's JSON).
// Colours are linear (glTF's factors are linear), as skinlayer's are.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/material/material_document.h"
#include "app/solution/shader_fit.h"
#include "core/fit/gltf_fit.h"

namespace skinlayer {


// The names of the KHR extensions the material's factors need, in a fixed order (ior, specular, sheen, clearcoat).
std::vector<std::string> gltf_extensions_used(const GltfPbrParameters& parameters);

// The glTF material object: name, pbrMetallicRoughness, extensions; `extras` attached where not null.
nlohmann::ordered_json gltf_material(const GltfPbrParameters& parameters, const std::string& name,
                                     const nlohmann::ordered_json& extras);

// The whole asset with the sphere (rings x segments quads; rings >= 2, segments >= 3) and the material.
nlohmann::ordered_json gltf_asset(const GltfPbrParameters& parameters, const std::string& name,
                                  const nlohmann::ordered_json& extras, int rings = 32, int segments = 64);

// The .gltf text for a fitted document (two-space indented, final newline).
std::string gltf_export(const MaterialDocument& document, const DocumentFit<GltfFit>& fit);

// RFC 4648 base64 with padding.
std::string base64_encode(const std::vector<unsigned char>& bytes);

}  // namespace skinlayer
