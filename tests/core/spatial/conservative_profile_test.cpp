// Conservative scattering (Omega = 1) in the profile (docs/model.md §21.18): the paper's own layers, at k = 0 the
// solver's subsurface reflectance and transmittance, and against the walk.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/solve/resolution.h"
#include "core/solver.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/layer_profile.h"
#include "tests/core/spatial/profile_against_walk.h"

namespace skinlayer {
namespace {

// R(0) plus the top's own multiply scattered reflection is the solver's subsurface reflectance at normal incidence,
// T(0) its transmittance, on the same 12 nodes and azimuth samples.
void expect_totals_match_the_solver(Material m) {
  m.ordinates = 12;
  LayerProfileOptions options = test::profile_test_options();
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

// The paper's default layer: sigma 0.5 and eta 1.4 on both faces, T 0.2, Omega 1, g 0.8.
TEST(ConservativeProfile, PapersLayerTotalsAreTheSolvers) { expect_totals_match_the_solver(Material{}); }

// Its semi-infinite layer (T 0): the exact bounded solution of mode 0 at k = 0, as in the solver.
TEST(ConservativeProfile, PapersHalfSpaceTotalsAreTheSolvers) {
  Material m;
  m.tau = std::numeric_limits<double>::infinity();
  expect_totals_match_the_solver(m);
}

// Against the walk under the paper's single-scattering interfaces (§21.17 says why not the default ones at sigma 0.5),
// on the 24 nodes of light through a finite layer.
TEST(ConservativeProfile, PapersLayerMatchesTheWalk) {
  Material m;
  m.microfacet = MicrofacetModel::Single;
  LayerProfileOptions options = test::profile_test_options();
  options.resolution.ordinates = 24;
  test::expect_profile_matches_the_walk(
      profile_layer(m), m, options, {0.0, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0});
}

}  // namespace
}  // namespace skinlayer
