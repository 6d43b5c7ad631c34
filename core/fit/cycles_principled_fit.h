// The Principled BSDF of Blender 4.x and 5.x (core/targets/cycles_principled.h) that best reproduces a reflectance
// (docs/model.md §22.2): the first half of `skinlayer fit --target principled`, with the metric of brdf_fit_target.h,
// under the node's default distribution, "Multiscatter GGX". The interfaces come from the material and stay, as in
// the OpenPBR fit: IOR is the top interface's index, or under a coat the index below it; a coat (a clear layer on
// top, as the caller says) has weight 1 and the top's index. The albedo at normal incidence is matched exactly: the
// base colour, which only the diffuse lobe takes, is solved for at every step, per channel, by bisection on the
// albedo's closed form, which rises with it. The least squares choose the rest within the node's ranges: roughness,
// Specular IOR Level, Diffuse Roughness, the sheen's weight and roughness, and with a coat its roughness. Where no
// colour in [0, 1] gives the albedo, what it misses joins the residuals, as in the other fits.
#pragma once

#include "core/fit/brdf_fit_target.h"
#include "core/targets/cycles_principled.h"

namespace skinlayer {

struct CyclesPrincipledFitSettings {
  double ior = 1.5;       // the interface under the coat, or the top one without a coat: [1, 1000]
  bool coat = false;      // a clear layer on top: Coat Weight 1
  double coat_ior = 1.5;  // its index (the top interface's): [1, 4]
};

struct CyclesPrincipledFit {
  CyclesPrincipledParameters parameters;
  bool albedo_matched = true;
  Rgb albedo_miss = Rgb::Zero();  // the fitted albedo at normal incidence less the target's (0 where matched)
  FitErrors errors;
};

// Throws std::invalid_argument for a malformed target, ParameterError for an index out of the node's range.
CyclesPrincipledFit fit_cycles_principled(const BrdfFitTarget& target, const CyclesPrincipledFitSettings& settings);

}  // namespace skinlayer
