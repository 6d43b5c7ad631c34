// The classical diffusion dipole for a pencil beam on a semi-infinite medium (Farrell, Patterson & Wilson 1992,
// "A diffusion theory model of spatially resolved, steady-state diffuse reflectance for the noninvasive
// determination of tissue optical properties in vivo", Med. Phys. 19:879), index-matched (A = 1). It is what
// production skin models build on, and an approximation: skinlayer compares the shape of its exact profile with it
// (docs/model.md §21.8). Lengths in mean free paths (mu_t = 1), reflectance per unit area (1/mfp^2).
//
// With mu_a = 1 - Omega, mu_s' = Omega (1 - g), mu_t' = mu_a + mu_s', alpha' = mu_s' / mu_t', D = 1 / (3 mu_t'),
// mu_eff = sqrt(mu_a / D), z0 = 1 / mu_t', z_b = 2 A D, r1 = sqrt(z0^2 + r^2) and r2 = sqrt((z0 + 2 z_b)^2 + r^2):
//   R(r) = alpha' / (4 pi) [z0 (mu_eff + 1/r1) e^{-mu_eff r1} / r1^2
//                           + (z0 + 2 z_b) (mu_eff + 1/r2) e^{-mu_eff r2} / r2^2],
// whose integral over the plane is R = (alpha'/2) (1 + e^{-(4/3) A sqrt(3 (1 - alpha'))}) e^{-sqrt(3 (1 - alpha'))}.
#pragma once

namespace skinlayer {

double diffusion_dipole_reflectance(double albedo, double g, double r);  // R(r), 1/mfp^2
double diffusion_dipole_total_reflectance(double albedo, double g);      // its integral over the plane

}  // namespace skinlayer
