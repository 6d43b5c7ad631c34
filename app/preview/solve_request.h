// What the solve worker is asked to compute: a colored material, and the incident angle at which to report its
// directional albedo (the light's polar angle).
#pragma once

#include <array>

#include "app/solution/material_solve.h"

namespace skinlayer {

struct SolveRequest {
  ColorMaterial material;
  double theta_i = 0.0;  // radians, in [0, pi/2): where ColorTables::albedo is evaluated
  bool compare = false;  // also solve the comparison models (kCompareModels) for the side-by-side view
  SubsurfaceModel plot_model = SubsurfaceModel::Stam;  // the lobe plots' model (material.model is the sphere's)
};

// The models a request needs solved: the sphere's, the plots', and all three for the compare view.
std::array<bool, 3> needed_models(const SolveRequest& request);

// True when a and b ask for the same solve: every field of the layer (layer.albedo excepted: albedo_rgb is used),
// the RGB albedo, a skin's parameters, the models, theta_i and the comparison flag compare equal.
bool same_request(const SolveRequest& a, const SolveRequest& b);

}  // namespace skinlayer
