// docs/model.md §22.1.1: Blender 4.x-5.x's Principled BSDF as Cycles evaluates it, its opaque dielectric lobes.
#include "core/targets/cycles_principled.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/material.h"
#include "core/targets/cycles_diffuse.h"
#include "core/targets/cycles_sheen.h"
#include "core/targets/fresnel_terms.h"
#include "core/targets/ggx_energy_compensation.h"
#include "core/targets/ggx_fresnel_estimate.h"
#include "core/targets/ggx_lobe.h"
#include "core/targets/half_vector_quadrature.h"
#include "core/targets/shader_inputs.h"

namespace skinlayer {
namespace {

constexpr double kWeightCutoff = 1e-5;  // CLOSURE_WEIGHT_CUTOFF
constexpr int kAlbedoPolar = 32;        // quadrature of the lobes' albedo tables (half_vector_quadrature.h)
constexpr double kAngleStep = 0.5 * kPi / (CyclesPrincipled::kAngles - 1);

void check(const CyclesPrincipledParameters& p) {
  const ShaderInputs inputs("cycles_principled");
  inputs.unit(p.base_color, "base_color");
  inputs.unit(p.metallic, "metallic");
  inputs.unit(p.roughness, "roughness");
  inputs.in_range(p.ior, 1.0, 1000.0, "ior");
  inputs.unit(p.alpha, "alpha");
  inputs.unit(p.diffuse_roughness, "diffuse_roughness");
  inputs.unit(p.subsurface_weight, "subsurface_weight");
  for (int c = 0; c < 3; ++c) inputs.in_range(p.subsurface_radius(c), 0.0, 100.0, "subsurface_radius");
  inputs.in_range(p.subsurface_scale, 0.0, 10.0, "subsurface_scale");
  inputs.in_range(p.subsurface_ior, 1.01, 3.8, "subsurface_ior");
  inputs.unit(p.subsurface_anisotropy, "subsurface_anisotropy");
  inputs.unit(p.specular_ior_level, "specular_ior_level");
  inputs.unit(p.specular_tint, "specular_tint");
  inputs.unit(p.anisotropic, "anisotropic");
  inputs.unit(p.anisotropic_rotation, "anisotropic_rotation");
  inputs.unit(p.transmission_weight, "transmission_weight");
  inputs.unit(p.coat_weight, "coat_weight");
  inputs.unit(p.coat_roughness, "coat_roughness");
  inputs.in_range(p.coat_ior, 1.0, 4.0, "coat_ior");
  inputs.unit(p.coat_tint, "coat_tint");
  inputs.unit(p.sheen_weight, "sheen_weight");
  inputs.unit(p.sheen_roughness, "sheen_roughness");
  inputs.unit(p.sheen_tint, "sheen_tint");
  inputs.unit(p.emission_color, "emission_color");
  inputs.in_range(p.emission_strength, 0.0, 1e6, "emission_strength");
  inputs.in_range(p.thin_film_thickness, 0.0, 1e5, "thin_film_thickness");
  inputs.in_range(p.thin_film_ior, 1.0, 1000.0, "thin_film_ior");
  inputs.not_built(p.metallic, "metallic");
  inputs.not_built(p.transmission_weight, "transmission_weight");
  inputs.not_built(p.anisotropic, "anisotropic");
  inputs.not_built(p.thin_film_thickness, "thin_film_thickness");
}

const CyclesPrincipledParameters& checked(const CyclesPrincipledParameters& p) {
  check(p);
  return p;
}

// bsdf_alloc makes a closure only where the mean of its weight reaches the cutoff.
bool made(const Rgb& weight) { return std::abs(weight.mean()) >= kWeightCutoff; }

// closure_layering_weight: the weight left under a layer of albedo estimate A, w saturate(1 - max_c(A_c / w_c)), a
// channel of weight 0 counting 0 (safe_divide_color).
Rgb layered(const Rgb& weight, const Rgb& albedo) {
  double most = 0.0;
  for (int c = 0; c < 3; ++c) most = std::max(most, weight(c) != 0.0 ? albedo(c) / weight(c) : 0.0);
  return weight * std::clamp(1.0 - most, 0.0, 1.0);
}

// GGX's single scattering for a white Fresnel, D(h) G2 / (4 mu_o) (f cos_i), and the cosine between light and half
// vector for the Fresnel; 0 below either horizon.
struct Microfacet {
  double lobe = 0.0, cos_ih = 1.0;
};
Microfacet single_scattering(double alpha, const Vec3& omega_i, const Vec3& omega_o) {
  const double mu_i = omega_i.z(), mu_o = omega_o.z();
  if (!(mu_i > 0.0 && mu_o > 0.0) || cycles_ggx_is_mirror(alpha)) return {};
  const Vec3 h = (omega_i + omega_o).normalized();
  return {ggx_distribution(h.z(), alpha) * ggx_height_correlated_masking(mu_i, mu_o, alpha) / (4.0 * mu_o),
          omega_i.dot(h)};
}

// The specular's single-scattering albedos for a white Fresnel and for the blend s(c), on the same nodes; a mirror
// reflects 1 and s(mu_o).
Eigen::Array2d specular_albedos(const HalfVectorQuadrature& quadrature, double alpha, double mu, double eta) {
  if (cycles_ggx_is_mirror(alpha)) return {1.0, cycles_fresnel_blend(mu, eta)};
  const Vec3 view(std::sqrt(1.0 - mu * mu), 0.0, mu);
  return quadrature.integrate(mu, std::max(alpha, 1e-3), [&](const Vec3& light) {
    const Vec3 h = (light + view).normalized();
    const double lobe =
        ggx_distribution(h.z(), alpha) * ggx_height_correlated_masking(light.z(), mu, alpha) / (4.0 * mu);
    return Eigen::Array2d(lobe, lobe * cycles_fresnel_blend(light.dot(h), eta));
  });
}

// The view cosine of angle node k; the last is held at Cycles' least cosine, 1e-4, where the albedos' limit is.
double angle_cosine(int k) { return std::max(std::cos(k * kAngleStep), 1e-4); }

// Catmull-Rom in the view angle through the table.
double interpolate(const std::array<double, CyclesPrincipled::kAngles>& table, double mu) {
  const double position = std::acos(std::clamp(mu, 0.0, 1.0)) / kAngleStep;
  const int k = std::min(static_cast<int>(position), CyclesPrincipled::kAngles - 2);
  const double t = position - k;
  const auto at = [&](int j) {
    return table[static_cast<std::size_t>(std::clamp(j, 0, CyclesPrincipled::kAngles - 1))];
  };
  const double p0 = at(k - 1), p1 = at(k), p2 = at(k + 1), p3 = at(k + 2);
  return p1 + 0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + t * (3.0 * (p1 - p2) + p3 - p0)));
}

}  // namespace

CyclesPrincipled::CyclesPrincipled(const CyclesPrincipledParameters& parameters) : parameters_(checked(parameters)) {
  const CyclesPrincipledParameters& p = parameters_;
  // Specular IOR Level: scale F0(eta) by 2 L and take the index of that reflectance.
  double f0 = normal_reflectance(p.ior);
  specular_index_ = p.ior;
  if (p.specular_ior_level != 0.5) {
    f0 *= 2.0 * p.specular_ior_level;
    specular_index_ = cycles_ior_from_f0(f0);
  }
  specular_f0_ = (f0 * p.specular_tint).min(1.0).max(0.0);
  const double index_f0 = normal_reflectance(specular_index_);
  const double average_blend =
      std::clamp((cycles_dielectric_average_fresnel(specular_index_) - index_f0) / (1.0 - index_f0), 0.0, 1.0);
  specular_average_fresnel_ = specular_f0_ * (1.0 - average_blend) + average_blend;
  coat_average_fresnel_ = cycles_dielectric_average_fresnel(p.coat_ior);

  const HalfVectorQuadrature quadrature(kAlbedoPolar);
  const double alpha = p.roughness * p.roughness, coat_alpha = p.coat_roughness * p.coat_roughness;
  for (int k = 0; k < kAngles; ++k) {
    const double mu = angle_cosine(k);
    const auto at = static_cast<std::size_t>(k);
    if (p.coat_weight > kWeightCutoff) {
      coat_albedo_[at] = ggx_reflection_albedo(quadrature, coat_alpha, mu,
                                               [&](double c) { return fresnel_dielectric(c, p.coat_ior); });
    }
    if (specular_index_ != 1.0) {
      const Eigen::Array2d both = specular_albedos(quadrature, alpha, mu, specular_index_);
      specular_white_[at] = both(0);
      specular_blend_[at] = both(1);
    }
  }
}

CyclesPrincipled CyclesPrincipled::with_base_color(const Rgb& base_color) const {
  ShaderInputs("cycles_principled").unit(base_color, "base_color");
  CyclesPrincipled surface = *this;
  surface.parameters_.base_color = base_color;
  return surface;
}

CyclesPrincipled::Layering CyclesPrincipled::layering(double mu_o) const {
  const CyclesPrincipledParameters& p = parameters_;
  Layering l;
  Rgb w = Rgb::Constant(p.alpha);
  if (p.sheen_weight > kWeightCutoff && made(p.sheen_weight * p.sheen_tint * w)) {
    l.sheen = true;
    w = layered(w, p.sheen_weight * p.sheen_tint * w * cycles_sheen_albedo(mu_o, p.sheen_roughness));
  }
  l.under_sheen = w;
  if (p.coat_weight > kWeightCutoff) {
    if (made(p.coat_weight * w)) {
      l.coat = true;
      double estimate = fresnel_dielectric(mu_o, p.coat_ior);  // Blender 4.0-4.3: a smooth surface's
      if (p.release == CyclesRelease::kBlender4_4On) {
        l.coat_compensation = cycles_ggx_energy_factor(p.coat_roughness, mu_o, Rgb::Constant(coat_average_fresnel_))(0);
        estimate = l.coat_compensation * cycles_ggx_albedo(p.coat_roughness, mu_o) *
                   cycles_dielectric_fresnel_estimate(p.coat_roughness, mu_o, p.coat_ior);
      }
      w = layered(w, p.coat_weight * w * estimate);
    }
    if (!(p.coat_tint == 1.0).all()) {
      // Beer's law along the refracted view, the tint being the transmittance at normal incidence.
      const double cos_t = std::sqrt(1.0 - (1.0 - mu_o * mu_o) / (p.coat_ior * p.coat_ior));
      w *= 1.0 + (p.coat_tint.pow(1.0 / cos_t) - 1.0) * p.coat_weight;
    }
  }
  l.under_coat = w;
  if (specular_index_ != 1.0 && made(w)) {
    l.specular = true;
    Rgb darkening = Rgb::Ones();
    if (p.distribution == CyclesDistribution::kMultiscatterGgx) {
      l.specular_compensation = cycles_ggx_energy_factor(p.roughness, mu_o, specular_average_fresnel_);
      darkening = l.specular_compensation * cycles_ggx_albedo(p.roughness, mu_o);
    }
    w = layered(w,
                w * darkening * cycles_principled_fresnel_estimate(p.roughness, mu_o, specular_index_, specular_f0_));
  }
  l.under_specular = w;
  return l;
}

CyclesPrincipledLobes CyclesPrincipled::lobes_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const {
  const CyclesPrincipledParameters& p = parameters_;
  CyclesPrincipledLobes lobes;
  const double mu_o = omega_o.z();
  if (!(omega_i.z() > 0.0 && mu_o > 0.0)) return lobes;
  const Layering l = layering(mu_o);
  if (l.sheen) {
    lobes.sheen =
        p.sheen_weight * p.sheen_tint * p.alpha * cycles_sheen_cosine_weighted(p.sheen_roughness, omega_i, omega_o);
  }
  if (l.coat) {
    const Microfacet m = single_scattering(p.coat_roughness * p.coat_roughness, omega_i, omega_o);
    lobes.coat =
        p.coat_weight * l.under_sheen * l.coat_compensation * fresnel_dielectric(m.cos_ih, p.coat_ior) * m.lobe;
  }
  if (l.specular) {
    const Microfacet m = single_scattering(p.roughness * p.roughness, omega_i, omega_o);
    const double s = cycles_fresnel_blend(m.cos_ih, specular_index_);
    lobes.specular = l.under_coat * l.specular_compensation * (specular_f0_ * (1.0 - s) + s) * m.lobe;
  }
  const Rgb diffuse_weight = p.base_color * (1.0 - p.subsurface_weight) * l.under_specular;
  if (made(diffuse_weight)) {
    lobes.diffuse = (1.0 - p.subsurface_weight) * l.under_specular *
                    cycles_diffuse_cosine_weighted(p.base_color, p.diffuse_roughness, omega_i, omega_o);
  }
  const Rgb subsurface_weight = p.base_color * p.subsurface_weight * l.under_specular;
  if (p.subsurface_weight > kWeightCutoff && made(subsurface_weight)) {
    lobes.subsurface = subsurface_weight * omega_i.z() * kInvPi;
  }
  return lobes;
}

Rgb CyclesPrincipled::brdf_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const {
  return lobes_cosine_weighted(omega_i, omega_o).sum();
}

Rgb CyclesPrincipled::brdf(const Vec3& omega_i, const Vec3& omega_o) const {
  return omega_i.z() > 0.0 ? Rgb(brdf_cosine_weighted(omega_i, omega_o) / omega_i.z()) : Rgb::Zero();
}

CyclesPrincipledLobes CyclesPrincipled::lobe_albedos(double mu_o) const {
  const CyclesPrincipledParameters& p = parameters_;
  CyclesPrincipledLobes albedos;
  if (!(mu_o > 0.0)) return albedos;
  const Layering l = layering(mu_o);
  if (l.sheen) albedos.sheen = p.sheen_weight * p.sheen_tint * p.alpha * cycles_sheen_albedo(mu_o, p.sheen_roughness);
  if (l.coat) albedos.coat = p.coat_weight * l.under_sheen * l.coat_compensation * interpolate(coat_albedo_, mu_o);
  if (l.specular) {
    const double white = interpolate(specular_white_, mu_o), blend = interpolate(specular_blend_, mu_o);
    albedos.specular = l.under_coat * l.specular_compensation * (specular_f0_ * white + (1.0 - specular_f0_) * blend);
  }
  const Rgb diffuse_weight = p.base_color * (1.0 - p.subsurface_weight) * l.under_specular;
  if (made(diffuse_weight)) {
    albedos.diffuse =
        (1.0 - p.subsurface_weight) * l.under_specular * cycles_diffuse_albedo(p.base_color, p.diffuse_roughness, mu_o);
  }
  const Rgb subsurface_weight = p.base_color * p.subsurface_weight * l.under_specular;
  if (p.subsurface_weight > kWeightCutoff && made(subsurface_weight)) albedos.subsurface = subsurface_weight;
  return albedos;
}

Rgb CyclesPrincipled::albedo(double mu_o) const { return lobe_albedos(mu_o).sum(); }

Rgb CyclesPrincipled::albedo_with_diffuse_color(double mu_o, const Rgb& diffuse) const {
  return with_base_color(diffuse).albedo(mu_o);
}

}  // namespace skinlayer
