// glTF 2.0's material fitted to a BRDF's samples: it finds its own parameters again, with and
// without a clearcoat, and it matches the albedo at normal incidence exactly whatever the target.
#include "core/fit/gltf_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/conventions.h"
#include "tests/core/fit/surface_fit_target.h"

namespace skinlayer {
namespace {

using test::target_of;

void expect_found(const GltfPbrParameters& truth, const GltfFitSettings& settings) {
  const GltfFit fit = fit_gltf(target_of(GltfPbr(truth)), settings);
  const GltfPbrParameters& found = fit.parameters;
  std::printf("  roughness %.4f specular %.4f sheen %.4f (%.4f) clearcoat roughness %.4f  lobe rms %.1e\n",
              found.roughness, found.specular, found.sheen_color(0), found.sheen_roughness, found.clearcoat_roughness,
              fit.errors.lobe_rms.maxCoeff());
  EXPECT_NEAR(found.roughness, truth.roughness, 2e-3);
  EXPECT_NEAR(found.specular, truth.specular, 2e-3);
  EXPECT_NEAR(found.sheen_color(0), truth.sheen_color(0), 1e-2);
  if (truth.sheen_color(0) > 0.0) {
    EXPECT_NEAR(found.sheen_roughness, truth.sheen_roughness, 1e-2);
  }
  EXPECT_NEAR(found.clearcoat_roughness, truth.clearcoat_roughness, 2e-3);
  EXPECT_EQ(found.clearcoat, truth.clearcoat);
  EXPECT_EQ(found.ior, truth.ior);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(found.base_color(c), truth.base_color(c), 2e-3);
  EXPECT_TRUE(fit.albedo_matched);
  EXPECT_LT(fit.errors.lobe_rms.maxCoeff(), 1e-3);
  EXPECT_LT(fit.errors.albedo_worst.maxCoeff(), 1e-3);
}

TEST(GltfFit, FindsItsOwnParametersAgain) {
  GltfPbrParameters truth;
  truth.metallic = 0.0;
  truth.base_color = Rgb(0.6, 0.35, 0.2);
  truth.ior = 1.4;
  truth.roughness = 0.35;
  truth.specular = 0.8;
  truth.sheen_color = Rgb::Constant(0.3);
  truth.sheen_roughness = 0.6;
  GltfFitSettings settings;
  settings.ior = 1.4;
  expect_found(truth, settings);
}

TEST(GltfFit, FindsAClearcoatedSurfaceAgain) {
  GltfPbrParameters truth;
  truth.metallic = 0.0;
  truth.base_color = Rgb(0.5, 0.05, 0.02);
  truth.ior = 1.8;
  truth.roughness = 0.5;
  truth.specular = 1.0;
  truth.clearcoat = 1.0;
  truth.clearcoat_roughness = 0.2;
  GltfFitSettings settings;
  settings.ior = 1.8;
  settings.clearcoat = true;
  expect_found(truth, settings);
}

// A Lambertian surface, which Appendix B's dielectric only approaches: the albedo at normal incidence is matched all
// the same, and the error elsewhere is reported.
TEST(GltfFit, MatchesTheAlbedoAtNormalIncidenceExactly) {
  const Rgb lambert(0.5, 0.3, 0.1);
  BrdfFitTarget target;
  target.pairs = fit_pairs();
  for (const DirectionPair& pair : target.pairs) target.brdf_cosine.push_back(lambert * pair.omega_i.z() / kPi);
  target.albedo_angles = {0.0, 1.0};
  target.albedo = {lambert, lambert};
  const GltfFit fit = fit_gltf(target, GltfFitSettings{});
  const Rgb at_normal = GltfPbr(fit.parameters).albedo(1.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(at_normal(c), lambert(c), 1e-9);
  EXPECT_TRUE(fit.albedo_matched);
  EXPECT_EQ(fit.parameters.metallic, 0.0);
  EXPECT_GT(fit.errors.lobe_rms.maxCoeff(), 0.0);
}

}  // namespace
}  // namespace skinlayer
