// OpenPBR Surface 1.1 (Academy Software Foundation), the parts that shape an opaque dielectric's BRDF (docs/model.md
// §22.3): the target whose parameters `skinlayer fit --target openpbr` chooses. Written from MaterialX's node graph
// for the node (libraries/bxdf/open_pbr_surface.mtlx, 1.39.5) and the GLSL of the nodes it uses, term by term: what
// renderers that read the .mtlx run. Its layer node scales by albedo at the view direction omega_o (so the BRDF is
// not reciprocal): a lobe of albedo-to-pass-on E^ lets through 1 - w E^ of what lies under it. The lobes:
//   fuzz      Zeltner 2022's LTC sheen (zeltner_fuzz.h), weight F, colour C_f, E^ = its albedo E_fuzz;
//   coat      a GGX dielectric of index coat_ior (ggx_dielectric_reflection.h), weight C, roughness r_c;
//   specular  a GGX dielectric of index eta', tinted by specular_color, roughness r_s' = lerp(r_s, min(1, r_s^4 +
//             2 r_c^4)^(1/4), C) (the coat roughens it); eta_s = lerp(n_b, max(n_b/n_c, n_c/n_b), C) and
//             specular_weight xi moves it to eta' = (1 + e) / (1 - e), e = sgn(eta_s - 1) sqrt(min(xi F0(eta_s),
//             0.99999));
//   diffuse   base_weight times EON (eon_diffuse.h) of colour base_color and roughness base_diffuse_roughness (the
//             weight multiplies the lobe, the colour enters EON's multiple scattering), mixed by subsurface_weight S
//             with the subsurface lobe, which at the BRDF's scale (a flat surface) is Lambert's of albedo
//             subsurface_color: MaterialX's GLSL subsurface_bsdf under its environment, and within 0.5% of it under
//             a light (its curvature-driven profile on a plane).
// For the coat and the specular E^ is MaterialX's fit with Schlick's Fresnel (GgxDielectricReflection::
// layer_albedo), not the lobe's own albedo E (GgxDielectricReflection::albedo), so a white furnace reflects 1 + (E -
// E^) terms: within about 1% of 1. Assembled, with the albedos at the view mu_o:
//   f = F C_f f_fuzz + (1 - F E_fuzz) [C f_coat + (1 - C E^_coat) lerp(1, T_c, C) lerp(1, Delta, C delta) f_base],
//   f_base = specular_color f_spec + (1 - E^_spec) lerp(base_weight f_diffuse, f_subsurface, S),
// where Delta = (1 - K) / (1 - E_b K) darkens the base under the coat (light the coat's underside sends back down):
// E_b = lerp(base_color, subsurface_color, S), K = 1 - (1 - F0(n_c)) / n_c^2 (the graph's "Kcoat", one number),
// delta = coat_darkening. Where the specification differs: it darkens by K = lerp(F(mu_o, n_c), 1 - (1 -
// E_F(n_c))/n_c^2, r_b) with the hemispherical Fresnel albedo E_F and a base roughness r_b, E_b with base_weight in
// it; it passes lerp(1, T_c (1 - E_coat), C) under the coat (the same at C = 0 and 1), and layers by the lobes' own
// albedos (energy conserved exactly). The graph is what renderers run, so it is what this class computes.
// Not here: metal, transmission, thin film, thin walls, anisotropy and emission (metalness and transmission must be
// 0; the others are not parameters).
#pragma once

#include <Eigen/Core>

#include "core/interfaces/microfacet.h"
#include "core/targets/ggx_dielectric_reflection.h"

namespace skinlayer {

using Rgb = Eigen::Array3d;

// The node's inputs that enter the BRDF above, with OpenPBR 1.1's defaults (its MaterialX node definition).
struct OpenPbrParameters {
  double base_weight = 1.0;
  Rgb base_color = Rgb::Constant(0.8);
  double base_diffuse_roughness = 0.0;
  double base_metalness = 0.0;  // must be 0 for now
  double specular_weight = 1.0;
  Rgb specular_color = Rgb::Ones();
  double specular_roughness = 0.3;
  double specular_ior = 1.5;
  double transmission_weight = 0.0;  // must be 0 for now
  double subsurface_weight = 0.0;
  Rgb subsurface_color = Rgb::Constant(0.8);
  double subsurface_radius = 1.0;                     // millimetres as skinlayer exports it; no part of the BRDF
  Rgb subsurface_radius_scale = Rgb(1.0, 0.5, 0.25);  // no part of the BRDF
  double subsurface_scatter_anisotropy = 0.0;         // no part of the BRDF
  double fuzz_weight = 0.0;
  Rgb fuzz_color = Rgb::Ones();
  double fuzz_roughness = 0.5;
  double coat_weight = 0.0;
  Rgb coat_color = Rgb::Ones();
  double coat_roughness = 0.0;
  double coat_ior = 1.6;
  double coat_darkening = 1.0;
};

// The lobes, each already weighted as in the sum above; f cos(theta_i) per channel.
struct OpenPbrLobes {
  Rgb fuzz = Rgb::Zero(), coat = Rgb::Zero(), specular = Rgb::Zero(), diffuse = Rgb::Zero();
  Rgb sum() const { return fuzz + coat + specular + diffuse; }
};

class OpenPbrSurface {
 public:
  // Throws ParameterError naming the input that is out of its range (the node definition's: weights, colours and
  // roughnesses in [0, 1], specular_weight >= 0, indices > 0, anisotropy in [-1, 1]) or not built (metalness,
  // transmission).
  explicit OpenPbrSurface(const OpenPbrParameters& parameters);

  const OpenPbrParameters& parameters() const { return parameters_; }

  // The same surface with base_color and subsurface_color replaced (each in [0, 1]): no lobe's table depends on them,
  // so this costs a copy, not the tables.
  OpenPbrSurface with_diffuse_colors(const Rgb& base_color, const Rgb& subsurface_color) const;

  OpenPbrLobes lobes_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const;
  Rgb brdf_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const;

  // The light the surface sends toward omega_o under a white sky, int f cos(theta_i) d omega_i: in closed form from
  // the lobes' albedos at the view, as albedo scaling makes it (each lobe's own albedo where it reflects, E^ where it
  // passes light on).
  Rgb albedo(double mu_o) const;

  // The same with base_color and subsurface_color both replaced by `diffuse`: what a fit needs to find the colour
  // that gives an albedo.
  Rgb albedo_with_diffuse_color(double mu_o, const Rgb& diffuse) const;

 private:
  // The layers' shares of the light toward the view: what the fuzz reflects (F E_fuzz) and passes on (outer =
  // 1 - F E_fuzz), what the coat reflects (C E_coat), and the factor on all under the coat, (1 - C E^_coat)
  // lerp(1, T_c, C) times the darkening for a base of albedo E_b.
  struct LayerShares {
    double fuzz = 0.0, outer = 1.0, coat = 0.0;
    Rgb under_coat = Rgb::Ones();
  };
  LayerShares layer_shares(double mu_o, const Rgb& base_albedo) const;
  Rgb base_albedo_color() const;  // E_b = lerp(base_color, subsurface_color, S)
  Rgb darkening(const Rgb& base_albedo) const;
  // The albedo at the view with E_b = base_albedo and the diffuse lobes' albedo (mixed) given.
  Rgb assembled_albedo(double mu_o, const Rgb& base_albedo, const Rgb& diffuse_albedo) const;

  OpenPbrParameters parameters_;
  GgxDielectricReflection specular_, coat_;
  double coat_internal_ = 0.0;  // K = 1 - (1 - F0(n_c)) / n_c^2
};

}  // namespace skinlayer
