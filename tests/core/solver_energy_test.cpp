#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/conventions.h"
#include "core/quadrature.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

std::vector<double> angles_degrees(std::initializer_list<double> degrees) {
  std::vector<double> radians;
  for (double d : degrees) radians.push_back(degrees_to_radians(d));
  return radians;
}

// Omega = 1 between index-matched boundaries: nothing is absorbed, so R + T = 1.
TEST(SolverEnergy, WhiteFurnaceIndexMatched) {
  for (double g : {0.0, 0.8, -0.5, 0.95}) {
    for (double transparency : {0.01, 0.2, 0.9}) {
      Material m;
      m.eta = 1.0;
      m.bottom.kind = BottomKind::Matched;
      m.albedo = 1.0;
      m.g = g;
      m.tau = optical_depth_from_transparency(transparency);
      for (const DirectionalAlbedo& row : directional_albedo(m, angles_degrees({0, 30, 60, 80, 89}))) {
        EXPECT_NEAR(row.reflectance() + row.transmittance, 1.0, 1e-6)
            << "g " << g << " T " << transparency << " theta " << radians_to_degrees(row.theta_i);
      }
    }
  }
}

// Omega = 1 between rough interfaces: all that is not reflected or transmitted is what shadowing-masking removed,
// counted interface by interface from each interface's own hemispherical albedo (interface_albedo's slope-space
// integral). The interface operators are energy-matched to those albedos, so the discrete problem balances to
// rounding and the iteration tolerances (~5e-7 at sigma 0.05); without the matching it missed by up to 5e-3.
TEST(SolverEnergy, WhiteFurnaceRoughInterfacesBalancesShadowingLoss) {
  for (double sigma : {0.05, 0.1, 0.3, 0.5, 1.0}) {
    for (const char* bottom : {"air", "matched", "lambert:1"}) {
      Material m;
      m.sigma = sigma;
      m.bottom = parse_bottom(bottom);
      for (const DirectionalAlbedo& row : directional_albedo(m, angles_degrees({0, 45, 70, 85}))) {
        EXPECT_NEAR(row.reflectance() + row.transmittance + row.interface_loss, 1.0, 2e-6)
            << "sigma " << sigma << " bottom " << bottom << " theta " << radians_to_degrees(row.theta_i);
        EXPECT_GT(row.interface_loss, 0.0);
      }
    }
  }
}

// The tables' BRDF integrated over the hemisphere equals the solver's directional-hemispherical reflectance.
TEST(SolverEnergy, TablesIntegrateToTheDirectionalAlbedo) {
  for (const char* bottom : {"air", "lambert:0.5"}) {
    Material m;
    m.bottom = parse_bottom(bottom);
    const LayerTables tables = solve(m);
    const std::vector<double> incidence = angles_degrees({0, 40, 75});
    const std::vector<DirectionalAlbedo> albedo = directional_albedo(m, incidence);
    const QuadratureRule theta = gauss_legendre(96, 0.0, 0.5 * kPi);
    for (std::size_t k = 0; k < incidence.size(); ++k) {
      double reflected = 0.0, transmitted = 0.0;
      for (int a = 0; a < theta.size(); ++a) {
        const double t = theta.nodes[a];
        const double w = theta.weights[a] * std::cos(t) * std::sin(t) * 2.0 * kPi;  // mode 0 only survives
        reflected += w * tables.reflection_mode(0, incidence[k], t);
        transmitted += w * tables.transmission_mode(0, incidence[k], t);
      }
      EXPECT_NEAR(reflected, albedo[k].reflectance_subsurface, 5e-3 * albedo[k].reflectance_subsurface) << bottom;
      EXPECT_NEAR(transmitted, albedo[k].transmittance, 5e-3 * albedo[k].transmittance + 1e-9) << bottom;
    }
  }
}

TEST(SolverEnergy, ExtremeValidParametersGiveFiniteNonNegativeConservingValues) {
  std::vector<Material> materials;
  for (double sigma : {0.05, 1.0}) {
    for (double g : {-0.95, 0.95}) {
      Material m;
      m.sigma = sigma;
      m.g = g;
      materials.push_back(m);
    }
  }
  for (double transparency : {0.0, 1.0}) {
    for (double albedo : {0.0, 1.0}) {
      Material m;
      m.tau = optical_depth_from_transparency(transparency);
      m.albedo = albedo;
      m.eta = 2.5;
      materials.push_back(m);
    }
  }
  for (const Material& m : materials) {
    for (const DirectionalAlbedo& row : directional_albedo(m, angles_degrees({0, 60, 89.9}))) {
      EXPECT_TRUE(std::isfinite(row.reflectance()) && std::isfinite(row.transmittance));
      EXPECT_GE(row.reflectance_subsurface, -1e-9);
      EXPECT_GE(row.transmittance, -1e-9);
      EXPECT_GE(row.absorptance, -1e-3) << "sigma " << m.sigma << " g " << m.g << " tau " << m.tau;
    }
    const LayerTables tables = solve(m);
    for (double ti : {0.0, 0.7, 1.5}) {
      for (double to : {0.0, 0.9, 1.57}) {
        const double f = tables.brdf_subsurface(ti, to, 2.0);
        EXPECT_TRUE(std::isfinite(f));
        EXPECT_GE(f, -1e-6 * (1.0 + std::abs(f)));
      }
    }
  }
}

}  // namespace
}  // namespace skinlayer
