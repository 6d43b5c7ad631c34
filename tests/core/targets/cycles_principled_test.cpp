// Blender 4.x-5.x's Principled BSDF as Cycles evaluates it (docs/model.md §22.1.1): each lobe's closed-form albedo is
// its integral, a white surface under a white sky, the single-scattering specular is core's GGX lobe, the layers'
// weights (coat tint, sheen, specular IOR level), subsurface at the BRDF's scale, reciprocity of the lobes, and the
// range checks.
#include "core/targets/cycles_principled.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/material.h"
#include "core/targets/cycles_sheen.h"
#include "core/targets/fresnel_terms.h"
#include "core/targets/ggx_dielectric_reflection.h"
#include "core/targets/ggx_energy_compensation.h"
#include "core/targets/ggx_fresnel_estimate.h"
#include "core/targets/ggx_lobe.h"
#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_hemisphere;

// Every lobe on, coloured, rough enough for the quadratures below.
CyclesPrincipledParameters everything(double roughness) {
  CyclesPrincipledParameters p;
  p.base_color = Rgb(0.7, 0.4, 0.2);
  p.roughness = roughness;
  p.ior = 1.45;
  p.diffuse_roughness = 0.5;
  p.subsurface_weight = 0.3;
  p.specular_ior_level = 0.6;
  p.specular_tint = Rgb(1.0, 0.9, 0.8);
  p.coat_weight = 0.7;
  p.coat_roughness = 0.2;
  p.coat_ior = 1.6;
  p.coat_tint = Rgb(0.9, 0.8, 0.7);
  p.sheen_weight = 0.6;
  p.sheen_roughness = 0.4;
  p.sheen_tint = Rgb(1.0, 0.8, 0.6);
  return p;
}

using LobeOf = std::function<Rgb(const CyclesPrincipledLobes&)>;

// The microfacet lobes over half vectors (core's ggx_lobe.h), the others over the light's hemisphere.
Rgb integrate(const CyclesPrincipled& surface, const Vec3& view, const LobeOf& lobe, double width) {
  const auto g = [&](const Vec3& light) { return lobe(surface.lobes_cosine_weighted(light, view)); };
  if (width > 0.0) return microfacet_lobe_albedo(g, view, width, 96);
  return over_hemisphere<Rgb>(g, 96, Rgb::Zero());
}

void expect_close(const Rgb& a, const Rgb& b, double relative, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a(c), b(c), relative * std::abs(b(c)) + 1e-7) << what << " channel " << c;
}

TEST(CyclesPrincipled, EachLobesAlbedoIsItsIntegral) {
  for (const double roughness : {0.3, 0.6, 1.0}) {
    const CyclesPrincipled surface(everything(roughness));
    for (const double theta : {0.0, 0.6, 1.2}) {
      const Vec3 view = direction_from_angles(theta, 0.4);
      const CyclesPrincipledLobes albedos = surface.lobe_albedos(view.z());
      const std::string at = std::to_string(roughness) + " " + std::to_string(theta);
      expect_close(integrate(
                       surface, view, [](const CyclesPrincipledLobes& l) { return l.sheen; }, 0.0),
                   albedos.sheen, 2e-3, "sheen " + at);
      expect_close(integrate(
                       surface, view, [](const CyclesPrincipledLobes& l) { return l.coat; }, 0.04),
                   albedos.coat, 1e-3, "coat " + at);
      expect_close(integrate(
                       surface, view, [](const CyclesPrincipledLobes& l) { return l.specular; }, roughness * roughness),
                   albedos.specular, 1e-3, "specular " + at);
      expect_close(integrate(
                       surface, view, [](const CyclesPrincipledLobes& l) { return l.diffuse; }, 0.0),
                   albedos.diffuse, 2e-4, "diffuse " + at);
      expect_close(integrate(
                       surface, view, [](const CyclesPrincipledLobes& l) { return l.subsurface; }, 0.0),
                   albedos.subsurface, 2e-4, "subsurface " + at);
      EXPECT_GT(albedos.sheen.minCoeff(), 0.0);
      EXPECT_GT(albedos.coat.minCoeff(), 0.0);
      expect_close(surface.albedo(view.z()), albedos.sum(), 1e-15, "sum " + at);
    }
  }
}

// A white base under a white sky. With "Multiscatter GGX" Cycles gives back what single scattering loses, but it
// layers the base under the specular by an estimate (the visible-normal mean of the Fresnel blend from a 16^3 table,
// read trilinearly, times E from a 32^2 table), not by the lobe's own albedo, so it is white only as far as that
// estimate goes. Measured on roughness 0 to 1 by 0.02: within 2e-4 of 1 seen from the normal, 1e-3 down to cosine 0.6,
// 5e-3 to 0.3, 1.1% to 0.1; at cosine 0.05 the estimate falls short and a surface of roughness 0.12 reflects 3.4% more
// than it receives. "GGX" does not compensate and darkens the base by the Fresnel estimate alone: 2.9% lost from the
// normal at roughness 1, up to 4.7% at grazing views.
TEST(CyclesPrincipled, WhiteFurnace) {
  const auto tolerance = [](double mu) { return mu == 1.0 ? 3e-4 : (mu >= 0.6 ? 1.5e-3 : (mu >= 0.3 ? 6e-3 : 0.012)); };
  for (const double roughness : {0.0, 0.12, 0.3, 0.5, 0.6, 0.8, 1.0}) {
    CyclesPrincipledParameters p;
    p.base_color = Rgb::Ones();
    p.roughness = roughness;
    const CyclesPrincipled multiple(p);
    p.distribution = CyclesDistribution::kGgx;
    const CyclesPrincipled single(p);
    for (const double mu : {1.0, 0.8, 0.6, 0.45, 0.3, 0.15, 0.1, 0.05}) {
      const double A = multiple.albedo(mu)(0);
      if (mu >= 0.1) {
        EXPECT_NEAR(A, 1.0, tolerance(mu)) << roughness << " " << mu;
      }
      EXPECT_LE(single.albedo(mu)(0), A + 1e-12) << roughness << " " << mu;
      EXPECT_GT(single.albedo(mu)(0), 0.95) << roughness << " " << mu;
    }
    EXPECT_NEAR(multiple.albedo(0.05)(0), 1.0, 0.035) << roughness;
  }
  CyclesPrincipledParameters grazing;
  grazing.base_color = Rgb::Ones();
  grazing.roughness = 0.12;
  EXPECT_GT(CyclesPrincipled(grazing).albedo(0.05)(0), 1.03);
  grazing.roughness = 1.0;
  grazing.distribution = CyclesDistribution::kGgx;
  EXPECT_NEAR(CyclesPrincipled(grazing).albedo(1.0)(0), 0.9714, 5e-4);
  // The coat (compensated whatever the distribution), the sheen and the diffuse roughness keep a white base white
  // from the normal.
  CyclesPrincipledParameters layered;
  layered.base_color = Rgb::Ones();
  layered.coat_weight = 1.0;
  layered.coat_roughness = 0.3;
  layered.sheen_weight = 1.0;
  layered.diffuse_roughness = 1.0;
  EXPECT_NEAR(CyclesPrincipled(layered).albedo(1.0)(0), 1.0, 5e-4);
}

// With Specular IOR Level 0.5 and a white tint the Principled Fresnel is the dielectric Fresnel of the IOR, and the
// "GGX" specular is core's single-scattering GGX: F D G2 / (4 mu_o). OpenPBR's GGX reflection is the same lobe
// times its own compensation at the view, so the two share their shape over the light and their ratio of lobe to
// albedo.
TEST(CyclesPrincipled, SingleScatteringSpecularIsCoresGgxLobe) {
  CyclesPrincipledParameters p;
  p.base_color = Rgb(0.3, 0.3, 0.3);
  p.roughness = 0.55;
  p.ior = 1.6;
  p.distribution = CyclesDistribution::kGgx;
  const CyclesPrincipled surface(p);
  const double alpha = p.roughness * p.roughness;
  const GgxDielectricReflection core(p.ior, alpha);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> theta(0.0, 1.4), phi(0.0, 2.0 * kPi);
  for (int n = 0; n < 50; ++n) {
    const Vec3 light = direction_from_angles(theta(random), phi(random)),
               view = direction_from_angles(theta(random), 0.0);
    const Vec3 h = (light + view).normalized();
    const double expected = fresnel_dielectric(light.dot(h), p.ior) * ggx_distribution(h.z(), alpha) *
                            ggx_height_correlated_masking(light.z(), view.z(), alpha) / (4.0 * view.z());
    EXPECT_NEAR(surface.lobes_cosine_weighted(light, view).specular(0), expected, 1e-12 * expected + 1e-15);
    const double ratio = core.cosine_weighted(light, view) / core.albedo(view.z());
    EXPECT_NEAR(expected / surface.lobe_albedos(view.z()).specular(0), ratio, 2e-3 * ratio);
  }
}

// A coat tint T is Beer's law along the view refracted into the coat, T^(1/cos_t), mixed in by the coat's weight; it
// tints all below the coat and not the coat.
TEST(CyclesPrincipled, CoatTintIsBeersLawAlongTheRefractedView) {
  CyclesPrincipledParameters p;
  p.coat_weight = 1.0;
  p.coat_ior = 1.7;
  CyclesPrincipledParameters tinted = p;
  tinted.coat_tint = Rgb(0.5, 0.7, 0.9);
  for (const double weight : {1.0, 0.5}) {
    p.coat_weight = tinted.coat_weight = weight;
    const CyclesPrincipled clear(p), coloured(tinted);
    for (const double theta : {0.0, 1.0}) {
      const Vec3 light = direction_from_angles(0.3, 0.0), view = direction_from_angles(theta, 2.0);
      const double sin2 = std::sin(theta) * std::sin(theta);
      const double cos_t = std::sqrt(1.0 - sin2 / (p.coat_ior * p.coat_ior));
      const Rgb expected = 1.0 + (tinted.coat_tint.pow(1.0 / cos_t) - 1.0) * weight;
      const CyclesPrincipledLobes a = clear.lobes_cosine_weighted(light, view),
                                  b = coloured.lobes_cosine_weighted(light, view);
      expect_close(b.diffuse / a.diffuse, expected, 1e-12, "diffuse");
      expect_close(b.specular / a.specular, expected, 1e-12, "specular");
      expect_close(b.coat, a.coat, 1e-15, "coat");
    }
  }
}

// Blender 4.0-4.3's coat (before Cycles' 2b408569): no energy compensation, and the layers under it keep 1 - W F(mu_o),
// the Fresnel of a smooth surface at the view; 4.4 on compensates it and estimates its albedo from its tables. At a
// rough coat and a grazing view the two part (the older coat loses light its successor keeps).
TEST(CyclesPrincipled, CoatBeforeBlender44IsUncompensatedAndEstimatedByItsFresnel) {
  CyclesPrincipledParameters today;
  today.coat_weight = 0.8;
  today.coat_roughness = 0.5;
  today.coat_ior = 1.5;
  CyclesPrincipledParameters older = today;
  older.release = CyclesRelease::kBlender4_0To4_3;
  const CyclesPrincipled now(today), before(older);
  for (const double mu : {1.0, 0.5, 0.2}) {
    const CyclesPrincipled::Layering l = before.layering(mu), m = now.layering(mu);
    EXPECT_EQ(l.coat_compensation, 1.0) << mu;
    EXPECT_GT(m.coat_compensation, 1.0) << mu;
    expect_close(l.under_coat, Rgb::Constant(1.0 - 0.8 * fresnel_dielectric(mu, 1.5)), 1e-12, "under the coat");
    const Vec3 light = direction_from_angles(0.4, 0.0), view(std::sqrt(1.0 - mu * mu), 0.0, mu);
    expect_close(before.lobes_cosine_weighted(light, view).coat,
                 now.lobes_cosine_weighted(light, view).coat / m.coat_compensation, 1e-12, "coat lobe");
  }
  EXPECT_LT(before.albedo(0.2)(0), now.albedo(0.2)(0));
}

// The sheen leaves w1 = 1 - W E_sh max_c(T) to the layers below it (closure_layering_weight: one factor, the
// largest channel's), E_sh the sheen's albedo at the view.
TEST(CyclesPrincipled, SheenLeavesTheRestByItsLargestChannel) {
  CyclesPrincipledParameters p;
  p.roughness = 0.4;
  CyclesPrincipledParameters sheened = p;
  sheened.sheen_weight = 0.8;
  sheened.sheen_roughness = 0.3;
  sheened.sheen_tint = Rgb(0.2, 0.9, 0.5);
  const CyclesPrincipled bare(p), fuzzy(sheened);
  for (const double theta : {0.2, 1.3}) {
    const Vec3 light = direction_from_angles(0.6, 0.0), view = direction_from_angles(theta, 1.0);
    const double left = 1.0 - 0.8 * 0.9 * cycles_sheen_albedo(view.z(), 0.3);
    const CyclesPrincipledLobes a = bare.lobes_cosine_weighted(light, view),
                                b = fuzzy.lobes_cosine_weighted(light, view);
    expect_close(b.specular, a.specular * left, 1e-12, "specular");
    expect_close(b.diffuse, a.diffuse * left, 1e-12, "diffuse");
    expect_close(b.sheen, 0.8 * sheened.sheen_tint * cycles_sheen_cosine_weighted(0.3, light, view), 1e-12, "sheen");
  }
}

// Specular IOR Level L scales F0 by 2 L: 0 removes the specular (and leaves the base whole), 1 doubles F0; the tint
// scales F0 per channel.
TEST(CyclesPrincipled, SpecularIorLevelScalesF0) {
  CyclesPrincipledParameters p;
  p.base_color = Rgb(0.5, 0.4, 0.3);
  p.roughness = 0.08;
  p.specular_ior_level = 0.0;
  const Vec3 light = direction_from_angles(0.5, 0.0), view = direction_from_angles(0.8, 2.0);
  const CyclesPrincipledLobes none = CyclesPrincipled(p).lobes_cosine_weighted(light, view);
  EXPECT_EQ(none.specular.maxCoeff(), 0.0);
  expect_close(none.diffuse, p.base_color * light.z() * kInvPi, 1e-15, "bare base");
  const double f0 = normal_reflectance(1.5);
  for (const double level : {0.5, 1.0}) {
    p.specular_ior_level = level;
    p.base_color = Rgb::Zero();
    p.specular_tint = Rgb(1.0, 0.5, 0.25);
    // From the normal a near-mirror reflects about its F0 (the blend is 0 there): within 2%.
    const Rgb normal = CyclesPrincipled(p).lobe_albedos(1.0).specular;
    expect_close(normal, 2.0 * level * f0 * p.specular_tint, 0.02, "level " + std::to_string(level));
  }
}

// At the BRDF's scale subsurface is Lambert in the base colour, whatever the diffuse roughness and the walk's radius,
// scale, IOR and anisotropy: a full subsurface weight gives the Lambert base of Diffuse Roughness 0.
TEST(CyclesPrincipled, SubsurfaceIsLambertInTheBaseColour) {
  CyclesPrincipledParameters lambert;
  lambert.base_color = Rgb(0.8, 0.5, 0.3);
  lambert.roughness = 0.4;
  CyclesPrincipledParameters subsurface = lambert;
  subsurface.subsurface_weight = 1.0;
  subsurface.diffuse_roughness = 0.9;
  subsurface.subsurface_radius = Rgb(3.0, 2.0, 1.0);
  subsurface.subsurface_scale = 2.0;
  subsurface.subsurface_ior = 1.3;
  subsurface.subsurface_anisotropy = 0.8;
  const Vec3 light = direction_from_angles(0.9, 0.0), view = direction_from_angles(0.4, 1.5);
  const CyclesPrincipledLobes a = CyclesPrincipled(lambert).lobes_cosine_weighted(light, view);
  const CyclesPrincipledLobes b = CyclesPrincipled(subsurface).lobes_cosine_weighted(light, view);
  EXPECT_EQ(b.diffuse.maxCoeff(), 0.0);
  expect_close(b.subsurface, a.diffuse, 1e-15, "subsurface");
  expect_close(CyclesPrincipled(subsurface).albedo(0.4), CyclesPrincipled(lambert).albedo(0.4), 1e-15, "albedo");
}

// Each lobe over the weight its view gives it is reciprocal (the specular and coat are GGX, the diffuse Cycles'
// Oren-Nayar, the subsurface Lambert); the BRDF, layered at the view, is not.
TEST(CyclesPrincipled, LobesAreReciprocalTheirLayeringIsNot) {
  const CyclesPrincipled surface(everything(0.5));
  const CyclesPrincipledParameters& p = surface.parameters();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> theta(0.05, 1.4), phi(0.0, 2.0 * kPi);
  double asymmetry = 0.0;
  for (int n = 0; n < 100; ++n) {
    const Vec3 a = direction_from_angles(theta(random), phi(random)),
               b = direction_from_angles(theta(random), phi(random));
    const CyclesPrincipledLobes ab = surface.lobes_cosine_weighted(a, b), ba = surface.lobes_cosine_weighted(b, a);
    const CyclesPrincipled::Layering lb = surface.layering(b.z()), la = surface.layering(a.z());
    const auto symmetric = [&](const Rgb& x, const Rgb& y, const std::string& what) {
      expect_close(Rgb(x / a.z()), Rgb(y / b.z()), 1e-10, what);
    };
    symmetric(ab.specular / (lb.under_coat * lb.specular_compensation),
              ba.specular / (la.under_coat * la.specular_compensation), "specular");
    symmetric(ab.coat / (p.coat_weight * lb.under_sheen * lb.coat_compensation),
              ba.coat / (p.coat_weight * la.under_sheen * la.coat_compensation), "coat");
    symmetric(ab.diffuse / lb.under_specular, ba.diffuse / la.under_specular, "diffuse");
    symmetric(ab.subsurface / lb.under_specular, ba.subsurface / la.under_specular, "subsurface");
    asymmetry = std::max(asymmetry, std::abs(ab.sum()(0) / a.z() - ba.sum()(0) / b.z()) / (ab.sum()(0) / a.z()));
  }
  EXPECT_GT(asymmetry, 0.01);
}

// "Multiscatter GGX" compensates the specular alone (by K_s); the coat is compensated under either distribution.
TEST(CyclesPrincipled, DistributionCompensatesTheSpecularOnly) {
  CyclesPrincipledParameters p = everything(0.8);
  const CyclesPrincipled multiple(p);
  p.distribution = CyclesDistribution::kGgx;
  const CyclesPrincipled single(p);
  const Vec3 light = direction_from_angles(0.7, 0.0), view = direction_from_angles(0.3, 2.0);
  const CyclesPrincipledLobes m = multiple.lobes_cosine_weighted(light, view),
                              s = single.lobes_cosine_weighted(light, view);
  expect_close(m.coat, s.coat, 1e-15, "coat");
  const CyclesPrincipled::Layering l = multiple.layering(view.z());
  EXPECT_GT(l.specular_compensation.minCoeff(), 1.02);  // roughness 0.8 loses light to single scattering
  expect_close(m.specular, s.specular * l.specular_compensation, 1e-12, "specular");
  EXPECT_GT(single.layering(view.z()).coat_compensation, 1.0);
}

// A mirror (roughness below 0.0038) has no lobe to evaluate; it reflects its Fresnel into the mirror direction, which
// the albedo counts.
TEST(CyclesPrincipled, MirrorReflectsItsFresnelIntoTheAlbedoOnly) {
  CyclesPrincipledParameters p;
  p.roughness = 0.0;
  p.base_color = Rgb::Zero();
  const CyclesPrincipled mirror(p);
  EXPECT_EQ(mirror.lobes_cosine_weighted(direction_from_angles(0.5, 0.0), direction_from_angles(0.5, kPi)).specular(0),
            0.0);
  for (const double mu : {1.0, 0.6, 0.25}) {
    EXPECT_NEAR(mirror.albedo(mu)(0), fresnel_dielectric(mu, 1.5), 2e-4 * fresnel_dielectric(mu, 1.5)) << mu;
  }
}

TEST(CyclesPrincipled, BaseColourIsACheapCopyAndTheFitsLinearInput) {
  const CyclesPrincipled surface(everything(0.5));
  const Rgb color(0.1, 0.6, 0.9);
  CyclesPrincipledParameters p = everything(0.5);
  p.base_color = color;
  const CyclesPrincipled fresh(p), copied = surface.with_base_color(color);
  for (const double mu : {1.0, 0.5, 0.1}) {
    EXPECT_EQ((copied.albedo(mu) - fresh.albedo(mu)).abs().maxCoeff(), 0.0);
    EXPECT_EQ((surface.albedo_with_diffuse_color(mu, color) - fresh.albedo(mu)).abs().maxCoeff(), 0.0);
  }
  // With a Lambert base and subsurface the albedo is affine in the colour: A(d) = A(0) + w3 d.
  CyclesPrincipledParameters lambert = everything(0.5);
  lambert.diffuse_roughness = 0.0;
  const CyclesPrincipled flat(lambert);
  const double mu = 0.7;
  const Rgb zero = flat.albedo_with_diffuse_color(mu, Rgb::Zero());
  expect_close(flat.albedo_with_diffuse_color(mu, color) - zero, flat.layering(mu).under_specular * color, 1e-12,
               "affine");
  EXPECT_THROW(surface.with_base_color(Rgb(0.5, 1.5, 0.5)), ParameterError);
}

TEST(CyclesPrincipled, OpacityScalesTheReflection) {
  CyclesPrincipledParameters p = everything(0.6);
  const CyclesPrincipled opaque(p);
  p.alpha = 0.4;
  const CyclesPrincipled faded(p);
  const Vec3 light = direction_from_angles(0.3, 0.0), view = direction_from_angles(1.0, 1.0);
  expect_close(faded.brdf(light, view), 0.4 * opaque.brdf(light, view), 1e-12, "brdf");
  expect_close(faded.albedo(0.5), 0.4 * opaque.albedo(0.5), 1e-12, "albedo");
}

TEST(CyclesPrincipled, DefaultsAreBlenders) {
  const CyclesPrincipledParameters p;
  EXPECT_EQ(p.base_color(0), 0.8);
  EXPECT_EQ(p.roughness, 0.5);
  EXPECT_EQ(p.ior, 1.5);
  EXPECT_EQ(p.specular_ior_level, 0.5);
  EXPECT_EQ(p.coat_roughness, 0.03);
  EXPECT_EQ(p.coat_ior, 1.5);
  EXPECT_EQ(p.sheen_roughness, 0.5);
  EXPECT_EQ(p.subsurface_scale, 0.05);
  EXPECT_EQ(p.subsurface_ior, 1.4);
  EXPECT_EQ(p.thin_film_ior, 1.33);
  EXPECT_EQ(p.distribution, CyclesDistribution::kMultiscatterGgx);
  EXPECT_NO_THROW(CyclesPrincipled{p});
}

// One line naming the input and its range.
TEST(CyclesPrincipled, RangeErrorsNameTheInput) {
  const std::vector<std::pair<std::function<void(CyclesPrincipledParameters&)>, std::string>> cases = {
      {[](auto& p) { p.roughness = 1.5; }, "cycles_principled: roughness must be in [0, 1]"},
      {[](auto& p) { p.ior = 0.9; }, "cycles_principled: ior must be in [1, 1000]"},
      {[](auto& p) { p.coat_ior = 4.5; }, "cycles_principled: coat_ior must be in [1, 4]"},
      {[](auto& p) { p.base_color(2) = -0.1; }, "cycles_principled: base_color must be in [0, 1]"},
      {[](auto& p) { p.subsurface_ior = 1.0; }, "cycles_principled: subsurface_ior must be in [1.01, 3.8]"},
      {[](auto& p) { p.sheen_tint(0) = std::nan(""); }, "cycles_principled: sheen_tint must be in [0, 1]"},
      {[](auto& p) { p.metallic = 0.5; }, "cycles_principled: metallic must be 0: it is not built yet"},
      {[](auto& p) { p.transmission_weight = 1.0; },
       "cycles_principled: transmission_weight must be 0: it is not built yet"},
      {[](auto& p) { p.anisotropic = 0.2; }, "cycles_principled: anisotropic must be 0: it is not built yet"},
      {[](auto& p) { p.thin_film_thickness = 300.0; },
       "cycles_principled: thin_film_thickness must be 0: it is not built yet"},
  };
  for (const auto& [spoil, message] : cases) {
    CyclesPrincipledParameters p;
    spoil(p);
    try {
      CyclesPrincipled{p};
      ADD_FAILURE() << "no error for: " << message;
    } catch (const ParameterError& error) {
      EXPECT_EQ(std::string(error.what()), message);
    }
  }
}

}  // namespace
}  // namespace skinlayer
