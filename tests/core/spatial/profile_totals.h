// The profile's totals against the BSDF solver: R(0) plus the top's own multiply scattered reflection is the solver's
// subsurface reflectance at normal incidence, T(0) its transmittance, on the same 12 nodes and the azimuth samples of
// the solver's albedo (its mode 0 alone), within 1e-6.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>

#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/solve/resolution.h"
#include "core/solver.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/layer_profile.h"
#include "tests/core/spatial/profile_against_walk.h"

namespace skinlayer::test {

inline void expect_totals_match_the_solver(Material m) {
  m.ordinates = 12;
  LayerProfileOptions options = profile_test_options();
  SolveOptions mode_zero;
  mode_zero.max_modes = 1;
  options.interface_azimuths = choose_resolution(m, mode_zero).interface_azimuths;
  const double edges[] = {0.0, 1.0};
  const LayerProfile profile = layer_profile(profile_layer(m), edges, options);
  const double theta[] = {0.0};
  const DirectionalAlbedo albedo = directional_albedo(m, theta).front();
  const double surface = lateral_top_interface(top_interface(m), 12, 16, Incidence::Normal, options.interface_azimuths)
                             .surface_multiple_reflectance;
  std::printf("  R(0) %.9f  solver less the surface's %.9f   T(0) %.9f  solver %.9f\n", profile.total_reflectance,
              albedo.reflectance_subsurface - surface, profile.total_transmittance, albedo.transmittance);
  EXPECT_NEAR(profile.total_reflectance, albedo.reflectance_subsurface - surface, 1e-6);
  EXPECT_NEAR(profile.total_transmittance, albedo.transmittance, 1e-6);
}

}  // namespace skinlayer::test
