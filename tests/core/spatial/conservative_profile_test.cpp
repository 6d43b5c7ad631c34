// Conservative scattering (Omega = 1) in the profile (docs/model.md §21.18): the paper's own layers, at k = 0 the
// solver's subsurface reflectance and transmittance, and against the walk.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/material.h"
#include "core/spatial/layer_profile.h"
#include "tests/core/spatial/profile_against_walk.h"
#include "tests/core/spatial/profile_totals.h"

namespace skinlayer {
namespace {

// The paper's default layer: sigma 0.5 and eta 1.4 on both faces, T 0.2, Omega 1, g 0.8.
TEST(ConservativeProfile, PapersLayerTotalsAreTheSolvers) { test::expect_totals_match_the_solver(Material{}); }

// Its semi-infinite layer (T 0): the exact bounded solution of mode 0 at k = 0, as in the solver.
TEST(ConservativeProfile, PapersHalfSpaceTotalsAreTheSolvers) {
  Material m;
  m.tau = std::numeric_limits<double>::infinity();
  test::expect_totals_match_the_solver(m);
}

// Against the walk under the default interfaces, on the 24 nodes of light through a finite layer.
TEST(ConservativeProfile, PapersLayerMatchesTheWalk) {
  const Material m;
  test::expect_profile_matches_the_walk(
      profile_layer(m), m, test::transmitted_radiance_options(),
      {0.0, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0});
}

}  // namespace
}  // namespace skinlayer
