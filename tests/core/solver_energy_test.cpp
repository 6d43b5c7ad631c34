#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <span>
#include <vector>

#include "core/conventions.h"
#include "core/series/quadrature.h"
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
      m.microfacet = MicrofacetModel::Single;
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

// The white furnace with the energy-conserving interfaces (MicrofacetModel::Multiple, the default): a conservative
// medium under rough interfaces returns all light, R = 1 for a semi-infinite layer and R + T = 1 for a slab, a slab
// over a white Lambertian base and a stack with a rough interface between its layers, at every angle of incidence,
// for sigma across [0.05, 1] and eta across (1, 2.5].
TEST(SolverEnergy, WhiteFurnaceWithMultipleScatteringInterfacesReturnsAllLight) {
  const std::vector<double> incidence = angles_degrees({0, 15, 30, 45, 60, 75, 85, 89});
  double worst = 0.0;
  for (const double sigma : {0.05, 0.2, 0.5, 1.0}) {
    for (const double eta : {1.05, 1.4, 2.5}) {
      std::vector<std::pair<std::string, Material>> cases;
      Material base;
      base.microfacet = MicrofacetModel::Multiple;
      base.sigma = sigma;
      base.eta = eta;
      base.albedo = 1.0;
      Material semi_infinite = base;
      semi_infinite.tau = std::numeric_limits<double>::infinity();
      cases.emplace_back("semi-infinite", semi_infinite);
      Material slab = base;
      slab.bottom = parse_bottom("air");
      slab.bottom.sigma = 1.05 - sigma;  // a bottom unlike the top
      cases.emplace_back("slab", slab);
      Material white_base = base;
      white_base.bottom = parse_bottom("lambert:1");
      cases.emplace_back("lambert:1", white_base);
      Material stack = base;
      stack.tau = 0.5;
      stack.below = {StackedLayer{1.0, 1.0, 0.3, LayerInterface{0.3, 1.2}}};
      stack.bottom.eta = 1.2;  // n_last / n_below: air below would exceed its range after eta 2.5 and 1.2
      cases.emplace_back("stack", stack);
      for (const auto& [name, m] : cases) {
        for (const DirectionalAlbedo& row : directional_albedo(m, incidence)) {
          const double total = row.reflectance() + row.transmittance;
          EXPECT_NEAR(total, 1.0, 1e-5) << name << " sigma " << sigma << " eta " << eta << " theta "
                                        << radians_to_degrees(row.theta_i);
          EXPECT_NEAR(row.interface_loss, 0.0, 1e-9) << name;
          worst = std::max(worst, std::abs(total - 1.0));
        }
      }
    }
  }
  std::printf("[ furnace  ] multiple-scattering interfaces: worst |R + T - 1| %.2e\n", worst);
}

// The tables' BRDF and BTDF (coefficients plus the exact unscattered part) integrated over the hemisphere equal the
// solver's directional-hemispherical reflectance and transmittance, computed from its node fluxes.
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
        // The unscattered part is not in the coefficients: integrated over azimuth here (symmetric about phi = 0).
        const QuadratureRule phi = gauss_legendre(48, 0.0, kPi);
        for (int b = 0; b < phi.size(); ++b) {
          const double wp = theta.weights[a] * std::cos(t) * std::sin(t) * 2.0 * phi.weights[b];
          reflected += wp * tables.unscattered().brdf(incidence[k], t, phi.nodes[b]);
          transmitted += wp * tables.unscattered().btdf(incidence[k], t, phi.nodes[b]);
        }
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

// The corners of the parameter table, together: sigma 0.05 | 1, g -0.95 | 0.95, T 0 | 1, Omega 0 | 1, eta 1 | 2.5
// and bottom air | matched | lambert:1, in the combinations of the three tests below. Each case must give
//   * directional_albedo: finite; R_sub, T and R_surface >= 0 up to round-off (1e-9); R + T <= 1 + 1e-3 (the
//     solver's documented albedo accuracy).
//   * solve(): the subsurface BRDF and the BTDF finite and >= 0 at every angle triple below (LayerTables clamps the
//     Catmull-Rom undershoot beside lobes narrower than a grid step; layer_tables_test checks that case itself).
struct ExtremeCase {
  const char* bottom;
  double sigma, g, transparency, albedo, eta;
};

void expect_finite_non_negative_bounded(const ExtremeCase& c) {
  Material m;
  m.bottom = parse_bottom(c.bottom);
  m.sigma = c.sigma;
  m.g = c.g;
  m.tau = optical_depth_from_transparency(c.transparency);
  m.albedo = c.albedo;
  m.eta = c.eta;
  char name[128];
  std::snprintf(name, sizeof name, "bottom %s sigma %g g %g T %g Omega %g eta %g", c.bottom, c.sigma, c.g,
                c.transparency, c.albedo, c.eta);
  SCOPED_TRACE(name);

  for (const DirectionalAlbedo& row : directional_albedo(m, angles_degrees({0, 45, 80, 89.9}))) {
    const double theta = radians_to_degrees(row.theta_i);
    ASSERT_TRUE(std::isfinite(row.reflectance_surface) && std::isfinite(row.reflectance_subsurface) &&
                std::isfinite(row.transmittance) && std::isfinite(row.absorptance) && std::isfinite(row.interface_loss))
        << "theta_i " << theta;
    EXPECT_GE(row.reflectance_surface, -1e-9) << "theta_i " << theta;
    EXPECT_GE(row.reflectance_subsurface, -1e-9) << "theta_i " << theta;
    EXPECT_GE(row.transmittance, -1e-9) << "theta_i " << theta;
    EXPECT_LE(row.reflectance() + row.transmittance, 1.0 + 1e-3) << "theta_i " << theta;
  }

  const LayerTables tables = solve(m);
  const int plane = tables.grid_size() * tables.grid_size();
  const std::span<const double> mode0 = tables.transmission_coefficients().first(plane);
  const double btdf_scale = std::abs(
      *std::max_element(mode0.begin(), mode0.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }));
  for (const double ti : {0.0, 0.7, 1.2, 1.5, 0.5 * kPi}) {
    for (const double to : {0.0, 0.45, 0.9, 1.3, 0.5 * kPi}) {
      for (const double phi : {0.0, 1.0, 2.0, kPi}) {
        const double f = tables.brdf_subsurface(ti, to, phi);
        const double t = tables.btdf(ti, to, phi);
        ASSERT_TRUE(std::isfinite(f) && std::isfinite(t)) << ti << " " << to << " " << phi;
        EXPECT_GE(f, 0.0) << "brdf at " << ti << " " << to << " " << phi;
        EXPECT_GE(t, 0.0) << "btdf at " << ti << " " << to << " " << phi;
      }
    }
  }
  std::printf("  %-56s %3d modes, btdf scale %.3g\n", name, tables.modes(), btdf_scale);
}

// Every pair of extremes occurs in at least one case (a pairwise covering array).
TEST(SolverEnergy, EveryPairOfExtremeParametersGivesFiniteNonNegativeBoundedValues) {
  const ExtremeCase cases[] = {
      {"air", 0.05, -0.95, 1.0, 0.0, 1.0},      {"air", 1.0, 0.95, 0.0, 1.0, 2.5},
      {"matched", 0.05, 0.95, 1.0, 1.0, 1.0},   {"matched", 1.0, -0.95, 0.0, 0.0, 2.5},
      {"lambert:1", 1.0, 0.95, 1.0, 0.0, 2.5},  {"lambert:1", 0.05, -0.95, 0.0, 1.0, 2.5},
      {"lambert:1", 1.0, -0.95, 0.0, 0.0, 1.0},
  };
  for (const ExtremeCase& c : cases) expect_finite_non_negative_bounded(c);
}

// T 0, Omega 1 and eta 1 together: a conservative half-space with no interface, lit by the unscattered beam. With
// |g| 0.95 it is the slowest solve in the parameter table (over 200 Fourier modes), so it has a test of its own.
TEST(SolverEnergy, ConservativeHalfSpaceWithoutInterfaceAtExtremeAsymmetryGivesFiniteBoundedValues) {
  expect_finite_non_negative_bounded({"matched", 1.0, -0.95, 0.0, 1.0, 1.0});
}

// Extremes that act on each other: no medium between smooth high-index interfaces (two-sided, over a matched
// half-space, on a white base), and a conservative half-space of backward or forward scattering.
TEST(SolverEnergy, InteractingExtremeParametersGiveFiniteNonNegativeBoundedValues) {
  const ExtremeCase cases[] = {
      {"air", 0.05, -0.95, 1.0, 1.0, 2.5},
      {"matched", 1.0, 0.95, 1.0, 0.0, 2.5},
      {"lambert:1", 0.05, 0.95, 1.0, 1.0, 2.5},
      {"matched", 1.0, -0.95, 0.0, 1.0, 2.5},
  };
  for (const ExtremeCase& c : cases) expect_finite_non_negative_bounded(c);
}

}  // namespace
}  // namespace skinlayer
