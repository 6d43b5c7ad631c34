// The energy-preserving Oren-Nayar diffuse lobe, "EON" (Portsmouth, Kutz & Hill 2025), OpenPBR Surface's diffuse
// (docs/model.md §22.3): Fujii's Oren-Nayar single scattering plus a multiple-scattering lobe that gives back what it
// loses, so that a white surface reflects all the light at every roughness. With sigma the diffuse roughness in
// [0, 1], rho the albedo, mu the cosines and s = omega_i.omega_o - mu_i mu_o:
//   f_FON = (rho / pi) A (1 + sigma s / t),   A = 1 / (1 + c1 sigma),  t = max(mu_i, mu_o) where s > 0, else 1;
//   E_FON(mu) = A + (sigma A / pi) G(theta),  G = sin(theta) (theta - sin(theta) cos(theta))
//               + (2/3) (tan(theta) (1 - sin^3(theta)) - sin(theta)),   its albedo for rho = 1, exact;
//   E_avg = A (1 + c2 sigma),                 its average over the hemisphere, 2 int E_FON mu d mu;
//   f_ms = (rho_ms / pi) (1 - E_FON(mu_i)) (1 - E_FON(mu_o)) / (1 - E_avg),  rho_ms = rho^2 E_avg / (1 - rho (1 -
//   E_avg)),
// with c1 = 1/2 - 2/(3 pi) and c2 = 2/3 - 28/(15 pi). The lobe is reciprocal; sigma = 0 is Lambert's rho / pi.
#pragma once

#include <Eigen/Core>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

using Rgb = Eigen::Array3d;

// f cos(theta_i) (per channel; 0 where either direction is below the surface).
Rgb eon_diffuse_cosine_weighted(const Rgb& albedo, double roughness, const Vec3& omega_i, const Vec3& omega_o);

// E_FON(mu) and E_avg above (rho = 1).
double eon_single_scattering_albedo(double mu, double roughness);
double eon_average_single_scattering_albedo(double roughness);

// The whole lobe's directional albedo, rho E_FON(mu) + rho_ms (1 - E_FON(mu)), in closed form.
Rgb eon_diffuse_albedo(const Rgb& albedo, double roughness, double mu);

}  // namespace skinlayer
