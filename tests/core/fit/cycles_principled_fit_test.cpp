// Blender 4.x-5.x's Principled BSDF fitted to a BRDF's samples (docs/model.md §22.2): it finds its own parameters
// again, with and without a coat and with Cycles' Oren-Nayar diffuse (whose albedo is not linear in the colour), and
// it matches the albedo at normal incidence exactly whatever the target.
#include "core/fit/cycles_principled_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "tests/core/fit/surface_fit_target.h"

namespace skinlayer {
namespace {

using test::target_of;

void expect_found(const CyclesPrincipledParameters& truth, const CyclesPrincipledFitSettings& settings) {
  const CyclesPrincipledFit fit = fit_cycles_principled(target_of(CyclesPrincipled(truth)), settings);
  const CyclesPrincipledParameters& found = fit.parameters;
  std::printf("  roughness %.4f level %.4f diffuse roughness %.4f sheen %.4f (%.4f) coat %.4f  lobe rms %.1e\n",
              found.roughness, found.specular_ior_level, found.diffuse_roughness, found.sheen_weight,
              found.sheen_roughness, found.coat_roughness, fit.errors.lobe_rms.maxCoeff());
  EXPECT_EQ(found.ior, settings.ior);
  EXPECT_EQ(found.coat_weight, settings.coat ? 1.0 : 0.0);
  EXPECT_EQ(found.distribution, CyclesDistribution::kMultiscatterGgx);
  EXPECT_NEAR(found.roughness, truth.roughness, 2e-3);
  EXPECT_NEAR(found.specular_ior_level, truth.specular_ior_level, 2e-3);
  EXPECT_NEAR(found.diffuse_roughness, truth.diffuse_roughness, 1e-2);
  EXPECT_NEAR(found.sheen_weight, truth.sheen_weight, 1e-2);
  if (settings.coat) {
    EXPECT_NEAR(found.coat_roughness, truth.coat_roughness, 2e-3);
  }
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(found.base_color(c), truth.base_color(c), 2e-3);
  EXPECT_TRUE(fit.albedo_matched);
  EXPECT_LT(fit.errors.lobe_rms.maxCoeff(), 1e-3);
  EXPECT_LT(fit.errors.albedo_worst.maxCoeff(), 1e-3);
}

TEST(CyclesPrincipledFit, FindsItsOwnParametersAgain) {
  CyclesPrincipledParameters truth;
  truth.base_color = Rgb(0.6, 0.35, 0.2);
  truth.ior = 1.4;
  truth.roughness = 0.45;
  truth.specular_ior_level = 0.7;
  truth.diffuse_roughness = 0.5;
  truth.sheen_weight = 0.3;
  truth.sheen_roughness = 0.6;
  CyclesPrincipledFitSettings settings;
  settings.ior = 1.4;
  expect_found(truth, settings);
}

TEST(CyclesPrincipledFit, FindsACoatedSurfaceAgain) {
  CyclesPrincipledParameters truth;
  truth.base_color = Rgb(0.5, 0.05, 0.02);
  truth.ior = 1.8;
  truth.roughness = 0.5;
  truth.specular_ior_level = 0.4;
  truth.coat_weight = 1.0;
  truth.coat_ior = 1.5;
  truth.coat_roughness = 0.2;
  CyclesPrincipledFitSettings settings;
  settings.ior = 1.8;
  settings.coat = true;
  settings.coat_ior = 1.5;
  expect_found(truth, settings);
}

// A Lambertian surface: the node holds it exactly (Specular IOR Level 0 removes the specular, Diffuse Roughness 0 is
// Lambert), and the fit finds it, its albedo at normal incidence matched.
TEST(CyclesPrincipledFit, MatchesTheAlbedoAtNormalIncidenceExactly) {
  const Rgb lambert(0.5, 0.3, 0.1);
  BrdfFitTarget target;
  target.pairs = fit_pairs();
  for (const DirectionPair& pair : target.pairs)
    target.brdf_cosine.push_back(lambert * pair.omega_i.z() / std::numbers::pi);
  for (const double angle : {0.0, 0.7, 1.2}) {
    target.albedo_angles.push_back(angle);
    target.albedo.push_back(lambert);
  }
  const CyclesPrincipledFit fit = fit_cycles_principled(target, CyclesPrincipledFitSettings{});
  const Rgb at_normal = CyclesPrincipled(fit.parameters).albedo(1.0);
  std::printf("  albedo at normal incidence %.6f %.6f %.6f; lobe rms %.3f, albedo worst %.3f\n", at_normal(0),
              at_normal(1), at_normal(2), fit.errors.lobe_rms.maxCoeff(), fit.errors.albedo_worst.maxCoeff());
  EXPECT_TRUE(fit.albedo_matched);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(at_normal(c), lambert(c), 1e-9);
  EXPECT_NEAR(fit.parameters.specular_ior_level, 0.0, 1e-3);
  EXPECT_NEAR(fit.parameters.diffuse_roughness, 0.0, 1e-2);
  EXPECT_LT(fit.errors.lobe_rms.maxCoeff(), 1e-4);
  EXPECT_LT(fit.errors.albedo_worst.maxCoeff(), 1e-4);
}

}  // namespace
}  // namespace skinlayer
