// docs/model.md §22.3: OpenPBR Surface's opaque dielectric lobes, layered by albedo scaling as MaterialX's graph
// layers them.
#include "core/targets/openpbr_surface.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/conventions.h"
#include "core/material.h"
#include "core/targets/eon_diffuse.h"
#include "core/targets/fresnel_terms.h"
#include "core/targets/shader_inputs.h"
#include "core/targets/zeltner_fuzz.h"

namespace skinlayer {
namespace {

double lerp(double a, double b, double t) { return a + (b - a) * t; }

void check(const OpenPbrParameters& p) {
  const ShaderInputs inputs("openpbr");
  inputs.unit(p.base_weight, "base_weight");
  inputs.unit(p.base_color, "base_color");
  inputs.unit(p.base_diffuse_roughness, "base_diffuse_roughness");
  inputs.non_negative(p.specular_weight, "specular_weight");
  inputs.unit(p.specular_color, "specular_color");
  inputs.unit(p.specular_roughness, "specular_roughness");
  inputs.positive(p.specular_ior, "specular_ior");
  inputs.unit(p.subsurface_weight, "subsurface_weight");
  inputs.unit(p.subsurface_color, "subsurface_color");
  inputs.non_negative(p.subsurface_radius, "subsurface_radius");
  inputs.unit(p.subsurface_radius_scale, "subsurface_radius_scale");
  inputs.in_range(p.subsurface_scatter_anisotropy, -1.0, 1.0, "subsurface_scatter_anisotropy");
  inputs.unit(p.fuzz_weight, "fuzz_weight");
  inputs.unit(p.fuzz_color, "fuzz_color");
  inputs.unit(p.fuzz_roughness, "fuzz_roughness");
  inputs.unit(p.coat_weight, "coat_weight");
  inputs.unit(p.coat_color, "coat_color");
  inputs.unit(p.coat_roughness, "coat_roughness");
  inputs.positive(p.coat_ior, "coat_ior");
  inputs.unit(p.coat_darkening, "coat_darkening");
  inputs.not_built(p.base_metalness, "base_metalness");
  inputs.not_built(p.transmission_weight, "transmission_weight");
}

// eta_s: the base's index over what lies above it, the coat where there is one; inverted where the coat is denser
// (the specification's guard against total internal reflection in the coat, after Kutz 2021).
double specular_relative_index(const OpenPbrParameters& p) {
  const double ratio = p.specular_ior / p.coat_ior;
  return lerp(p.specular_ior, ratio >= 1.0 ? ratio : 1.0 / ratio, p.coat_weight);
}

// eta': the index whose normal reflectance is specular_weight times eta_s's (held below 0.99999, as the graph does).
double modulated_index(const OpenPbrParameters& p) {
  const double eta = specular_relative_index(p);
  const double root = std::sqrt(std::clamp(p.specular_weight * normal_reflectance(eta), 0.0, 0.99999));
  const double e = eta >= 1.0 ? root : -root;
  return (1.0 + e) / (1.0 - e);
}

double specular_alpha(const OpenPbrParameters& p) {
  const double r = p.specular_roughness, rc = p.coat_roughness;
  const double roughened = std::pow(std::min(1.0, r * r * r * r + 2.0 * rc * rc * rc * rc), 0.25);
  const double r_coated = lerp(r, roughened, p.coat_weight);
  return r_coated * r_coated;
}

const OpenPbrParameters& checked(const OpenPbrParameters& p) {
  check(p);
  return p;
}

}  // namespace

OpenPbrSurface::OpenPbrSurface(const OpenPbrParameters& parameters)
    : parameters_(checked(parameters)),
      specular_(modulated_index(parameters), specular_alpha(parameters)),
      coat_(parameters.coat_ior, parameters.coat_roughness * parameters.coat_roughness) {
  // The graph's Kcoat: the light the coat sends back down, from its normal reflectance alone.
  const double n = parameters.coat_ior;
  coat_internal_ = 1.0 - (1.0 - normal_reflectance(n)) / (n * n);
}

OpenPbrSurface OpenPbrSurface::with_diffuse_colors(const Rgb& base_color, const Rgb& subsurface_color) const {
  OpenPbrSurface surface = *this;
  surface.parameters_.base_color = base_color;
  surface.parameters_.subsurface_color = subsurface_color;
  check(surface.parameters_);
  return surface;
}

Rgb OpenPbrSurface::darkening(const Rgb& base_albedo) const {
  const OpenPbrParameters& p = parameters_;
  const double amount = p.coat_weight * p.coat_darkening;
  if (amount == 0.0) return Rgb::Ones();
  const double K = coat_internal_;
  const Rgb delta = (1.0 - K) / (1.0 - base_albedo * K);
  return 1.0 + (delta - 1.0) * amount;
}

Rgb OpenPbrSurface::base_albedo_color() const {
  const OpenPbrParameters& p = parameters_;
  return p.base_color * (1.0 - p.subsurface_weight) + p.subsurface_color * p.subsurface_weight;
}

OpenPbrSurface::LayerShares OpenPbrSurface::layer_shares(double mu_o, const Rgb& base_albedo) const {
  const OpenPbrParameters& p = parameters_;
  LayerShares shares;
  if (p.fuzz_weight > 0.0) {
    shares.fuzz = p.fuzz_weight * zeltner_fuzz_albedo(mu_o, p.fuzz_roughness);
    shares.outer = 1.0 - shares.fuzz;
  }
  if (p.coat_weight > 0.0) {
    shares.coat = p.coat_weight * coat_.albedo(mu_o);
    const Rgb attenuation = 1.0 + (p.coat_color - 1.0) * p.coat_weight;
    shares.under_coat = (1.0 - p.coat_weight * coat_.layer_albedo(mu_o)) * attenuation * darkening(base_albedo);
  }
  return shares;
}

OpenPbrLobes OpenPbrSurface::lobes_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const {
  const OpenPbrParameters& p = parameters_;
  OpenPbrLobes lobes;
  const double mu_o = omega_o.z();
  if (!(omega_i.z() > 0.0 && mu_o > 0.0)) return lobes;
  const LayerShares shares = layer_shares(mu_o, base_albedo_color());
  if (p.fuzz_weight > 0.0) {
    lobes.fuzz = p.fuzz_weight * p.fuzz_color * zeltner_fuzz_cosine_weighted(p.fuzz_roughness, omega_i, omega_o);
  }
  if (p.coat_weight > 0.0) {
    lobes.coat = Rgb::Constant(shares.outer * p.coat_weight * coat_.cosine_weighted(omega_i, omega_o));
  }
  const Rgb base = shares.outer * shares.under_coat;
  lobes.specular = base * p.specular_color * specular_.cosine_weighted(omega_i, omega_o);
  Rgb diffuse = p.base_weight * eon_diffuse_cosine_weighted(p.base_color, p.base_diffuse_roughness, omega_i, omega_o);
  if (p.subsurface_weight > 0.0) {
    // Lambert's lobe of albedo subsurface_color.
    diffuse = diffuse * (1.0 - p.subsurface_weight) + p.subsurface_weight * p.subsurface_color * omega_i.z() / kPi;
  }
  lobes.diffuse = base * (1.0 - specular_.layer_albedo(mu_o)) * diffuse;
  return lobes;
}

Rgb OpenPbrSurface::brdf_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const {
  return lobes_cosine_weighted(omega_i, omega_o).sum();
}

Rgb OpenPbrSurface::assembled_albedo(double mu_o, const Rgb& base_albedo, const Rgb& diffuse_albedo) const {
  const LayerShares shares = layer_shares(mu_o, base_albedo);
  const Rgb base =
      parameters_.specular_color * specular_.albedo(mu_o) + (1.0 - specular_.layer_albedo(mu_o)) * diffuse_albedo;
  return shares.fuzz * parameters_.fuzz_color + shares.outer * (shares.coat + shares.under_coat * base);
}

Rgb OpenPbrSurface::albedo_with_diffuse_color(double mu_o, const Rgb& diffuse) const {
  const OpenPbrParameters& p = parameters_;
  const double S = p.subsurface_weight;
  return assembled_albedo(
      mu_o, diffuse,
      p.base_weight * eon_diffuse_albedo(diffuse, p.base_diffuse_roughness, mu_o) * (1.0 - S) + diffuse * S);
}

Rgb OpenPbrSurface::albedo(double mu_o) const {
  const OpenPbrParameters& p = parameters_;
  const double S = p.subsurface_weight;
  return assembled_albedo(mu_o, base_albedo_color(),
                          p.base_weight * eon_diffuse_albedo(p.base_color, p.base_diffuse_roughness, mu_o) * (1.0 - S) +
                              p.subsurface_color * S);
}

}  // namespace skinlayer
