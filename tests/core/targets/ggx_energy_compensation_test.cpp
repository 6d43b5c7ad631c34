// Cycles' GGX energy compensation (docs/model.md §22.1.1): its recomputed tables against closed forms and an
// independent integration over light directions, and the compensation's energy balance.
#include "core/targets/ggx_energy_compensation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/interfaces/fresnel.h"
#include "core/series/quadrature.h"
#include "core/targets/ggx_lobe.h"
#include "tests/core/targets/graded_hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_graded_hemisphere;

// At alpha = 1, D = 1/pi and G2 = 2 mu_i mu_o / (mu_i + mu_o), so f cos_i = mu_i / (2 pi (mu_i + mu_o)) and
//   E(mu) = 1 - mu ln((1 + mu) / mu),   E_avg = 2 int E mu dmu = 4 (1 - ln 2) / 3.
double rough_albedo(double mu) { return 1.0 - mu * std::log((1.0 + mu) / mu); }

TEST(GgxEnergyCompensation, RoughestRowMatchesItsClosedForm) {
  for (int j = 0; j < 32; ++j) {
    const double mu = std::max(j / 31.0, 1e-4);
    EXPECT_NEAR(cycles_ggx_albedo_node(31, j), rough_albedo(mu), j == 0 ? 3e-4 : (j < 4 ? 1e-4 : 1e-6)) << j;
  }
  EXPECT_NEAR(cycles_ggx_average_albedo_node(31), 4.0 * (1.0 - std::log(2.0)) / 3.0, 1e-6);
  EXPECT_NEAR(cycles_ggx_albedo(1.0, 1.0), 1.0 - std::log(2.0), 1e-6);
}

// The nodes against Gauss-Legendre over the light's hemisphere (not half vectors; graded toward its horizon), where
// that converges: roughness 0.3 and up.
TEST(GgxEnergyCompensation, NodesAreTheSingleScatteringAlbedo) {
  for (const int i : {10, 20, 27}) {
    const double r = i / 31.0, alpha = r * r;
    for (const int j : {1, 4, 12, 31}) {
      const double mu = j / 31.0;
      const Vec3 view(std::sqrt(1.0 - mu * mu), 0.0, mu);
      const double integral = over_graded_hemisphere(
          [&](const Vec3& light) {
            const Vec3 h = (light + view).normalized();
            return ggx_distribution(h.z(), alpha) * ggx_height_correlated_masking(light.z(), mu, alpha) / (4.0 * mu);
          },
          256);
      EXPECT_NEAR(cycles_ggx_albedo_node(i, j), integral, j == 1 ? 1e-4 : 1e-6) << i << " " << j;
    }
  }
  // Smooth: nothing lost; the node at roughness 0 is a mirror (alpha = 1e-8).
  EXPECT_EQ(cycles_ggx_albedo_node(0, 5), 1.0);
  EXPECT_NEAR(cycles_ggx_average_albedo_node(0), 1.0, 1e-12);
  EXPECT_GT(cycles_ggx_albedo_node(1, 16), 0.9999);
}

// E_avg is twice the cosine-weighted mean of E: against the table's own E at Gauss-Legendre cosines (linear in mu
// between its 32 nodes, so within 1e-3).
TEST(GgxEnergyCompensation, AverageIsTheCosineWeightedMeanOfTheAlbedo) {
  const QuadratureRule mu = gauss_legendre(64, 0.0, 1.0);
  for (const int i : {5, 15, 25}) {
    double mean = 0.0;
    for (int k = 0; k < mu.size(); ++k) {
      mean += 2.0 * mu.weights[std::size_t(k)] * mu.nodes[std::size_t(k)] *
              cycles_ggx_albedo(i / 31.0, mu.nodes[std::size_t(k)]);
    }
    EXPECT_NEAR(cycles_ggx_average_albedo_node(i), mean, 1e-3) << i;
  }
}

// With a white Fresnel the compensation is 1/E: at a node, the compensated lobe reflects all the light.
TEST(GgxEnergyCompensation, WhiteLobeIsMadeWhole) {
  for (const int i : {8, 20, 31}) {
    const double r = i / 31.0;
    for (const int j : {6, 18, 31}) {
      const double mu = j / 31.0;
      const double K = cycles_ggx_energy_factor(r, mu, Rgb::Ones())(0);
      EXPECT_NEAR(K, 1.0 / cycles_ggx_albedo(r, mu), 1e-12);
      EXPECT_NEAR(K * ggx_reflection_albedo(
                          r * r, mu, [](double) { return 1.0; }, 64),
                  1.0, 2e-4)
          << i << " " << j;
    }
  }
  // A black Fresnel is not compensated; a grey one in between.
  EXPECT_EQ(cycles_ggx_energy_factor(0.7, 0.5, Rgb::Zero())(0), 1.0);
  const Rgb K = cycles_ggx_energy_factor(0.7, 0.5, Rgb(0.04, 0.5, 1.0));
  EXPECT_LT(K(0), K(1));
  EXPECT_LT(K(1), K(2));
}

// Kulla & Conty's fit of the average Fresnel, which Cycles takes for 2 int F(mu) mu dmu, is that only roughly:
// 15% low at index 1.2, within 2.5% from 1.5 to 3.
TEST(GgxEnergyCompensation, AverageFresnelFitIsRoughlyTheHemisphericalFresnel) {
  const QuadratureRule mu = gauss_legendre(128, 0.0, 1.0);
  for (const double eta : {1.2, 1.5, 2.0, 3.0}) {
    double exact = 0.0;
    for (int k = 0; k < mu.size(); ++k) {
      exact += 2.0 * mu.weights[std::size_t(k)] * mu.nodes[std::size_t(k)] *
               fresnel_dielectric(mu.nodes[std::size_t(k)], eta);
    }
    EXPECT_NEAR(cycles_dielectric_average_fresnel(eta), exact, (eta < 1.3 ? 0.15 : 0.025) * exact) << eta;
  }
  EXPECT_EQ(cycles_dielectric_average_fresnel(1.0), 0.0);
}

}  // namespace
}  // namespace skinlayer
