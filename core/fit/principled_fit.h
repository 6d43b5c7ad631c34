// The Principled BSDF (core/targets/principled_bsdf.h) that best reproduces a reflectance (docs/model.md §22.2): the
// first half of `skinlayer fit --target principled` (issue 44), on samples the caller takes from its BRDF, with the
// metric of brdf_fit_target.h. The directional albedo at normal incidence is matched exactly: per channel the base
// colour enters the albedo linearly, A = a C + b, and is solved for at every step, so the least squares choose the
// rest (roughness, specular, sheen, clearcoat and its roughness) within the node's ranges. Where the colour would
// leave [0, 1] (the other lobes alone reflect more than the target), what the albedo then misses joins the
// residuals, heavily weighted, so that the fit moves back to where it can match.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/fit/brdf_fit_target.h"
#include "core/targets/principled_bsdf.h"

namespace skinlayer {

struct PrincipledFit {
  PrincipledParameters parameters;
  bool albedo_matched = true;  // false where a channel's colour had to be clamped to [0, 1]
  Rgb albedo_miss = Rgb::Zero();  // the fitted albedo at normal incidence less the target's (0 where matched)
  FitErrors errors;
};

// Throws std::invalid_argument for a target whose sizes disagree or whose first albedo angle is not 0.
PrincipledFit fit_principled(const BrdfFitTarget& target);

}  // namespace skinlayer
