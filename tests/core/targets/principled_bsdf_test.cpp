// Blender 3.4's Principled BSDF (docs/model.md §22.1): reciprocity, closed-form albedos of its lobes, the normalization
// of its distributions, and how its weights split the light.
#include "core/targets/principled_bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/material.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

constexpr double kMinRoughnessChecked = 0.1;  // the fit's least (core/fit/principled_fit.h)

TEST(PrincipledBsdf, IsReciprocal) {
  const PrincipledParameters p{.base_color = Rgb(0.9, 0.4, 0.2),
                               .metallic = 0.3,
                               .specular_tint = 0.4,
                               .sheen = 0.6,
                               .clearcoat = 0.7,
                               .clearcoat_roughness = 0.2};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> theta(0.0, 1.5), phi(0.0, 2.0 * kPi);
  for (int n = 0; n < 200; ++n) {
    const Vec3 a = direction_from_angles(theta(random), phi(random)),
               b = direction_from_angles(theta(random), phi(random));
    const Rgb ab = principled_brdf(p, a, b), ba = principled_brdf(p, b, a);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ab(c), ba(c), 1e-12 * std::max(1.0, ab(c)));
  }
}

// Seen from the normal (F_o = 0), the diffuse lobe is (1/pi)[(1 - F_i/2) + r (1 + mu) F_i], so its albedo is
//   2 int_0^1 [1 - (1 - mu)^5 / 2 + r (1 + mu)(1 - mu)^5] mu d mu = 41/42 + 5 r / 84,
// from B(2, 6) = 1/42 and B(3, 6) = 1/168. At roughness 1 that is 1.036: Burley's diffuse is not energy-conserving.
TEST(PrincipledBsdf, DiffuseAlbedoFromTheNormalIsTheClosedForm) {
  PrincipledParameters p;
  p.base_color = Rgb::Ones();
  p.specular = 0.0;
  for (const double roughness : {0.0, 0.5, 1.0}) {
    p.roughness = roughness;
    EXPECT_NEAR(principled_albedo(p, Vec3::UnitZ(), 192)(0), 41.0 / 42.0 + 5.0 * roughness / 84.0, 1e-6) << roughness;
  }
}

// A white metal's specular is GGX with F = 1: its albedo is 1 less what the masking removes, which vanishes as the
// surface turns smooth. At the specular parameter s a smooth dielectric reflects F_eta(1) = 0.08 s at normal incidence:
// Cycles' eta = 2 / (1 - sqrt(0.08 s)) - 1 is that reflectance's index.
TEST(PrincipledBsdf, SpecularLobeIsNormalizedAndItsIndexGivesItsReflectance) {
  PrincipledParameters metal;
  metal.base_color = Rgb::Ones();
  metal.metallic = 1.0;
  metal.roughness = 0.1;
  EXPECT_NEAR(principled_albedo(metal, Vec3::UnitZ())(0), 1.0, 2e-4);
  metal.roughness = 0.7;
  const double rough = principled_albedo(metal, direction_from_angles(1.2, 0.0))(0);
  EXPECT_LT(rough, 0.97);  // single scattering loses light at grazing incidence on a rough surface
  EXPECT_GT(rough, 0.5);
  PrincipledParameters dielectric;
  dielectric.base_color = Rgb::Zero();
  dielectric.roughness = 0.1;
  for (const double specular : {0.25, 0.5, 1.0}) {
    dielectric.specular = specular;
    EXPECT_NEAR(principled_albedo(dielectric, Vec3::UnitZ())(0), 0.08 * specular, 2e-3 * specular) << specular;
  }
}

// The albedo's quadrature follows each microfacet lobe's width and stops its polar nodes where the view meets the
// horizon, so that sharp lobes and grazing light converge at the default 48 nodes: within 1e-5 of 192 nodes, down to
// the fit's least roughness.
TEST(PrincipledBsdf, AlbedoConvergesForSharpLobesAndGrazingLight) {
  for (const double roughness : {kMinRoughnessChecked, 0.3, 1.0}) {
    for (const double theta : {0.0, 1.0, 1.4}) {
      PrincipledParameters p;
      p.base_color = Rgb(0.5, 0.2, 0.1);
      p.roughness = roughness;
      p.sheen = 0.5;
      p.clearcoat = 1.0;
      p.clearcoat_roughness = roughness;
      const PrincipledLobes coarse = principled_lobe_albedos(p, direction_from_angles(theta, 0.3));
      const PrincipledLobes fine = principled_lobe_albedos(p, direction_from_angles(theta, 0.3), 192);
      EXPECT_NEAR(coarse.specular(0), fine.specular(0), 1e-5 * fine.specular(0)) << roughness << " " << theta;
      EXPECT_NEAR(coarse.clearcoat(0), fine.clearcoat(0), 1e-5 * fine.clearcoat(0)) << roughness << " " << theta;
      EXPECT_NEAR(coarse.diffuse(0), fine.diffuse(0), 1e-5 * fine.diffuse(0)) << roughness << " " << theta;
      EXPECT_NEAR(coarse.sheen(0), fine.sheen(0), 1e-5 * fine.sheen(0)) << roughness << " " << theta;
    }
  }
}

// The clearcoat's GTR1 distribution (Berry) is normalized but heavy-tailed: of its microfacets, the fraction tilted
// less than 45 degrees, which reflect light from the normal back above the horizon, is
//   int_{cos^2 > 1/2} D cos(theta_m) d omega_m = 1 - ln((1 + a^2) / 2) / ln(a^2),
// 92.5% at a = 0.01. So a smooth coat seen from the normal reflects about 0.25 clearcoat times its 0.04 times that,
// within 2% (masking, and the Fresnel's rise on the tilted facets), and twice the coat reflects twice the light.
TEST(PrincipledBsdf, ClearcoatReflectsItsFresnelTimesAQuarterOfItsUpperFacets) {
  PrincipledParameters p;
  p.base_color = Rgb::Zero();
  p.specular = 0.0;
  p.clearcoat = 1.0;
  p.clearcoat_roughness = 0.1;
  const PrincipledLobes coat_only = principled_lobes_cosine_weighted(p, Vec3::UnitZ(), direction_from_angles(0.3, 1.0));
  EXPECT_EQ(coat_only.diffuse.maxCoeff(), 0.0);
  const double a2 = 1e-4, upper = 1.0 - std::log(0.5 * (1.0 + a2)) / std::log(a2);
  const double coat = principled_albedo(p, Vec3::UnitZ())(0);
  EXPECT_NEAR(coat, 0.25 * 0.04 * upper, 0.02 * 0.25 * 0.04 * upper);
  p.clearcoat = 0.5;
  EXPECT_NEAR(principled_albedo(p, Vec3::UnitZ())(0), 0.5 * coat, 1e-12);
}

// Metal removes the diffuse and sheen lobes; the specular tint and the sheen tint colour their lobes by the base
// colour's hue.
TEST(PrincipledBsdf, WeightsAndTintsSplitTheLight) {
  PrincipledParameters p{.base_color = Rgb(0.8, 0.2, 0.1), .specular_tint = 1.0, .sheen = 1.0, .sheen_tint = 1.0};
  const Vec3 in = direction_from_angles(0.7, 0.0), out = direction_from_angles(1.1, 2.0);
  const PrincipledLobes dielectric = principled_lobes_cosine_weighted(p, in, out);
  EXPECT_GT(dielectric.sheen(0), dielectric.sheen(1));
  EXPECT_GT(dielectric.specular(0), dielectric.specular(1));
  p.metallic = 1.0;
  const PrincipledLobes metal = principled_lobes_cosine_weighted(p, in, out);
  EXPECT_EQ(metal.diffuse.maxCoeff(), 0.0);
  EXPECT_EQ(metal.sheen.maxCoeff(), 0.0);
  EXPECT_GT(metal.specular(0), dielectric.specular(0));
  EXPECT_EQ(principled_brdf(p, in, direction_from_angles(1.0, 0.0) * -1.0).maxCoeff(),
            0.0);  // below the surface: nothing
}

// At the BRDF's scale subsurface scattering is the diffuse lobe in the mixed colour: a subsurface of weight 1 is the
// base colour's diffuse with the subsurface colour, whatever its radius; half of it is the half-way colour; the
// sheen keeps the base colour.
TEST(PrincipledBsdf, SubsurfaceIsTheDiffuseLobeInTheMixedColour) {
  PrincipledParameters diffuse;
  diffuse.base_color = Rgb(0.6, 0.3, 0.1);
  diffuse.sheen = 0.5;
  PrincipledParameters subsurface = diffuse;
  subsurface.base_color = Rgb(0.2, 0.2, 0.2);
  subsurface.subsurface = 1.0;
  subsurface.subsurface_color = Rgb(0.6, 0.3, 0.1);
  subsurface.subsurface_radius = Rgb(5.0, 1.0, 0.1);
  const Vec3 light = direction_from_angles(0.4, 0.0), view = direction_from_angles(1.1, 2.0);
  const PrincipledLobes a = principled_lobes_cosine_weighted(diffuse, light, view);
  const PrincipledLobes b = principled_lobes_cosine_weighted(subsurface, light, view);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.diffuse(c), b.diffuse(c), 1e-15);
  subsurface.subsurface = 0.5;
  PrincipledParameters halfway = diffuse;
  halfway.base_color = Rgb(0.4, 0.25, 0.15);
  const double mixed = principled_lobes_cosine_weighted(subsurface, light, view).diffuse(0);
  EXPECT_NEAR(mixed, principled_lobes_cosine_weighted(halfway, light, view).diffuse(0), 1e-15);
  PrincipledParameters no_subsurface = subsurface;
  no_subsurface.subsurface = 0.0;
  const Rgb sheen = principled_lobes_cosine_weighted(subsurface, light, view).sheen;
  EXPECT_GT(sheen(0), 0.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(sheen(c), principled_lobes_cosine_weighted(no_subsurface, light, view).sheen(c));
  }
}

// Transmission: the glass reflects the Fresnel of its IOR at the view's angle and refracts the rest. A white,
// fully transmissive node of roughness 0.3 under a white sky on both sides sends toward the view F (its reflection,
// within 2%) plus 1 - F (its refraction from below, within 1%): all the light, as Cycles' closures weigh it. The base
// colour tints the refraction only (tint 0), and the diffuse lobe gives way as transmission rises.
TEST(PrincipledBsdf, GlassReflectsItsFresnelAndRefractsTheRest) {
  PrincipledParameters glass;
  glass.base_color = Rgb::Ones();
  glass.transmission = 1.0;
  glass.roughness = 0.3;
  glass.ior = 1.45;
  for (const double theta : {0.0, 0.8}) {
    const Vec3 view = direction_from_angles(theta, 0.0);
    const double fresnel = fresnel_dielectric(std::cos(theta), glass.ior);
    const PrincipledLobes reflected = principled_lobe_albedos(glass, view);
    EXPECT_NEAR(reflected.glass(0), fresnel, 0.02 * fresnel) << theta;
    EXPECT_EQ(reflected.diffuse(0), 0.0);
    const QuadratureRule mu = gauss_legendre(400, 0.0, 1.0), phi = gauss_legendre(800, 0.0, 2.0 * kPi);
    double refracted = 0.0;
    for (std::size_t a = 0; a < mu.nodes.size(); ++a) {
      for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
        const Vec3 below = direction_from_angles(kPi - std::acos(mu.nodes[a]), phi.nodes[b]);
        refracted += mu.weights[a] * phi.weights[b] * principled_btdf_cosine_weighted(glass, below, view)(0);
      }
    }
    EXPECT_NEAR(refracted, 1.0 - fresnel, 0.01 * (1.0 - fresnel)) << theta;
    EXPECT_NEAR(reflected.glass(0) + refracted, 1.0, 0.01) << theta;
  }
  PrincipledParameters tinted = glass;
  tinted.base_color = Rgb(0.5, 0.25, 1.0);
  const Vec3 below = direction_from_angles(2.8, 0.3), view = direction_from_angles(0.2, 0.0);
  const Rgb white = principled_btdf_cosine_weighted(glass, below, view);
  const Rgb colored = principled_btdf_cosine_weighted(tinted, below, view);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(colored(c), tinted.base_color(c) * white(c), 1e-15);
  const Vec3 light = direction_from_angles(0.4, 0.0), mirror = direction_from_angles(0.4, kPi);
  EXPECT_EQ(principled_lobes_cosine_weighted(tinted, light, mirror).glass(1),
            principled_lobes_cosine_weighted(glass, light, mirror).glass(1));
  PrincipledParameters half = tinted;
  half.transmission = 0.5;
  PrincipledParameters opaque = tinted;
  opaque.transmission = 0.0;
  EXPECT_NEAR(principled_lobes_cosine_weighted(half, light, view).diffuse(0),
              0.5 * principled_lobes_cosine_weighted(opaque, light, view).diffuse(0), 1e-15);
  EXPECT_EQ(principled_btdf_cosine_weighted(glass, view, light).maxCoeff(), 0.0);  // both above: no refraction
}

TEST(PrincipledBsdf, RefusesWhatItCannotTake) {
  PrincipledParameters p;
  p.roughness = 1.5;
  EXPECT_THROW(principled_brdf(p, Vec3::UnitZ(), Vec3::UnitZ()), ParameterError);
  p.roughness = 0.5;
  p.anisotropic = 0.5;
  EXPECT_THROW(principled_brdf(p, Vec3::UnitZ(), Vec3::UnitZ()), ParameterError);
  p.anisotropic = 0.0;
  p.ior = 0.0;
  EXPECT_THROW(principled_brdf(p, Vec3::UnitZ(), Vec3::UnitZ()), ParameterError);
  p.ior = 1.45;
  p.subsurface_radius(1) = -1.0;
  EXPECT_THROW(principled_brdf(p, Vec3::UnitZ(), Vec3::UnitZ()), ParameterError);
}

}  // namespace
}  // namespace skinlayer
