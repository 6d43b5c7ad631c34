// Light scattered exactly once in a layer under a rough top, lit by a pencil beam at normal incidence: the singular
// part of its reflectance profile (docs/model.md §21.10). Lengths are in mean free paths.
//
// The top refracts the beam into a lobe, which the ordinates hold as node radiance t_j at cosines mu_j, uniform in
// azimuth (lateral_top_interface.h). Light entering along d (node j, any azimuth) and scattered at path length s
// into an upward direction o (node i) leaves the top after the further path s mu_j / mu_i, displaced by s rho with
//   rho^2 = sin^2(theta_j) + (mu_j tan(theta_i))^2 + 2 sin(theta_j) mu_j tan(theta_i) cos(dphi),
// where dphi is the azimuth between d and o. It survives e^{-a s}, a = 1 + mu_j / mu_i, and crosses the top with
// T_i = T_top,inside(mu_i). Summed over the nodes, with the azimuth dphi integrated exactly, the light leaving a
// semi-infinite layer is
//   R1 = sum_ij 2 pi a_i T_i a_j mu_j t_j Omega int_0^{2 pi} p(d.o) int_0^inf e^{-a s} [what s reaches] ds ddphi,
// d.o = -mu_i mu_j + sin(theta_i) sin(theta_j) cos(dphi). This is the discrete ordinates' own single scattering with
// infinitely many azimuthal modes: at k = 0 it equals their first order in Omega.
#pragma once

#include "core/spatial/lateral_frequency_response.h"
#include "core/spatial/lateral_top_interface.h"

namespace skinlayer {

// The first order in Omega of rough_top_lateral_response's reflectance at frequency k (1/mfp), exactly: the top's
// node radiance streamed down, scattered once, streamed up and out, every stream through the same M coupled modes.
// With C = W diag(lambda) W^-1, streaming along node mu over depth t is W diag(e^{-t (1 + k sin(theta) lambda)/mu})
// W^-1, so the depth integral is closed-form per pair of eigenvalues. A finite tau bounds it; no bottom reflects.
double rough_top_single_scattering_reflectance(double tau, double albedo, double g, const LateralTopInterface& top,
                                               double k, const LateralFrequencyResolution& resolution);

// For a semi-infinite layer, with the top's operators on `ordinates` nodes: the singly scattered power leaving the
// top through the annulus r0 <= r < r1 (per unit incident power), its density at r > 0 (1/mfp^2, growing like 1/r
// as r -> 0), and its Hankel transform at k (R1(0) is the whole singly scattered reflectance).
//   annulus: int_0^inf e^{-a s} [r0 <= s rho < r1] ds = (e^{-a r0/rho} - e^{-a r1/rho}) / a,
//   density: (1 / 2 pi r) e^{-a r/rho} / rho,   transform: 1 / sqrt(a^2 + k^2 rho^2).
double rough_top_single_scattered_power(double albedo, double g, const LateralTopInterface& top, int ordinates,
                                        double r0, double r1);
double rough_top_single_scattered_density(double albedo, double g, const LateralTopInterface& top, int ordinates,
                                          double r);
double rough_top_single_scattered_transform(double albedo, double g, const LateralTopInterface& top, int ordinates,
                                            double k);

}  // namespace skinlayer
