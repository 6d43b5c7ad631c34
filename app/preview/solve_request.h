// What the solve worker is asked to compute: a colored material, and the incident angle at which to report its
// directional albedo (the light's polar angle).
#pragma once

#include "app/render/material_solve.h"

namespace skinlayer {

struct SolveRequest {
  ColorMaterial material;
  double theta_i = 0.0;  // radians, in [0, pi/2): where ColorTables::albedo is evaluated
  bool compare = false;  // also solve the comparison models (kCompareModels) for the side-by-side view
};

// True when a and b ask for the same solve: every field of the layer (layer.albedo excepted: albedo_rgb is used),
// the RGB albedo, the model, theta_i and the comparison flag compare equal.
bool same_request(const SolveRequest& a, const SolveRequest& b);

}  // namespace skinlayer
