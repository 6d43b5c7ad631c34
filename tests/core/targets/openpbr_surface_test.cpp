// OpenPBR Surface's opaque lobes (docs/model.md §22.3): the closed-form albedo at the view is the integral of the
// lobes, a white surface under a white coat and a white fuzz reflects all the light (the specification's furnace
// test), the defaults are what the node definition says, and what it cannot take is one message.
#include "core/targets/openpbr_surface.h"

#include <gtest/gtest.h>

#include "core/interfaces/fresnel.h"
#include "core/material.h"
#include "core/targets/eon_diffuse.h"
#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_hemisphere;

Rgb integral_at_view(const OpenPbrSurface& surface, const Vec3& view) {
  return over_hemisphere<Rgb>([&](const Vec3& light) { return surface.brdf_cosine_weighted(light, view); }, 160,
                              Rgb::Zero());
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

TEST(OpenPbrSurface, AWhiteSurfaceUnderAWhiteCoatAndFuzzReflectsAllTheLight) {
  OpenPbrParameters p = every_lobe();
  p.base_color = p.subsurface_color = p.specular_color = p.coat_color = p.fuzz_color = Rgb::Ones();
  p.specular_weight = 1.0;
  const OpenPbrSurface surface(p);
  for (const double theta : {0.0, 0.5, 1.0, 1.4}) {
    const Rgb closed = surface.albedo(std::cos(theta));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(closed(c), 1.0, 1e-12) << theta;
    EXPECT_NEAR(integral_at_view(surface, direction_from_angles(theta, 0.0))(0), 1.0, 3e-3) << theta;
  }
}

// The node's defaults: a Lambertian 0.8 under a GGX dielectric of index 1.5 and roughness 0.3, nothing else.
TEST(OpenPbrSurface, TheDefaultsAreAGlossyDiffuse) {
  const OpenPbrSurface surface{OpenPbrParameters{}};
  const GgxDielectricReflection specular(1.5, 0.09);
  for (const double mu : {1.0, 0.5}) {
    const double expected = specular.albedo(mu) + (1.0 - specular.albedo(mu)) * 0.8;
    EXPECT_NEAR(surface.albedo(mu)(0), expected, 1e-12);
  }
  // specular_weight 0 leaves the diffuse alone.
  OpenPbrParameters matte;
  matte.specular_weight = 0.0;
  const OpenPbrSurface lambert(matte);
  EXPECT_NEAR(lambert.albedo(0.3)(1), 0.8, 1e-12);
  EXPECT_NEAR(lambert.brdf_cosine_weighted(direction_from_angles(0.2, 0.0), direction_from_angles(0.9, 2.0))(2),
              0.8 * std::cos(0.2) / kPi, 1e-12);
}

// Under a coat the base darkens by Delta = (1 - K) / (1 - E_b K): light the base sends up and the coat sends back
// down is absorbed again by a coloured base, so a white channel (E_b = 1, Delta = 1) keeps its albedo and the others
// lose some, against the same coat with darkening 0.
TEST(OpenPbrSurface, ACoatDarkensAColouredBaseAndNotAWhiteOne) {
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
