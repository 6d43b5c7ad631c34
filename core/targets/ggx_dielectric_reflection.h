// A dielectric interface's reflection as OpenPBR Surface's specular and coat lobes have it in MaterialX's node graph
// (docs/model.md §22.3; the graph's dielectric_bsdf in reflection, as its GLSL generator implements it): GGX with
// Smith's height-correlated masking and the exact dielectric Fresnel,
//   f_ss cos(theta_i) = F(omega_i.h, eta) D(h) G2(mu_i, mu_o) / (4 mu_o),
// made up for the light it loses to single scattering by Turquin 2019's scaling, as MaterialX 1.39 (1.39.5, the
// release renderers run) weighs it under an environment (mx_dielectric_bsdf.glsl, its indirect closure):
//   f = f_ss c(mu_o),   c(mu_o) = 1 + F(mu_o, eta) (1 - E_w(mu_o)) / E_w(mu_o),
// with E_w MaterialX's rational fit of the GGX albedo for a white Fresnel (materialx_ggx_albedo_terms below, a + b),
// not the integral: the renderer's own numbers. The factor is the view's, so the lobe is not reciprocal. Two albedos
// at the view follow:
//   albedo(mu_o)        the lobe's own, int f cos(theta_i) d omega_i = c(mu_o) E_F(mu_o), E_F the single-scattering
//                       albedo with the exact Fresnel, integrated once (ggx_lobe.h, 16 nodes) on 33 view angles, 0
//                       to 90 degrees, and interpolated by Catmull-Rom in the angle: what a renderer that integrates
//                       the lobe (under a white sky, by sampling) gets;
//   layer_albedo(mu_o)  what MaterialX's layer node takes from the light under the lobe: c(mu_o) (F0 a + b), the fit
//                       with Schlick's Fresnel of the same F0 = ((eta - 1)/(eta + 1))^2. Within about 1% of albedo,
//                       and not equal to it: the graph does not conserve energy exactly.
// Under a light MaterialX 1.39 weighs c by F(omega_o.h) instead, in the lobe and in what it passes on, so that its
// direct lighting differs from this at grazing views where F(omega_o.h) and F(mu_o) part. Its next release (after
// 1.39.5, pull request 2958) weighs c by F_avg = F0 + (1 - F0) / 21 everywhere: 1.3-2.6% less light at 80 degrees
// for a coat of index 1.5 over a base of index 1.2 (docs/model.md §22.3).
// Below alpha 1e-4 the interface is smooth: a mirror, whose albedo is c(mu_o) F(mu_o, eta) and whose f is 0 between
// mirror pairs (MaterialX clamps alpha at 1e-8 and its fit is a polynomial in alpha, so c is the same there).
#pragma once

#include <array>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

// MaterialX's rational fit of GGX's directional albedo (its GLSL generator's default "analytic" method,
// mx_microfacet_specular.glsl, MaterialX 1.39): with Schlick's Fresnel F0 + (F90 - F0)(1 - cos)^5 the albedo at the
// view of cosine mu is F0 a + F90 b, each of a and b a ratio of polynomials in mu and alpha held to [0, 1].
struct GgxAlbedoTerms {
  double a = 0.0, b = 0.0;
};
GgxAlbedoTerms materialx_ggx_albedo_terms(double mu, double alpha);

class GgxDielectricReflection {
 public:
  static constexpr int kAngles = 33;
  static constexpr double kSmoothAlpha = 1e-4;

  // eta: the index below over the index above (> 0); alpha: GGX's width, >= 0.
  GgxDielectricReflection(double eta, double alpha);

  double eta() const { return eta_; }
  double alpha() const { return alpha_; }
  bool smooth() const { return alpha_ < kSmoothAlpha; }

  // f cos(theta_i), compensated; 0 below either horizon.
  double cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const;

  // int f cos(theta_i) d omega_i for the view at cosine mu_o: c(mu_o) E_F(mu_o).
  double albedo(double mu_o) const;

  // What a layer of this lobe takes from the light under it, in MaterialX's graph: c(mu_o) (F0 a + b).
  double layer_albedo(double mu_o) const;

  // Turquin's factor c(mu_o) with MaterialX's fit for E_w and the Fresnel at the view.
  double compensation(double mu_o) const;

 private:
  double interpolate(const std::array<double, kAngles>& table, double mu) const;

  double eta_, alpha_, f0_;
  std::array<double, kAngles> fresnel_{};  // E_F on the angles
};

}  // namespace skinlayer
