// The Lambert comparison model of Stam's results slides: the same surface term over a diffuse (Lambertian)
// subsurface BRDF whose albedo equals the layer's own subsurface albedo at normal incidence, so that both models
// send back the same energy for light from the normal.
#pragma once

#include "core/material.h"

namespace skinlayer {

struct LambertModel {
  double albedo = 0.0;  // directional-hemispherical subsurface reflectance, the same for every incidence
  double brdf_subsurface() const;  // albedo / pi  [1/sr]
};

// The Lambert model matched to the layer: albedo = the layer's reflectance_subsurface at theta_i = 0 (solver.h).
LambertModel lambert_model_for(const Material& material);

}  // namespace skinlayer
