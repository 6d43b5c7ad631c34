// The Principled BSDF fitted to a BRDF's samples (docs/model.md §22.2): it finds its own parameters again, and it
// matches the albedo at normal incidence exactly whatever the target.
#include "core/fit/principled_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "core/conventions.h"

namespace skinlayer {
namespace {

constexpr double kAngles[] = {0.0, 0.5, 1.0, 1.3};

// A target from any cosine-weighted BRDF, and its directional albedos at kAngles.
BrdfFitTarget target_of(const std::function<Rgb(const Vec3&, const Vec3&)>& brdf_cosine,
                        const std::function<Rgb(double)>& albedo) {
  BrdfFitTarget target;
  target.pairs = fit_pairs();
  for (const DirectionPair& pair : target.pairs) target.brdf_cosine.push_back(brdf_cosine(pair.omega_i, pair.omega_o));
  for (const double angle : kAngles) {
    target.albedo_angles.push_back(angle);
    target.albedo.push_back(albedo(angle));
  }
  return target;
}

Vec3 light_at(double theta) { return {std::sin(theta), 0.0, std::cos(theta)}; }

TEST(PrincipledFit, FindsItsOwnParametersAgain) {
  const PrincipledParameters truth{.base_color = Rgb(0.7, 0.4, 0.2),
                                   .specular = 0.6,
                                   .roughness = 0.35,
                                   .sheen = 0.0,
                                   .sheen_tint = 0.0,
                                   .clearcoat = 0.3,
                                   .clearcoat_roughness = 0.1};
  const PrincipledFit fit = fit_principled(
      target_of([&](const Vec3& i, const Vec3& o) { return principled_brdf_cosine_weighted(truth, i, o); },
                [&](double angle) { return principled_albedo(truth, light_at(angle)); }));
  const PrincipledParameters& found = fit.parameters;
  std::printf("  roughness %.5f specular %.5f clearcoat %.5f (%.5f) sheen %.5f  lobe rms %.1e\n", found.roughness,
              found.specular, found.clearcoat, found.clearcoat_roughness, found.sheen, fit.errors.lobe_rms.maxCoeff());
  EXPECT_NEAR(found.roughness, truth.roughness, 1e-3);
  EXPECT_NEAR(found.specular, truth.specular, 1e-3);
  EXPECT_NEAR(found.clearcoat, truth.clearcoat, 1e-2);
  EXPECT_NEAR(found.clearcoat_roughness, truth.clearcoat_roughness, 1e-2);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(found.base_color(c), truth.base_color(c), 1e-3);
  EXPECT_TRUE(fit.albedo_matched);
  EXPECT_LT(fit.errors.lobe_rms.maxCoeff(), 1e-4);
  EXPECT_LT(fit.errors.albedo_worst.maxCoeff(), 1e-4);
}

// A sharp surface, the least roughness the fit gives and a sharp coat: the cap's nodes see its peaks, so the fit
// finds it again as it finds a rough one.
TEST(PrincipledFit, FindsASharpSurfaceAgain) {
  const PrincipledParameters truth{.base_color = Rgb(0.3, 0.5, 0.2),
                                   .specular = 0.8,
                                   .roughness = kMinFittedRoughness,
                                   .sheen = 0.0,
                                   .sheen_tint = 0.0,
                                   .clearcoat = 0.6,
                                   .clearcoat_roughness = 0.15};
  const PrincipledFit fit = fit_principled(
      target_of([&](const Vec3& i, const Vec3& o) { return principled_brdf_cosine_weighted(truth, i, o); },
                [&](double angle) { return principled_albedo(truth, light_at(angle)); }));
  const PrincipledParameters& found = fit.parameters;
  EXPECT_NEAR(found.roughness, truth.roughness, 1e-3);
  EXPECT_NEAR(found.specular, truth.specular, 1e-3);
  EXPECT_NEAR(found.clearcoat, truth.clearcoat, 1e-2);
  EXPECT_NEAR(found.clearcoat_roughness, truth.clearcoat_roughness, 1e-2);
  EXPECT_LT(fit.errors.lobe_rms.maxCoeff(), 1e-4);
}

// A Lambertian surface, f = A / pi, which Burley's diffuse can only approach: the albedo at normal incidence is A to
// round-off all the same, and the error elsewhere is reported, not hidden.
TEST(PrincipledFit, MatchesTheAlbedoAtNormalIncidenceExactly) {
  const Rgb lambert(0.5, 0.3, 0.1);
  const PrincipledFit fit = fit_principled(target_of(
      [&](const Vec3& i, const Vec3&) { return Rgb(lambert * kInvPi * i.z()); }, [&](double) { return lambert; }));
  const Rgb at_normal = principled_albedo(fit.parameters, Vec3::UnitZ());
  std::printf("  roughness %.3f specular %.3f  lobe rms %.4f worst %.4f  albedo worst %.4f\n", fit.parameters.roughness,
              fit.parameters.specular, fit.errors.lobe_rms.maxCoeff(), fit.errors.lobe_worst.maxCoeff(),
              fit.errors.albedo_worst.maxCoeff());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(at_normal(c), lambert(c), 1e-12);
  EXPECT_TRUE(fit.albedo_matched);
  EXPECT_GT(fit.errors.albedo_worst.maxCoeff(), 0.0);
  EXPECT_LT(fit.errors.lobe_rms.maxCoeff(), 0.1);
}

// A channel darker at normal incidence than the specular alone can be: the colour is clamped at 0, the fit lowers the
// specular as far as the other channels let it, and it reports the albedo it then misses rather than hiding it.
TEST(PrincipledFit, SaysWhereTheAlbedoCannotBeMatched) {
  const PrincipledParameters glossy{.base_color = Rgb(0.6, 0.5, 0.0), .specular = 1.0, .roughness = 0.2};
  BrdfFitTarget target =
      target_of([&](const Vec3& i, const Vec3& o) { return principled_brdf_cosine_weighted(glossy, i, o); },
                [&](double angle) { return principled_albedo(glossy, light_at(angle)); });
  target.albedo.front()(2) = 0.01;  // below the specular's own 0.08 and what the others' lobes let it go down to
  const PrincipledFit fit = fit_principled(target);
  std::printf("  miss %.2e %.2e %.2e  specular %.3f\n", fit.albedo_miss(0), fit.albedo_miss(1), fit.albedo_miss(2),
              fit.parameters.specular);
  EXPECT_FALSE(fit.albedo_matched);
  EXPECT_EQ(fit.parameters.base_color(2), 0.0);
  EXPECT_GT(fit.albedo_miss(2), 0.0);
  EXPECT_NEAR(fit.albedo_miss(0), 0.0, 1e-12);
  const Rgb at_normal = principled_albedo(fit.parameters, Vec3::UnitZ());
  EXPECT_NEAR(at_normal(2) - 0.01, fit.albedo_miss(2), 1e-12);
}

TEST(PrincipledFit, RefusesAMalformedTarget) {
  BrdfFitTarget target;
  target.pairs = fit_pairs(4);
  EXPECT_THROW(fit_principled(target), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
