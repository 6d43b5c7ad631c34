// The OpenPBR Surface (core/targets/openpbr_surface.h) that best reproduces a reflectance (docs/model.md §22.4): the
// first half of `skinlayer fit --target openpbr`, with the metric of brdf_fit_target.h. The interfaces come from the
// material and stay: specular_ior is its top interface's index, or, under a coat, the index below the coat; a coat,
// where the caller says the material has one (a clear layer on top), takes the top's index. The albedo at normal
// incidence is matched exactly: the diffuse colour (base_color and subsurface_color alike, which at the BRDF's scale
// are the same lobe) is solved for at every step, per channel, by bisection on the albedo's closed form, which rises
// with it. The least squares choose the rest within the node's ranges: specular roughness and weight, the diffuse
// roughness, the fuzz's weight and roughness, and the coat's roughness. Where no colour in [0, 1] gives the albedo,
// what it misses joins the residuals, as in the Principled fit.
#pragma once

#include "core/fit/brdf_fit_target.h"
#include "core/targets/openpbr_surface.h"

namespace skinlayer {

struct OpenPbrFitSettings {
  double specular_ior = 1.5;       // the interface under the coat, or the top one without a coat
  bool coat = false;               // a clear layer on top: coat_weight 1
  double coat_ior = 1.5;           // its index (the top interface's)
  double subsurface_weight = 0.0;  // 1 where the caller knows the subsurface radius; the BRDF is the same
};

struct OpenPbrFit {
  OpenPbrParameters parameters;
  bool albedo_matched = true;
  Rgb albedo_miss = Rgb::Zero();  // the fitted albedo at normal incidence less the target's (0 where matched)
  FitErrors errors;
};

// Throws std::invalid_argument for a malformed target, ParameterError for an index out of range.
OpenPbrFit fit_openpbr(const BrdfFitTarget& target, const OpenPbrFitSettings& settings);

}  // namespace skinlayer
