// OpenPBR Surface's opaque lobes as MaterialX's graph layers them (docs/model.md §22.3): the closed-form albedo at
// the view is the integral of the lobes, a white surface under a white coat and a white fuzz reflects all the light
// but for what the graph's Schlick fits miss, the coat darkens by the graph's Kcoat, the subsurface is Lambert's and
// base_weight scales the diffuse lobe, the defaults are what the node definition says, and what it cannot take is
// one message.
#include "core/targets/openpbr_surface.h"

#include <gtest/gtest.h>

#include "core/interfaces/fresnel.h"
#include "core/material.h"
#include "core/targets/eon_diffuse.h"
#include "core/targets/zeltner_fuzz.h"
#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_hemisphere;

Rgb integral_at_view(const OpenPbrSurface& surface, const Vec3& view) {
  return over_hemisphere<Rgb>([&](const Vec3& light) { return surface.brdf_cosine_weighted(light, view); }, 160,
                              Rgb::Zero());
}

// With specular_weight 0 the specular's index is 1 and its Fresnel 0, yet the graph's layer still takes c (0 a + 1
// b) from the light under it: the fit's F90 part (Schlick's F90 is 1 there). What passes, 1 - c b, at the
// specular's roughness as the coat makes it, lerp(r, min(1, r^4 + 2 r_c^4)^(1/4), C).
double passed_by_an_unweighted_specular(const OpenPbrParameters& p, double mu) {
  const double r = p.specular_roughness, rc = p.coat_roughness;
  const double roughened =
      r + (std::pow(std::min(1.0, std::pow(r, 4) + 2.0 * std::pow(rc, 4)), 0.25) - r) * p.coat_weight;
  return 1.0 - GgxDielectricReflection(1.0, roughened * roughened).layer_albedo(mu);
}

OpenPbrParameters every_lobe() {
  OpenPbrParameters p;
  p.base_color = Rgb(0.7, 0.4, 0.2);
  p.base_diffuse_roughness = 0.6;
  p.specular_roughness = 0.5;
  p.specular_ior = 1.4;
  p.specular_weight = 0.8;
  p.specular_color = Rgb(1.0, 0.9, 0.8);
  p.subsurface_weight = 0.5;
  p.subsurface_color = Rgb(0.9, 0.5, 0.3);
  p.coat_weight = 0.7;
  p.coat_roughness = 0.6;
  p.coat_color = Rgb(0.9, 0.95, 1.0);
  p.fuzz_weight = 0.4;
  p.fuzz_roughness = 0.5;
  p.fuzz_color = Rgb(0.8, 0.8, 1.0);
  return p;
}

TEST(OpenPbrSurface, TheAlbedoAtTheViewIsTheIntegralOfTheLobes) {
  const OpenPbrSurface surface(every_lobe());
  for (const double theta : {0.0, 0.6, 1.2}) {
    const Vec3 view = direction_from_angles(theta, 0.8);
    const Rgb integral = integral_at_view(surface, view), closed = surface.albedo(view.z());
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(integral(c), closed(c), 2e-3 * closed(c)) << theta << " " << c;
  }
}

// The specification's furnace test. The graph passes on 1 - E^ (Schlick's Fresnel, fitted) under a lobe that
// reflects E (the exact Fresnel, integrated), so a white surface reflects F E_fuzz + (1 - F E_fuzz) [C E_coat + (1 - C
// E^_coat) (E_spec + 1 - E^_spec)]: 1 where E = E^, and here within 1% of it.
TEST(OpenPbrSurface, AWhiteSurfaceUnderAWhiteCoatAndFuzzReflectsAllTheLightButWhatTheFitsMiss) {
  OpenPbrParameters p = every_lobe();
  p.base_color = p.subsurface_color = p.specular_color = p.coat_color = p.fuzz_color = Rgb::Ones();
  p.specular_weight = 1.0;
  const OpenPbrSurface surface(p);
  const GgxDielectricReflection coat(p.coat_ior, p.coat_roughness * p.coat_roughness);
  for (const double theta : {0.0, 0.5, 1.0, 1.4}) {
    const double mu = std::cos(theta);
    const Rgb closed = surface.albedo(mu);
    const double missed = coat.albedo(mu) - coat.layer_albedo(mu);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(closed(c), 1.0, 0.01) << theta;
    EXPECT_NE(closed(0), 1.0);
    EXPECT_NEAR(integral_at_view(surface, direction_from_angles(theta, 0.0))(0), closed(0), 3e-3) << theta;
    // Without the specular (weight 0: E = 0, E^ = c b) the sum is known term by term.
    OpenPbrParameters no_specular = p;
    no_specular.specular_weight = 0.0;
    const double fuzz = p.fuzz_weight * zeltner_fuzz_albedo(mu, p.fuzz_roughness), C = p.coat_weight;
    const double expected = fuzz + (1.0 - fuzz) * (C * coat.albedo(mu) + (1.0 - C * coat.layer_albedo(mu)) *
                                                                             passed_by_an_unweighted_specular(p, mu));
    EXPECT_NEAR(OpenPbrSurface(no_specular).albedo(mu)(1), expected, 1e-12);
    EXPECT_NE(missed, 0.0);
  }
}

// The node's defaults: a Lambertian 0.8 under a GGX dielectric of index 1.5 and roughness 0.3, nothing else.
TEST(OpenPbrSurface, TheDefaultsAreAGlossyDiffuse) {
  const OpenPbrSurface surface{OpenPbrParameters{}};
  const GgxDielectricReflection specular(1.5, 0.09);
  for (const double mu : {1.0, 0.5}) {
    const double expected = specular.albedo(mu) + (1.0 - specular.layer_albedo(mu)) * 0.8;
    EXPECT_NEAR(surface.albedo(mu)(0), expected, 1e-12);
  }
  // specular_weight 0 reflects nothing, and passes on all of the diffuse but the fit's F90 part: 0.1% at normal
  // incidence, more toward grazing.
  OpenPbrParameters matte;
  matte.specular_weight = 0.0;
  const OpenPbrSurface lambert(matte);
  EXPECT_NEAR(lambert.albedo(0.3)(1), 0.8 * passed_by_an_unweighted_specular(matte, 0.3), 1e-12);
  EXPECT_NEAR(passed_by_an_unweighted_specular(matte, 1.0), 1.0, 2e-3);
  const Vec3 view = direction_from_angles(0.9, 2.0);
  EXPECT_NEAR(lambert.brdf_cosine_weighted(direction_from_angles(0.2, 0.0), view)(2),
              0.8 * std::cos(0.2) / kPi * passed_by_an_unweighted_specular(matte, view.z()), 1e-12);
}

// Under a coat the base darkens by Delta = (1 - K) / (1 - E_b K): light the base sends up and the coat sends back
// down is absorbed again by a coloured base, so a white channel (E_b = 1, Delta = 1) keeps its albedo and the others
// lose some, against the same coat with darkening 0. K is the graph's: 1 - (1 - F0) / n^2, at n = 1.6 (F0 = (0.6 /
// 2.6)^2) 0.630177, for every view.
TEST(OpenPbrSurface, ACoatDarkensAColouredBaseByTheGraphsFactor) {
  OpenPbrParameters p;
  p.coat_weight = 1.0;
  p.coat_roughness = 0.3;
  p.base_color = Rgb(1.0, 0.5, 0.1);
  const OpenPbrSurface darkened(p);
  p.coat_darkening = 0.0;
  const OpenPbrSurface plain(p);
  const Rgb with = darkened.albedo(1.0), without = plain.albedo(1.0);
  EXPECT_NEAR(with(0), without(0), 1e-12);  // white: Delta = 1
  EXPECT_LT(with(1), without(1));
  EXPECT_LT(with(2) / without(2), 1.0);
  const double f0 = (0.6 / 2.6) * (0.6 / 2.6), K = 1.0 - (1.0 - f0) / (1.6 * 1.6);
  ASSERT_NEAR(K, 0.630177, 1e-6);
  for (const double theta : {0.0, 0.7, 1.3}) {
    const Vec3 light = direction_from_angles(0.4, 0.0), view = direction_from_angles(theta, 2.0);
    const Rgb ratio =
        darkened.lobes_cosine_weighted(light, view).diffuse / plain.lobes_cosine_weighted(light, view).diffuse;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ratio(c), (1.0 - K) / (1.0 - p.base_color(c) * K), 1e-12) << theta;
  }
}

// The coat's colour tints what lies under it by lerp(1, T_c, C), and what the coat takes, C E^_coat, multiplies
// apart (the specification's lerp(1, T_c (1 - E_coat), C) is another number at C = 0.5).
TEST(OpenPbrSurface, UnderAPartialCoatTheTintAndTheCoatsShareMultiply) {
  OpenPbrParameters p;
  p.specular_weight = 0.0;
  p.base_color = Rgb::Ones();
  p.coat_weight = 0.5;
  p.coat_roughness = 0.4;
  p.coat_color = Rgb(0.2, 0.6, 1.0);
  const OpenPbrSurface surface(p);
  const GgxDielectricReflection coat(p.coat_ior, 0.16);
  for (const double mu : {1.0, 0.4}) {
    const Rgb expected = 0.5 * coat.albedo(mu) + (1.0 - 0.5 * coat.layer_albedo(mu)) *
                                                     (1.0 + (p.coat_color - 1.0) * 0.5) *
                                                     passed_by_an_unweighted_specular(p, mu);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(surface.albedo(mu)(c), expected(c), 1e-12) << mu;
  }
}

// At the BRDF's scale MaterialX's subsurface is Lambert's lobe of albedo subsurface_color, whatever the diffuse
// roughness; base_weight multiplies the EON lobe of base_color (it does not dim the colour EON's multiple
// scattering sees).
TEST(OpenPbrSurface, SubsurfaceIsLambertAndBaseWeightScalesTheDiffuseLobe) {
  OpenPbrParameters p;
  p.specular_weight = 0.0;
  p.base_diffuse_roughness = 0.8;
  p.subsurface_weight = 1.0;
  p.subsurface_color = Rgb(0.9, 0.4, 0.1);
  const Vec3 light = direction_from_angles(0.5, 0.0), view = direction_from_angles(1.1, 2.5);
  const Rgb lambert = OpenPbrSurface(p).brdf_cosine_weighted(light, view);
  const double passed = passed_by_an_unweighted_specular(p, view.z());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(lambert(c), p.subsurface_color(c) * std::cos(0.5) / kPi * passed, 1e-12);
  p.subsurface_weight = 0.0;
  p.base_weight = 0.5;
  p.base_color = Rgb(0.9, 0.6, 0.3);
  for (const double mu : {1.0, 0.3}) {
    const Rgb expected = 0.5 * eon_diffuse_albedo(p.base_color, 0.8, mu) * passed_by_an_unweighted_specular(p, mu);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(OpenPbrSurface(p).albedo(mu)(c), expected(c), 1e-12);
  }
}

TEST(OpenPbrSurface, RefusesWhatItCannotTakeNamingTheInput) {
  const auto refused = [](OpenPbrParameters p, const char* name) {
    try {
      OpenPbrSurface surface(p);
    } catch (const ParameterError& error) {
      return std::string(error.what()).find(name) != std::string::npos;
    }
    return false;
  };
  OpenPbrParameters p;
  p.base_color(1) = 1.2;
  EXPECT_TRUE(refused(p, "base_color"));
  p = {};
  p.specular_ior = 0.0;
  EXPECT_TRUE(refused(p, "specular_ior"));
  p = {};
  p.coat_roughness = -0.1;
  EXPECT_TRUE(refused(p, "coat_roughness"));
  p = {};
  p.base_metalness = 1.0;
  EXPECT_TRUE(refused(p, "base_metalness"));
  p = {};
  p.subsurface_scatter_anisotropy = 2.0;
  EXPECT_TRUE(refused(p, "subsurface_scatter_anisotropy"));
}

}  // namespace
}  // namespace skinlayer
