// A dielectric interface's reflection as OpenPBR Surface's specular and coat lobes have it (docs/model.md §22.3):
// GGX with Smith's height-correlated masking and the exact dielectric Fresnel,
//   f_ss cos(theta_i) = F(omega_i.h, eta) D(h) G2(mu_i, mu_o) / (4 mu_o),
// made up for the light it loses to single scattering by Turquin 2019's scaling, in the form of MaterialX 1.39's
// reference (mx_microfacet_specular.glsl, after its 1.39.5 release):
//   f = f_ss (1 + F_avg (1 - E_ss(mu_o)) / E_ss(mu_o)),   F_avg = F0 + (1 - F0) / 21,
// with E_ss the lobe's albedo for a white Fresnel (F = 1). The factor is the view's, so the lobe is not reciprocal,
// and its albedo at the view is the factor times the single-scattering albedo E_F(mu_o). Both albedos are integrated
// once (ggx_lobe.h, 16 nodes) on 33 view angles, 0 to 90 degrees, and interpolated by Catmull-Rom in the angle.
// Below alpha 1e-4 the interface is smooth: a mirror, whose albedo is F(mu_o, eta) and whose f is 0 between mirror
// pairs.
#pragma once

#include <array>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

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

  // int f cos(theta_i) d omega_i for the view at cosine mu_o: the compensation times E_F(mu_o).
  double albedo(double mu_o) const;

 private:
  double compensation(double mu_o) const;
  double interpolate(const std::array<double, kAngles>& table, double mu) const;

  double eta_, alpha_, fresnel_average_;
  std::array<double, kAngles> white_{}, fresnel_{};  // E_ss and E_F on the angles
};

}  // namespace skinlayer
