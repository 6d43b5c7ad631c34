// The GGX (Trowbridge-Reitz) microfacet lobe as the target shaders use it (docs/model.md §22.1, §22.3): its normal
// distribution and Smith masking, and the directional albedo of any lobe that lives on half vectors. Isotropic;
// alpha is GGX's width (the shaders' roughness squared). Directions are unit vectors in the graphics convention.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

using Rgb = Eigen::Array3d;

// D(m) = alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2), 1/sr, for a microfacet normal of cosine cos_m.
double ggx_distribution(double cos_m, double alpha);

// Smith's G1 along a direction of cosine mu (Walter et al. 2007, eq. 34): 2 / (1 + sqrt(1 + alpha^2 tan^2)).
double ggx_masking(double mu, double alpha);

// Smith's height-correlated masking-shadowing (Heitz 2014, eq. 99): 1 / (1 + Lambda(mu_i) + Lambda(mu_o)), with
// Lambda(mu) = (sqrt(1 + alpha^2 tan^2) - 1) / 2.
double ggx_height_correlated_masking(double mu_i, double mu_o, double alpha);

// The directional albedo of a microfacet lobe for light from omega_i, int lobe(omega_o) d omega_o, where `lobe`
// gives f cos(theta_o) (1/sr times the cosine). Integrated over the half vector h, with omega_o = 2 (omega_i.h) h -
// omega_i and d omega_o = 4 (omega_i.h) d omega_h (Walter et al. 2007, eq. 14): at each of 2 `polar` azimuths of h the
// view leaves the hemisphere where a sin(2 theta_h) + b cos(2 theta_h) = 0 (a = sin(theta_i) cos(phi_h - phi_i),
// b = cos(theta_i)), and `polar` Gauss-Legendre nodes stop there, so that they meet no kink; between, theta_h =
// atan(width tan(v pi / 2)) on v in [0, 1] spreads them as a distribution of that width in tan(theta_h) does (alpha
// for GGX, whose tail falls as a Cauchy's; sqrt(alpha) for heavier tails).
Rgb microfacet_lobe_albedo(const std::function<Rgb(const Vec3& omega_o)>& lobe, const Vec3& omega_i, double width,
                           int polar);

}  // namespace skinlayer
