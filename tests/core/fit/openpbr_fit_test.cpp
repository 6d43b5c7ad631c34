// OpenPBR Surface fitted to a BRDF's samples (docs/model.md §22.4): it finds its own parameters again, with and
// without a coat, and it matches the albedo at normal incidence exactly whatever the target.
#include "core/fit/openpbr_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/conventions.h"
#include "tests/core/fit/surface_fit_target.h"

namespace skinlayer {
namespace {

using test::target_of;

void expect_found(const OpenPbrParameters& truth, const OpenPbrFitSettings& settings) {
  const OpenPbrFit fit = fit_openpbr(target_of(OpenPbrSurface(truth)), settings);
  const OpenPbrParameters& found = fit.parameters;
  std::printf("  roughness %.4f weight %.4f diffuse roughness %.4f fuzz %.4f (%.4f) coat %.4f  lobe rms %.1e\n",
              found.specular_roughness, found.specular_weight, found.base_diffuse_roughness, found.fuzz_weight,
              found.fuzz_roughness, found.coat_roughness, fit.errors.lobe_rms.maxCoeff());
  EXPECT_NEAR(found.specular_roughness, truth.specular_roughness, 2e-3);
  EXPECT_NEAR(found.specular_weight, truth.specular_weight, 2e-3);
  EXPECT_NEAR(found.base_diffuse_roughness, truth.base_diffuse_roughness, 1e-2);
  EXPECT_NEAR(found.fuzz_weight, truth.fuzz_weight, 1e-2);
  EXPECT_NEAR(found.coat_roughness, truth.coat_roughness, 2e-3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(found.base_color(c), truth.base_color(c), 2e-3);
  EXPECT_TRUE(fit.albedo_matched);
  EXPECT_LT(fit.errors.lobe_rms.maxCoeff(), 1e-3);
  EXPECT_LT(fit.errors.albedo_worst.maxCoeff(), 1e-3);
}

TEST(OpenPbrFit, FindsItsOwnParametersAgain) {
  OpenPbrParameters truth;
  truth.base_color = truth.subsurface_color = Rgb(0.6, 0.35, 0.2);
  truth.specular_ior = 1.4;
  truth.specular_roughness = 0.35;
  truth.specular_weight = 0.8;
  truth.base_diffuse_roughness = 0.4;
  truth.fuzz_weight = 0.3;
  truth.fuzz_roughness = 0.6;
  OpenPbrFitSettings settings;
  settings.specular_ior = 1.4;
  expect_found(truth, settings);
}

TEST(OpenPbrFit, FindsACoatedSurfaceAgain) {
  OpenPbrParameters truth;
  truth.base_color = truth.subsurface_color = Rgb(0.5, 0.05, 0.02);
  truth.specular_ior = 1.5 * 1.2;
  truth.specular_roughness = 0.5;
  truth.specular_weight = 1.0;
  truth.base_diffuse_roughness = 0.0;
  truth.coat_weight = 1.0;
  truth.coat_ior = 1.5;
  truth.coat_roughness = 0.2;
  OpenPbrFitSettings settings;
  settings.specular_ior = 1.5 * 1.2;
  settings.coat = true;
  settings.coat_ior = 1.5;
  expect_found(truth, settings);
}

// A Lambertian surface, which the glossy diffuse can only approach: the albedo at normal incidence is matched all the
// same, and the error elsewhere is reported.
TEST(OpenPbrFit, MatchesTheAlbedoAtNormalIncidenceExactly) {
  const Rgb lambert(0.5, 0.3, 0.1);
  BrdfFitTarget target;
  target.pairs = fit_pairs();
  for (const DirectionPair& pair : target.pairs) target.brdf_cosine.push_back(lambert * pair.omega_i.z() / kPi);
  target.albedo_angles = {0.0, 1.0};
  target.albedo = {lambert, lambert};
  const OpenPbrFit fit = fit_openpbr(target, OpenPbrFitSettings{});
  const Rgb at_normal = OpenPbrSurface(fit.parameters).albedo(1.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(at_normal(c), lambert(c), 1e-9);
  EXPECT_TRUE(fit.albedo_matched);
  EXPECT_GT(fit.errors.lobe_rms.maxCoeff(), 0.0);
}

}  // namespace
}  // namespace skinlayer
