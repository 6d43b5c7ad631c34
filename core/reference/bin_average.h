// The solver's side of a comparison with the Monte Carlo walk: the layer's BSDF averaged over one of the walk's
// angular bins. The walk itself (monte_carlo.cpp) uses none of this; it sits here because both the reference
// tests and `skinlayer validate` compare against the same bins.
#pragma once

#include "core/material.h"
#include "core/reference/monte_carlo.h"
#include "core/series/layer_tables.h"

namespace skinlayer {

// The BSDF over the bin, weighted as the walk tallies exits (projected solid angle, cos theta d omega):
//   <f> = int_bin f cos theta sin theta dtheta dphi / int_bin cos theta sin theta dtheta dphi   [1/sr],
// by a grid x grid midpoint rule in (theta, phi) for the surface term and the scattered part, and a 4 (closed forms)
// or 2 (two interfaces) times finer one for the unscattered part (core/unscattered/unscattered_light.h), whose lobes
// can be a degree wide. Reflected bins hold the surface term (brdf_surface) plus the
// subsurface BRDF; transmitted bins the scattered BTDF (an index-matched layer's unscattered beam is a delta
// direction, in the transmittance, not in any bin). theta_i in radians.
double layer_bsdf_bin_average(const Material& material, const LayerTables& tables, double theta_i,
                              const AngularBin& bin, int grid = 16);

}  // namespace skinlayer
