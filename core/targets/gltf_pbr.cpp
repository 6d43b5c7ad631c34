// glTF 2.0's metallic-roughness BRDF with KHR_materials_ior, _specular, _sheen and _clearcoat.
#include "core/targets/gltf_pbr.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/conventions.h"
#include "core/material.h"
#include "core/series/quadrature.h"
#include "core/targets/charlie_sheen.h"
#include "core/targets/fresnel_terms.h"
#include "core/targets/ggx_lobe.h"
#include "core/targets/shader_inputs.h"

namespace skinlayer {
namespace {

constexpr double kAngleStep = 0.5 * kPi / (GltfPbr::kAngles - 1);
constexpr double kCoatF0 = 0.04;  // ((1.5 - 1) / (1.5 + 1))^2: the coat's index is 1.5 (KHR_materials_clearcoat)

void check(const GltfPbrParameters& p) {
  const ShaderInputs inputs("gltf");
  inputs.unit(p.base_color, "base_color");
  inputs.unit(p.metallic, "metallic");
  inputs.unit(p.roughness, "roughness");
  if (!(p.ior >= 1.0) || !std::isfinite(p.ior)) {
    throw ParameterError("gltf: ior must be >= 1 (KHR_materials_ior's 0, the specular-glossiness mode, is not taken)");
  }
  inputs.unit(p.specular, "specular");
  for (int c = 0; c < 3; ++c) inputs.non_negative(p.specular_color(c), "specular_color");
  inputs.unit(p.clearcoat, "clearcoat");
  inputs.unit(p.clearcoat_roughness, "clearcoat_roughness");
  inputs.unit(p.sheen_color, "sheen_color");
  inputs.unit(p.sheen_roughness, "sheen_roughness");
  inputs.not_built(p.transmission, "transmission");
  inputs.not_built(p.diffuse_transmission, "diffuse_transmission");
  inputs.not_built(p.thickness, "thickness");
}

const GltfPbrParameters& checked(const GltfPbrParameters& p) {
  check(p);
  return p;
}

double alpha_of(double roughness) {
  const double r = std::max(roughness, GltfPbr::kLeastRoughness);
  return r * r;
}

// D V cos(theta_i) = D G2 / (4 mu_o): the specular_brdf, cosine-weighted.
double specular_cosine_weighted(double alpha, const Vec3& omega_i, const Vec3& omega_o, const Vec3& h) {
  return ggx_distribution(h.z(), alpha) * ggx_height_correlated_masking(omega_i.z(), omega_o.z(), alpha) /
         (4.0 * omega_o.z());
}

// Catmull-Rom in the view's angle on the tables' angles.
template <typename Value, std::size_t N>
Value interpolate(const std::array<Value, N>& table, double mu) {
  const double position = std::acos(std::clamp(mu, 0.0, 1.0)) / kAngleStep;
  const int k = std::min(static_cast<int>(position), static_cast<int>(N) - 2);
  const double t = position - k;
  const auto at = [&](int j) { return table[static_cast<std::size_t>(std::clamp(j, 0, static_cast<int>(N) - 1))]; };
  const Value p0 = at(k - 1), p1 = at(k), p2 = at(k + 1), p3 = at(k + 2);
  return p1 + 0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + t * (3.0 * (p1 - p2) + p3 - p0)));
}

}  // namespace

GltfPbr::GltfPbr(const GltfPbrParameters& parameters)
    : parameters_(checked(parameters)),
      alpha_(alpha_of(parameters.roughness)),
      coat_alpha_(alpha_of(parameters.clearcoat_roughness)) {
  const double eta = parameters.ior, normal = normal_reflectance(eta);
  f0_ = (normal * parameters.specular_color).min(1.0) * parameters.specular;
  f90_ = parameters.specular;
  integrate_tables();
}

GltfPbr GltfPbr::with_base_color(const Rgb& base_color) const {
  GltfPbr surface = *this;
  surface.parameters_.base_color = base_color;
  check(surface.parameters_);
  return surface;
}

Rgb GltfPbr::dielectric_fresnel(double cos_vh) const { return f0_ + (f90_ - f0_) * schlick_weight(cos_vh); }

double GltfPbr::sheen_scaling(double mu_i, double mu_o) const {
  const double strength = parameters_.sheen_color.maxCoeff();
  if (strength == 0.0) return 1.0;
  const double r = parameters_.sheen_roughness;
  return 1.0 - strength * std::max(threejs_sheen_albedo(mu_i, r), threejs_sheen_albedo(mu_o, r));
}

double GltfPbr::coat_fresnel(double mu_o) const { return kCoatF0 + (1.0 - kCoatF0) * schlick_weight(mu_o); }

GltfPbrLobes GltfPbr::lobes_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const {
  const GltfPbrParameters& p = parameters_;
  GltfPbrLobes lobes;
  const double mu_i = omega_i.z(), mu_o = omega_o.z();
  if (!(mu_i > 0.0 && mu_o > 0.0)) return lobes;
  const Vec3 h = (omega_i + omega_o).normalized();
  const double cos_vh = omega_o.dot(h), w = schlick_weight(cos_vh);
  const double microfacet = specular_cosine_weighted(alpha_, omega_i, omega_o, h);
  const Rgb fresnel = dielectric_fresnel(cos_vh);
  const Rgb metal_fresnel = p.base_color + (1.0 - p.base_color) * w;
  const double scaling = sheen_scaling(mu_i, mu_o);
  const double under_coat = 1.0 - p.clearcoat * coat_fresnel(mu_o);
  const double base = under_coat * scaling;
  lobes.specular = base * ((1.0 - p.metallic) * fresnel + p.metallic * metal_fresnel) * microfacet;
  lobes.diffuse = base * (1.0 - p.metallic) * (1.0 - fresnel.maxCoeff()) * p.base_color * mu_i * kInvPi;
  if (p.sheen_color.maxCoeff() > 0.0) {
    lobes.sheen = under_coat * p.sheen_color * charlie_sheen_cosine_weighted(p.sheen_roughness, omega_i, omega_o);
  }
  if (p.clearcoat > 0.0) {
    lobes.clearcoat =
        Rgb::Constant(p.clearcoat * coat_fresnel(mu_o) * specular_cosine_weighted(coat_alpha_, omega_i, omega_o, h));
  }
  return lobes;
}

Rgb GltfPbr::brdf_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const {
  return lobes_cosine_weighted(omega_i, omega_o).sum();
}

void GltfPbr::integrate_tables() {
  const GltfPbrParameters& p = parameters_;
  const bool sheen = p.sheen_color.maxCoeff() > 0.0;
  // The smooth integrands (the diffuse weight and the sheen lobe) on a plain grid of the light's hemisphere; the
  // microfacet ones about the mirror direction (ggx_lobe.h).
  const QuadratureRule mu = gauss_legendre(48, 0.0, 1.0), phi = gauss_legendre(96, 0.0, 2.0 * kPi);
  for (int k = 0; k < kAngles; ++k) {
    const std::size_t at = static_cast<std::size_t>(k);
    const double theta = std::min(k * kAngleStep, degrees_to_radians(89.9));
    const Vec3 view(std::sin(theta), 0.0, std::cos(theta));
    const auto half = [&](const Vec3& light) { return (light + view).normalized(); };
    tables_.dielectric_specular[at] = microfacet_lobe_albedo(
        [&](const Vec3& light) -> Rgb {
          if (light.z() <= 0.0) return Rgb::Zero();
          const Vec3 h = half(light);
          return dielectric_fresnel(view.dot(h)) * specular_cosine_weighted(alpha_, light, view, h) *
                 sheen_scaling(light.z(), view.z());
        },
        view, alpha_, 24);
    const Rgb metal = microfacet_lobe_albedo(
        [&](const Vec3& light) -> Rgb {
          if (light.z() <= 0.0) return Rgb::Zero();
          const Vec3 h = half(light);
          const double value = specular_cosine_weighted(alpha_, light, view, h) * sheen_scaling(light.z(), view.z());
          return Rgb(value, value * schlick_weight(view.dot(h)), 0.0);
        },
        view, alpha_, 24);
    tables_.metal[at] = metal(0);
    tables_.metal_edge[at] = metal(1);
    if (p.clearcoat > 0.0) {
      tables_.coat[at] = microfacet_lobe_albedo(
          [&](const Vec3& light) -> Rgb {
            if (light.z() <= 0.0) return Rgb::Zero();
            return Rgb::Constant(specular_cosine_weighted(coat_alpha_, light, view, half(light)));
          },
          view, coat_alpha_, 24)(0);
    }
    double diffuse = 0.0, sheen_albedo = 0.0;
    for (std::size_t a = 0; a < mu.nodes.size(); ++a) {
      const double sine = std::sqrt(1.0 - mu.nodes[a] * mu.nodes[a]);
      for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
        const Vec3 light(sine * std::cos(phi.nodes[b]), sine * std::sin(phi.nodes[b]), mu.nodes[a]);
        const double weight = mu.weights[a] * phi.weights[b];
        diffuse += weight * (1.0 - dielectric_fresnel(view.dot(half(light))).maxCoeff()) *
                   sheen_scaling(light.z(), view.z()) * light.z() * kInvPi;
        if (sheen) sheen_albedo += weight * charlie_sheen_cosine_weighted(p.sheen_roughness, light, view);
      }
    }
    tables_.diffuse_weight[at] = diffuse;
    tables_.sheen[at] = sheen_albedo;
  }
}

Rgb GltfPbr::albedo_with_diffuse_color(double mu_o, const Rgb& base) const {
  const GltfPbrParameters& p = parameters_;
  const double metal = interpolate(tables_.metal, mu_o), edge = interpolate(tables_.metal_edge, mu_o);
  const Rgb dielectric =
      interpolate(tables_.dielectric_specular, mu_o) + base * interpolate(tables_.diffuse_weight, mu_o);
  const Rgb metallic = base * (metal - edge) + edge;
  const Rgb material =
      (1.0 - p.metallic) * dielectric + p.metallic * metallic + p.sheen_color * interpolate(tables_.sheen, mu_o);
  const double coat = p.clearcoat * coat_fresnel(mu_o);
  return (1.0 - coat) * material + coat * interpolate(tables_.coat, mu_o);
}

Rgb GltfPbr::albedo(double mu_o) const { return albedo_with_diffuse_color(mu_o, parameters_.base_color); }

}  // namespace skinlayer
