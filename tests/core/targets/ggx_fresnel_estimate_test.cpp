// Cycles' estimate of a GGX reflection's Fresnel albedo (docs/model.md §22.1.1): the Principled Fresnel blend is the
// dielectric Fresnel remapped from F0 to white, the recomputed table holds the visible-normal mean of the blend
// (against an integration over light directions), and a mirror's row is the blend at the view.
#include "core/targets/ggx_fresnel_estimate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/interfaces/fresnel.h"
#include "core/targets/fresnel_terms.h"
#include "core/targets/ggx_lobe.h"
#include "tests/core/targets/graded_hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_graded_hemisphere;

TEST(GgxFresnelEstimate, BlendRemapsTheDielectricFresnelFromF0ToWhite) {
  for (const double eta : {1.33, 1.5, 2.4}) {
    const double f0 = normal_reflectance(eta);
    EXPECT_NEAR(cycles_ior_from_f0(f0), eta, 1e-12);
    EXPECT_NEAR(cycles_fresnel_blend(1.0, eta), 0.0, 1e-15);
    EXPECT_NEAR(cycles_fresnel_blend(0.0, eta), 1.0, 1e-15);
    for (const double c : {0.9, 0.5, 0.1}) {
      // With f0 = F0(eta) the blend is the Fresnel itself.
      const double s = cycles_fresnel_blend(c, eta);
      EXPECT_NEAR(f0 * (1.0 - s) + s, fresnel_dielectric(c, eta), 1e-14) << eta << " " << c;
    }
  }
  EXPECT_EQ(cycles_ior_from_f0(2.0), cycles_ior_from_f0(0.99));  // ior_from_F0 clamps F0 at 0.99
}

// s_bar = int s(omega_i.h) G1(mu_o) D(h) / (4 mu_o) d omega_i, integrated here over light directions by
// Gauss-Legendre; the function and the table's nodes (roughness k/15, cosine j/15, z = 0.2 -> eta = 1.0833,
// z = 0.6 -> eta = 2.125) agree within 1e-4.
TEST(GgxFresnelEstimate, TableHoldsTheVisibleNormalMeanOfTheBlend) {
  for (const double r : {6.0 / 15.0, 10.0 / 15.0, 1.0}) {
    for (const double mu : {3.0 / 15.0, 8.0 / 15.0, 1.0}) {
      for (const double z : {0.2, 0.6}) {
        const double eta = cycles_ior_from_f0(std::pow(z, 4.0)), alpha = r * r;
        const Vec3 view(std::sqrt(1.0 - mu * mu), 0.0, mu);
        const double integral = over_graded_hemisphere(
            [&](const Vec3& light) {
              const Vec3 h = (light + view).normalized();
              return cycles_fresnel_blend(light.dot(h), eta) * ggx_masking(mu, alpha) * ggx_distribution(h.z(), alpha) /
                     (4.0 * mu);
            },
            256);
        EXPECT_NEAR(ggx_visible_fresnel_blend(r, mu, eta), integral, 1e-4) << r << " " << mu << " " << z;
        EXPECT_NEAR(cycles_ggx_fresnel_blend(r, mu, eta), integral, 1e-4) << r << " " << mu << " " << z;
      }
    }
  }
}

// Not the Fresnel-weighted albedo over the white one: the mean leaves out G2 / G1 (which favours the facets that send
// light up) and counts reflections below the horizon as 0. At roughness 0.5 seen at cosine 0.2 it is 7% above that
// ratio.
TEST(GgxFresnelEstimate, IsNotTheRatioOfAlbedos) {
  const double r = 0.5, mu = 0.2, eta = 1.5, alpha = r * r;
  const Vec3 view(std::sqrt(1.0 - mu * mu), 0.0, mu);
  const auto albedo = [&](bool blend) {
    return over_graded_hemisphere(
        [&](const Vec3& light) {
          const Vec3 h = (light + view).normalized();
          return (blend ? cycles_fresnel_blend(light.dot(h), eta) : 1.0) * ggx_distribution(h.z(), alpha) *
                 ggx_height_correlated_masking(light.z(), mu, alpha) / (4.0 * mu);
        },
        256);
  };
  const double ratio = albedo(true) / albedo(false), mean = ggx_visible_fresnel_blend(r, mu, eta);
  EXPECT_GT(mean, 1.05 * ratio);
  EXPECT_LT(mean, 1.1 * ratio);
}

// A mirror's row (roughness 0, a mirror in Cycles) is the blend at the view's own angle, at the table's nodes.
TEST(GgxFresnelEstimate, MirrorRowIsTheBlendAtTheView) {
  const double eta = cycles_ior_from_f0(std::pow(9.0 / 15.0, 4.0));
  for (const int j : {2, 7, 15}) {
    const double mu = j / 15.0;
    EXPECT_NEAR(cycles_ggx_fresnel_blend(0.0, mu, eta), cycles_fresnel_blend(mu, eta), 1e-12) << j;
  }
  const Rgb f0(0.02, 0.04, 0.08);
  const Rgb estimate = cycles_principled_fresnel_estimate(0.0, 1.0, eta, f0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(estimate(c), f0(c), 1e-12);  // s = 0 at normal incidence
  EXPECT_EQ(cycles_dielectric_fresnel_estimate(0.3, 0.5, 1.0), 0.0);   // index 1 reflects nothing
  EXPECT_NEAR(cycles_dielectric_fresnel_estimate(0.0, 1.0, eta), normal_reflectance(eta), 1e-12);
}

}  // namespace
}  // namespace skinlayer
