#include <gtest/gtest.h>

#include <cmath>

#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

// Helmholtz reciprocity of the whole layer: both outside media are air, so f(i, o) = f(o, i) for the BRDF. For the
// BTDF the reversed path enters from below, so f_T(i, o) = f_T(o, i) holds when the layer is mirror-symmetric.
void expect_reciprocal(const Material& m) {
  const LayerTables tables = solve(m);
  for (double ti : {3.0, 21.7, 47.2, 66.6, 83.0}) {
    for (double to : {8.4, 33.3, 59.1, 79.5}) {
      for (double phi : {0.0, 77.0, 180.0}) {
        const double a = degrees_to_radians(ti), b = degrees_to_radians(to), c = degrees_to_radians(phi);
        const double forward = brdf_surface(m, a, b, c) + tables.brdf_subsurface(a, b, c);
        const double backward = brdf_surface(m, b, a, c) + tables.brdf_subsurface(b, a, c);
        EXPECT_NEAR(forward, backward, 1e-6 * forward) << ti << " " << to << " " << phi;
        if (m.bottom.kind == BottomKind::Air && m.bottom_eta() == m.eta && m.bottom_sigma() == m.sigma) {
          // 1e-5: the unscattered part's quadrature (two_interface_btdf) is good to ~1e-6 and not exactly symmetric.
          EXPECT_NEAR(tables.btdf(a, b, c), tables.btdf(b, a, c), 1e-5 * tables.btdf(a, b, c));
        }
      }
    }
  }
}

TEST(SolverReciprocity, BottomAir) { expect_reciprocal(Material{}); }

TEST(SolverReciprocity, BottomAirWithDifferentBottomInterface) {
  Material m;
  m.bottom.sigma = 0.3;
  m.bottom.eta = 1.2;
  expect_reciprocal(m);
}

// A thin layer that does not scatter: its BRDF is the unscattered light's bottom reflection, which the solver puts on
// four times the ordinates (core/unscattered/bottom_bounce.h); the correction keeps the tables reciprocal.
TEST(SolverReciprocity, BottomBounceOnFinerOrdinates) {
  Material m;
  m.sigma = 0.2;
  m.albedo = 0.0;
  m.g = 0.5;
  m.tau = optical_depth_from_transparency(0.5);
  expect_reciprocal(m);
}

TEST(SolverReciprocity, BottomLambert) {
  Material m;
  m.bottom = parse_bottom("lambert:0.6");
  m.albedo = 0.9;
  expect_reciprocal(m);
}

TEST(SolverReciprocity, IndexMatchedTopOverLambert) {
  Material m;
  m.eta = 1.0;
  m.bottom = parse_bottom("lambert:0.5");
  m.g = 0.5;
  expect_reciprocal(m);
}

}  // namespace
}  // namespace skinlayer
