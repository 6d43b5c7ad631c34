// The Principled BSDF of Blender 4.x and 5.x as Cycles evaluates it, for the opaque dielectric that a fit uses
// (docs/model.md §22.1.1). Written from the Principled closure's setup in svm/closure.h (svm_node_closure_bsdf,
// CLOSURE_BSDF_PRINCIPLED_ID) and the closures it makes (closure/bsdf_sheen.h, bsdf_microfacet.h, bsdf_oren_nayar.h,
// bsdf_diffuse.h, bssrdf.h, bsdf_util.h), as stored in Blender's repository for 4.2 and for 4.4+/5.x; the node's
// sockets and defaults from nodes/shader/nodes/node_shader_bsdf_principled.cc.
//
// Cycles layers by albedo scaling at the view omega_o: each layer, top down, is a closure whose weight is what the
// layers above left, and the weight left below it is closure_layering_weight's
//   w' = w saturate(1 - max_c(A_c / w_c)),   A = the layer's albedo estimate (bsdf_albedo),
// one factor for all channels. For light from omega_i seen from omega_o (both unit, away from the surface), r the
// roughness, alpha = r^2, mu the cosines, and w0 = the node's Alpha (opacity):
//   sheen     W_sh T_sh w0 f_sh,  f_sh cos_i = E_sh(mu_o) D_ltc(omega_i), Zeltner et al. 2022's LTC sheen of
//             roughness r_sh read from Cycles' table (cycles_sheen.h); its albedo W_sh T_sh E_sh leaves
//             w1 = w0 (1 - W_sh max_c(T_sh) E_sh);
//   coat      W_c w1 K_c f_ss(F_eta_c, alpha_c), GGX of alpha_c = r_c^2 with the exact dielectric Fresnel of index
//             eta_c and Cycles' energy compensation K_c (ggx_energy_compensation.h, F_ss from Kulla & Conty's fit),
//             whatever the distribution; its estimate A = W_c w1 K_c E(r_c, mu_o) mix(F0(eta_c), 1, s_bar(r_c, mu_o,
//             eta_c)) (ggx_fresnel_estimate.h) leaves w2 = w1 (1 - W_c K_c E mix(...)) lerp(1, T_c^(1/cos_t), W_c),
//             T_c the coat tint and cos_t = sqrt(1 - (1 - mu_o^2) / eta_c^2) the refracted view (Blender 4.4
//             on; 4.0-4.3 differ, CyclesRelease below);
//   specular  w2 K_s f_ss(F_s, alpha), F_s(c) = mix(f0, 1, s(c)), s(c) = saturate((F_eta'(c) - F0(eta')) / (1 -
//             F0(eta'))), f0 = saturate(2 L F0(eta) T_s) and eta' = ior_from_F0(2 L F0(eta)) (eta itself at L =
//             0.5), L the Specular IOR Level and T_s the Specular Tint; K_s = 1 for "GGX", and for "Multiscatter GGX"
//             K_s = 1 + F_ms (1 - E) / E with F_ss = mix(f0, 1, saturate((F_ss_fit(eta') - F0(eta')) / (1 -
//             F0(eta')))); its estimate A = w2 K_s E_s mix(f0, 1, s_bar(r, mu_o, eta')), with E_s = E(r, mu_o) for
//             Multiscatter GGX and 1 for GGX (Cycles estimates the Fresnel alone), leaves w3 = w2 (1 - max_c(A_c /
//             w2_c)); no specular closure where eta' = 1 (L = 0 or eta = 1);
//   diffuse   w3 C (1 - S) f_d, Lambert or (Diffuse Roughness > 0, 4.3+) Cycles' Oren-Nayar (cycles_diffuse.h);
//   subsurface w3 C S cos_i / pi.
// f_ss(F, alpha) cos_i = F(omega_i.h) D(h) G2(mu_i, mu_o) / (4 mu_o), GGX with height-correlated Smith masking; C the
// base colour; W, T and r the layers' weights, tints and roughnesses. Every weight depends on the view alone, so the
// BRDF is not reciprocal; each lobe by itself is. A microfacet lobe of alpha^2 <= 2e-10 is a mirror: no f, and its
// albedo F(mu_o) (times its weight and K) reflected into the mirror direction. A closure whose mean weight is below
// 1e-5 is not made (bsdf_alloc) and does not layer.
//
// Subsurface, at the BRDF's scale (a flat surface, light leaving where it entered): Cycles hands the share S of the
// base to a BSSRDF of weight C S w3 whose random walk starts along the refracted view, divides its weight by C and
// scatters in a medium whose half-space albedo its fit sets to C, and leaves through a Lambert closure of weight 1
// (integrator/subsurface.h, subsurface_random_walk.h): C S w3 cos_i / pi, as far as the fit holds. Its radius, scale,
// IOR and anisotropy and the walk's method do not enter; Diffuse Roughness does not shape it.
//
// The energy compensation's tables E(r, mu), E_avg(r) and s_bar(r, mu, eta) are Cycles' (their nodes, coordinates and
// interpolation), their values integrated here. The sheen's LTC and albedo are Cycles' own table's values.
// Not here: metal, transmission, thin film, anisotropy (each must be 0) and emission (adds light, reflects none).
#pragma once

#include <Eigen/Core>
#include <array>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

using Rgb = Eigen::Array3d;

// The node's "Distribution": "GGX" is single scattering; "Multiscatter GGX" (the default) compensates its specular.
enum class CyclesDistribution { kGgx, kMultiscatterGgx };

// The Cycles whose coat is modelled. Blender 4.4 (Cycles commit 2b408569, February 2025, "Principled coat doesn't
// pass furnace test") gave the coat the energy compensation K_c and the tabulated Fresnel estimate above. Blender
// 4.0-4.3 make the coat with the exact Fresnel alone: K_c = 1 and the estimate A = W_c w1 F_eta_c(mu_o), the
// Fresnel of a smooth surface at the view. Nothing else in this model differs between them (4.2 has no Diffuse
// Roughness: it must stay 0 there).
enum class CyclesRelease { kBlender4_0To4_3, kBlender4_4On };

// The node's inputs, Blender 4.x-5.x's defaults (node_shader_bsdf_principled.cc). Ranges: the node's.
struct CyclesPrincipledParameters {
  Rgb base_color = Rgb::Constant(0.8);
  double metallic = 0.0;  // must be 0 for now
  double roughness = 0.5;
  double ior = 1.5;                // [1, 1000]
  double alpha = 1.0;              // opacity: the reflected light scales with it
  double diffuse_roughness = 0.0;  // 4.3+; 0 is Lambert (4.2's only diffuse)
  double subsurface_weight = 0.0;
  Rgb subsurface_radius = Rgb(1.0, 0.2, 0.1);  // [0, 100]; no part of the BRDF
  double subsurface_scale = 0.05;              // [0, 10] scene units; no part of the BRDF
  double subsurface_ior = 1.4;                 // [1.01, 3.8]; no part of the BRDF
  double subsurface_anisotropy = 0.0;          // no part of the BRDF
  double specular_ior_level = 0.5;
  Rgb specular_tint = Rgb::Ones();
  double anisotropic = 0.0;  // must be 0 for now
  double anisotropic_rotation = 0.0;
  double transmission_weight = 0.0;  // must be 0 for now
  double coat_weight = 0.0;
  double coat_roughness = 0.03;
  double coat_ior = 1.5;  // [1, 4]
  Rgb coat_tint = Rgb::Ones();
  double sheen_weight = 0.0;
  double sheen_roughness = 0.5;
  Rgb sheen_tint = Rgb::Ones();
  Rgb emission_color = Rgb::Ones();  // no part of the BRDF
  double emission_strength = 0.0;    // [0, 1e6]; no part of the BRDF
  double thin_film_thickness = 0.0;  // nm; must be 0 for now
  double thin_film_ior = 1.33;       // [1, 1000]
  CyclesDistribution distribution = CyclesDistribution::kMultiscatterGgx;
  CyclesRelease release = CyclesRelease::kBlender4_4On;  // not an input of the node: the Blender that renders it
};

// The lobes, each already weighted as in the sum above; f cos(theta_i) per channel.
struct CyclesPrincipledLobes {
  Rgb sheen = Rgb::Zero(), coat = Rgb::Zero(), specular = Rgb::Zero(), diffuse = Rgb::Zero(), subsurface = Rgb::Zero();
  Rgb sum() const { return sheen + coat + specular + diffuse + subsurface; }
};

class CyclesPrincipled {
 public:
  // Throws ParameterError naming the input out of its range or not built (metallic, transmission_weight,
  // anisotropic, thin_film_thickness must be 0).
  explicit CyclesPrincipled(const CyclesPrincipledParameters& parameters);

  const CyclesPrincipledParameters& parameters() const { return parameters_; }

  // The same surface with another base colour (each channel in [0, 1]): no table depends on it, so this costs a copy.
  CyclesPrincipled with_base_color(const Rgb& base_color) const;

  CyclesPrincipledLobes lobes_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const;
  Rgb brdf_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const;
  Rgb brdf(const Vec3& omega_i, const Vec3& omega_o) const;  // 1/sr

  // The light each lobe sends toward the view at cosine mu_o under a white sky, int f cos(theta_i) d omega_i, weighted
  // as above (a mirror's reflection included); and their sum. In closed form from the lobes' own albedos, which are
  // integrated once at construction on 65 view angles and interpolated (Catmull-Rom).
  CyclesPrincipledLobes lobe_albedos(double mu_o) const;
  Rgb albedo(double mu_o) const;

  // The same with the base colour replaced by `diffuse` (in [0, 1]): what a fit needs to find the colour that gives an
  // albedo. The base colour enters only the diffuse and subsurface lobes.
  Rgb albedo_with_diffuse_color(double mu_o, const Rgb& diffuse) const;

  // The weights left at the view for the layers below the sheen (w1), the coat (w2, its tint included) and the
  // specular (w3), and the compensations K_c and K_s.
  struct Layering {
    Rgb under_sheen = Rgb::Ones(), under_coat = Rgb::Ones(), under_specular = Rgb::Ones();
    double coat_compensation = 1.0;
    Rgb specular_compensation = Rgb::Ones();
    bool sheen = false, coat = false, specular = false;  // whether the closure is made
  };
  Layering layering(double mu_o) const;

  static constexpr int kAngles = 65;  // view angles of the lobes' albedo tables, 0 to 90 degrees

 private:
  CyclesPrincipledParameters parameters_;
  double specular_index_ = 1.0;                 // eta'
  Rgb specular_f0_ = Rgb::Zero();               // f0
  Rgb specular_average_fresnel_ = Rgb::Zero();  // F_ss of the specular
  double coat_average_fresnel_ = 0.0;           // F_ss of the coat
  // The single-scattering lobes' albedos on the view angles: the coat's with its Fresnel, the specular's with a white
  // Fresnel and with s(c), so that its albedo is f0 E_white + (1 - f0) E_blend.
  std::array<double, kAngles> coat_albedo_{}, specular_white_{}, specular_blend_{};
};

}  // namespace skinlayer
