// Light scattered exactly once in a stack of slabs under a rough top, lit by a pencil beam at normal incidence, or
// under any top by diffuse light: the singular part of its reflectance profile (docs/model.md §21.10). Lengths are in
// mean free paths of the first slab.
//
// The top refracts the beam into a lobe (or diffuse light arrives from everywhere), which the ordinates hold as node
// radiance t_j at cosines mu_j, uniform in azimuth (lateral_top_interface.h). Light entering along d (node j, any
// azimuth) and scattered at path length s into an upward direction o (node i) leaves the top displaced by s rho, with
//   rho^2 = sin^2(theta_j) + (mu_j tan(theta_i))^2 + 2 sin(theta_j) mu_j tan(theta_i) cos(dphi),
// where dphi is the azimuth between d and o, and crosses the top with T_i = T_top,inside(mu_i). Going down and back
// up it passes the optical depth O(z) twice, at the rates 1/mu_j and 1/mu_i. In slab l (albedo Omega_l, relative
// extinction e_l, optical depth T_l above it, reached at s_l = depth / mu_j) the path survives
//   e^{-T_l a / mu_j} e^{-e_l a (s - s_l)},   a = 1 + mu_j / mu_i,
// and the light leaving is
//   R1 = sum_ij 2 pi a_i T_i a_j mu_j t_j sum_l Omega_l e_l int_0^{2 pi} p_l(d.o) int_slab e^{...} [what s reaches] ds
// with d.o = -mu_i mu_j + sin(theta_i) sin(theta_j) cos(dphi). This is the discrete ordinates' own single scattering
// with infinitely many azimuthal modes: at k = 0 it equals their first order in the albedos.
#pragma once

#include <span>

#include "core/spatial/lateral_frequency_response.h"
#include "core/spatial/lateral_top_interface.h"

namespace skinlayer {

// The ordinates' own low orders in the albedos under `top` at frequency k, exactly, every stream through the same M
// coupled modes. With C = W diag(lambda) W^-1, streaming along node mu over optical depth t of slab l is
// W diag(e^{-t (1 + (k / e_l) sin(theta) lambda) / mu}) W^-1, so each depth integral is closed-form per pair of
// eigenvalues and slab. Nothing reflects at either face.
//   reflected_once: lateral_stack_response's reflectance to first order: the top's node radiance streamed down,
//     scattered once, streamed up and out through the top;
//   transmitted_once, transmitted_unscattered: on the bottom of a finite stack, the first order, and the node radiance
//     streamed down through every slab unscattered (§21.15), leaving the bottom by its exit fraction at each node
//     (bottom_exit; empty: an index-matched bottom, all of it); 0 for a semi-infinite stack.
struct RoughTopLowOrders {
  double reflected_once = 0.0, transmitted_once = 0.0, transmitted_unscattered = 0.0;
};
RoughTopLowOrders rough_top_low_orders(std::span<const LateralSlab> slabs, const LateralTopInterface& top, double k,
                                       const LateralFrequencyResolution& resolution,
                                       const Eigen::VectorXd& bottom_exit = {});

// With the top's operators on `ordinates` nodes: the singly scattered power leaving the top through the annulus
// r0 <= r < r1 (per unit incident power; r1 may be +infinity), and its density at r > 0 (1/mfp^2, growing like 1/r
// as r -> 0). Over slab l the path integral is closed-form:
//   annulus: int e^{-e_l a (s - s_l)} over s in the slab with r0 <= s rho < r1,
//   density: (1 / 2 pi r) e^{-e_l a (r / rho - s_l)} / rho where r / rho lies in the slab.
double rough_top_single_scattered_power(std::span<const LateralSlab> slabs, const LateralTopInterface& top,
                                        int ordinates, double r0, double r1);
double rough_top_single_scattered_density(std::span<const LateralSlab> slabs, const LateralTopInterface& top,
                                          int ordinates, double r);

// The Hankel transform of one semi-infinite slab's R1 at k: its path integral is 1 / sqrt(a^2 + k^2 rho^2).
double rough_top_single_scattered_transform(double albedo, double g, const LateralTopInterface& top, int ordinates,
                                            double k);

}  // namespace skinlayer
