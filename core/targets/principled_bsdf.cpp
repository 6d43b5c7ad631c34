// docs/model.md §22.1: Blender 3.4's Principled BSDF (Cycles), its opaque lobes.
#include "core/targets/principled_bsdf.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/color/luminance.h"
#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/material.h"
#include "core/series/quadrature.h"
#include "core/targets/fresnel_terms.h"
#include "core/targets/ggx_lobe.h"
#include "core/targets/shader_inputs.h"

namespace skinlayer {
namespace {

void check(const PrincipledParameters& p) {
  const ShaderInputs inputs("principled");
  inputs.unit(p.base_color, "base_color");
  inputs.unit(p.metallic, "metallic");
  inputs.unit(p.specular, "specular");
  inputs.unit(p.specular_tint, "specular_tint");
  inputs.unit(p.roughness, "roughness");
  inputs.unit(p.sheen, "sheen");
  inputs.unit(p.sheen_tint, "sheen_tint");
  inputs.unit(p.clearcoat, "clearcoat");
  inputs.unit(p.clearcoat_roughness, "clearcoat_roughness");
  inputs.unit(p.subsurface, "subsurface");
  inputs.unit(p.subsurface_anisotropy, "subsurface_anisotropy");
  inputs.unit(p.subsurface_color, "subsurface_color");
  for (int c = 0; c < 3; ++c) inputs.non_negative(p.subsurface_radius(c), "subsurface_radius");
  inputs.unit(p.transmission, "transmission");
  inputs.unit(p.transmission_roughness, "transmission_roughness");
  inputs.positive(p.ior, "ior");
  inputs.not_built(p.anisotropic, "anisotropic");
}

// Berry's distribution (GTR1, Burley 2012 appendix B): (a^2 - 1) / (pi ln(a^2) (1 + (a^2 - 1) cos^2)); 1/pi at a >= 1.
double gtr1_distribution(double cos_m, double alpha) {
  if (alpha >= 1.0) return kInvPi;
  const double a2 = alpha * alpha;
  return (a2 - 1.0) / (kPi * std::log(a2) * (1.0 + (a2 - 1.0) * cos_m * cos_m));
}

// Cycles' Fresnel blend: c0 at normal incidence, rising to white as the dielectric Fresnel of eta does.
Rgb fresnel_blend(double cos_h, double eta, const Rgb& c0) {
  const double f0 = fresnel_dielectric(1.0, eta);
  const double t = (fresnel_dielectric(cos_h, eta) - f0) / (1.0 - f0);
  return c0 * (1.0 - t) + t;
}

// The colour with its luminance divided out: hue and saturation alone (white where it is black).
Rgb tint_of(const Rgb& color, const Rgb& luminance_weights) {
  const double luminance = (color * luminance_weights).sum();
  return luminance > 0.0 ? Rgb(color / luminance) : Rgb::Ones();
}

// Which lobes evaluate_lobes computes: the albedos integrate one family at a time.
enum LobeMask : unsigned { kDiffuseAndSheen = 1u, kSpecular = 2u, kGlass = 4u, kClearcoat = 8u, kAllLobes = 15u };

// principled_lobes_cosine_weighted for checked parameters, the lobes outside `mask` left 0.
PrincipledLobes evaluate_lobes(const PrincipledParameters& p, const Vec3& omega_i, const Vec3& omega_o, unsigned mask) {
  PrincipledLobes lobes;
  const double cos_i = omega_i.z(), cos_o = omega_o.z();
  if (!(cos_i > 0.0 && cos_o > 0.0)) return lobes;
  const Vec3 h = (omega_i + omega_o).normalized();
  const double cos_h = h.z(), cos_ih = omega_i.dot(h);
  const double glass_weight = p.transmission * (1.0 - p.metallic);
  const double diffuse_weight = (1.0 - p.metallic) * (1.0 - p.transmission), specular_weight = 1.0 - glass_weight;

  if (mask & kDiffuseAndSheen) {
    const double F_i = schlick_weight(cos_i), F_o = schlick_weight(cos_o);
    const double retro = p.roughness * (omega_i.dot(omega_o) + 1.0);
    const double diffuse =
        kInvPi * cos_i * ((1.0 - 0.5 * F_o) * (1.0 - 0.5 * F_i) + retro * (F_i + F_o + F_i * F_o * (retro - 1.0)));
    const Rgb diffuse_color = p.base_color * (1.0 - p.subsurface) + p.subsurface_color * p.subsurface;
    lobes.diffuse = diffuse_weight * diffuse_color * diffuse;

    if (p.sheen > 0.0) {
      const Rgb rec709(kRec709Luminance[0], kRec709Luminance[1], kRec709Luminance[2]);
      const Rgb sheen_color = (1.0 - p.sheen_tint) + tint_of(p.base_color, rec709) * p.sheen_tint;
      lobes.sheen = diffuse_weight * p.sheen * sheen_color * schlick_weight(cos_ih) * cos_i;
    }
  }

  if ((mask & kSpecular) && (p.specular > 0.0 || p.metallic > 0.0)) {
    const double alpha = p.roughness * p.roughness;
    const double eta = 2.0 / (1.0 - std::sqrt(0.08 * p.specular)) - 1.0;
    const Rgb tint = (1.0 - p.specular_tint) + tint_of(p.base_color, Rgb(0.3, 0.6, 0.1)) * p.specular_tint;
    const Rgb c0 = (p.specular * 0.08 * tint * (1.0 - p.metallic) + p.base_color * p.metallic).min(1.0).max(0.0);
    const double G = ggx_masking(cos_i, alpha) * ggx_masking(cos_o, alpha);
    lobes.specular =
        specular_weight * fresnel_blend(cos_ih, eta, c0) * G * ggx_distribution(cos_h, alpha) / (4.0 * cos_o);
  }

  if ((mask & kGlass) && glass_weight > 0.0) {
    const double alpha = p.roughness * p.roughness;
    const Rgb c0 = p.base_color * p.specular_tint + (1.0 - p.specular_tint);
    const double G = ggx_masking(cos_i, alpha) * ggx_masking(cos_o, alpha);
    lobes.glass = glass_weight * fresnel_dielectric(cos_o, p.ior) * fresnel_blend(cos_ih, p.ior, c0) * G *
                  ggx_distribution(cos_h, alpha) / (4.0 * cos_o);
  }

  if ((mask & kClearcoat) && p.clearcoat > 0.0) {
    const double alpha = p.clearcoat_roughness * p.clearcoat_roughness;
    const double G = ggx_masking(cos_i, 0.25) * ggx_masking(cos_o, 0.25);
    lobes.clearcoat = 0.25 * p.clearcoat * fresnel_blend(cos_ih, 1.5, Rgb::Constant(0.04)) * G *
                      gtr1_distribution(cos_h, alpha) / (4.0 * cos_o);
  }
  return lobes;
}

}  // namespace

PrincipledLobes principled_lobes_cosine_weighted(const PrincipledParameters& p, const Vec3& omega_i,
                                                 const Vec3& omega_o) {
  check(p);
  return evaluate_lobes(p, omega_i, omega_o, kAllLobes);
}

PrincipledLobes principled_lobe_albedos(const PrincipledParameters& p, const Vec3& omega_i, int polar) {
  check(p);  // once: each lobe below is evaluated for its own albedo alone
  PrincipledLobes albedos;
  // Diffuse and sheen: the view's hemisphere, on Gauss-Legendre cosines and azimuths.
  const QuadratureRule mu = gauss_legendre(polar, 0.0, 1.0), phi = gauss_legendre(2 * polar, 0.0, 2.0 * kPi);
  for (std::size_t a = 0; a < mu.nodes.size(); ++a) {
    const double sine = std::sqrt(std::max(0.0, 1.0 - mu.nodes[a] * mu.nodes[a]));
    for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
      const Vec3 omega_o(sine * std::cos(phi.nodes[b]), sine * std::sin(phi.nodes[b]), mu.nodes[a]);
      const PrincipledLobes lobes = evaluate_lobes(p, omega_o, omega_i, kDiffuseAndSheen);
      const double w = mu.weights[a] * phi.weights[b];
      albedos.diffuse += w * lobes.diffuse;
      albedos.sheen += w * lobes.sheen;
    }
  }
  // The microfacet lobes over their half vectors (ggx_lobe.h): GTR1's tail, 1 / tan^2, is heavier than GGX's, and
  // its nodes spread over sqrt(alpha), the clearcoat roughness.
  const double floor = 1e-3;  // the nodes' least width; the lobes themselves are exact at any roughness
  // (A lobe of weight 0 is skipped: the fit's colour solve asks for these albedos at every step.)
  if (p.specular > 0.0 || p.metallic > 0.0) {
    albedos.specular = microfacet_lobe_albedo(
        [&](const Vec3& omega_o) { return evaluate_lobes(p, omega_o, omega_i, kSpecular).specular; }, omega_i,
        std::max(floor, p.roughness * p.roughness), polar);
  }
  if (p.transmission > 0.0 && p.metallic < 1.0) {
    albedos.glass =
        microfacet_lobe_albedo([&](const Vec3& omega_o) { return evaluate_lobes(p, omega_o, omega_i, kGlass).glass; },
                               omega_i, std::max(floor, p.roughness * p.roughness), polar);
  }
  if (p.clearcoat > 0.0) {
    albedos.clearcoat = microfacet_lobe_albedo(
        [&](const Vec3& omega_o) { return evaluate_lobes(p, omega_o, omega_i, kClearcoat).clearcoat; }, omega_i,
        std::max(floor, p.clearcoat_roughness), polar);
  }
  return albedos;
}

Rgb principled_albedo(const PrincipledParameters& p, const Vec3& omega_i, int polar) {
  return principled_lobe_albedos(p, omega_i, polar).sum();
}

Rgb principled_brdf_cosine_weighted(const PrincipledParameters& p, const Vec3& omega_i, const Vec3& omega_o) {
  return principled_lobes_cosine_weighted(p, omega_i, omega_o).sum();
}

Rgb principled_btdf_cosine_weighted(const PrincipledParameters& p, const Vec3& omega_i, const Vec3& omega_o) {
  check(p);
  const double cos_i = omega_i.z(), cos_o = omega_o.z();
  const double glass_weight = p.transmission * (1.0 - p.metallic);
  if (!(cos_i < 0.0 && cos_o > 0.0) || glass_weight == 0.0) return Rgb::Zero();
  const double r = 1.0 - (1.0 - p.roughness) * (1.0 - p.transmission_roughness), alpha = r * r;
  const Vec3 ht = -(p.ior * omega_i + omega_o);
  const Vec3 h = ht.normalized();
  const double cos_hi = h.dot(omega_i), cos_ho = h.dot(omega_o);
  const double G = ggx_masking(std::abs(cos_i), alpha) * ggx_masking(cos_o, alpha);
  const double btdf = G * std::abs(cos_hi * cos_ho) * ggx_distribution(std::abs(h.z()), alpha) * p.ior * p.ior /
                      (cos_o * ht.squaredNorm());
  return glass_weight * std::max(1e-4, 1.0 - fresnel_dielectric(cos_o, p.ior)) * p.base_color * btdf;
}

Rgb principled_brdf(const PrincipledParameters& p, const Vec3& omega_i, const Vec3& omega_o) {
  const Rgb weighted = principled_brdf_cosine_weighted(p, omega_i, omega_o);
  return omega_i.z() > 0.0 ? Rgb(weighted / omega_i.z()) : Rgb::Zero();
}

}  // namespace skinlayer
