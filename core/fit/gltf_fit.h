// The glTF 2.0 material (core/targets/gltf_pbr.h) that best reproduces a reflectance: the first
// half of `skinlayer fit --target gltf`, with the metric of brdf_fit_target.h, as the OpenPBR fit does it. The index
// comes from the material and stays (KHR_materials_ior); metallic is 0. The albedo at normal incidence is matched
// exactly: every lobe is linear in base_color, so each channel is solved for in closed form at every step, and where
// no colour in [0, 1] gives the albedo, what it misses joins the residuals. The least squares choose the rest within
// the extensions' ranges: roughness, specular (KHR_materials_specular's factor, the specular colour white), a grey
// sheen's strength and roughness (KHR_materials_sheen), and with a clear layer on top the clearcoat's roughness
// (clearcoat 1; KHR_materials_clearcoat fixes the coat's index at 1.5, whatever the material's top is).
#pragma once

#include "core/fit/brdf_fit_target.h"
#include "core/targets/gltf_pbr.h"

namespace skinlayer {

// The least sheen roughness a fit gives: a Charlie lobe of a = 0.09, whose grazing peak the fit's pairs resolve.
constexpr double kMinFittedSheenRoughness = 0.3;

struct GltfFitSettings {
  double ior = 1.5;        // the base's: the top interface's index, or under a clearcoat the relative index below it
  bool clearcoat = false;  // a clear layer on top: clearcoat 1
};

struct GltfFit {
  GltfPbrParameters parameters;
  bool albedo_matched = true;
  Rgb albedo_miss = Rgb::Zero();  // the fitted albedo at normal incidence less the target's (0 where matched)
  FitErrors errors;
};

// Throws std::invalid_argument for a malformed target, ParameterError for an index below 1.
GltfFit fit_gltf(const BrdfFitTarget& target, const GltfFitSettings& settings);

}  // namespace skinlayer
