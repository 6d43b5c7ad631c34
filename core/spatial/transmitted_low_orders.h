// The light leaving the bottom of a finite stack that crossed it unscattered or was scattered once on the way, for
// light entering at a point through its top (docs/model.md §21.15): the singular part of the transmittance profile,
// continuous in angle. Lengths are in mean free paths of the first slab; the stack's geometric depth is
// H = sum_l tau_l / e_l and its optical depth tau = sum_l tau_l.
//
// Unscattered: light entering at cosine mu leaves at r = H tan(theta) having passed e^{-tau / mu}:
//   power through [r0, r1) = int 2 pi L(mu) X(mu) e^{-tau / mu} mu sin(theta) d theta over H tan(theta) in [r0, r1),
//   density at r            = L(mu) X(mu) e^{-tau / mu} mu^4 / H^2,   mu = H / sqrt(H^2 + r^2),
// with L the entering radiance (entering_radiance.h) and X the bottom's exit fraction. The collimated beam's own
// unscattered light is a delta at r = 0, in no profile.
//
// Once scattered: light entering along e (cosine mu_e, power P_e, any azimuth) is scattered at geometric depth z in
// slab l (optical depth O(z) = T_l + e_l (z - G_l), T_l and G_l above the slab) into o (cosine mu_o, azimuth dphi
// from e's) and leaves the bottom displaced by z A + (H - z) B, |A| = tan(theta_e), |B| = tan(theta_o):
//   r(z)^2 = |H B + z (A - B)|^2,  a quadratic in z,
// having passed e^{-O / mu_e - (tau - O) / mu_o}. The power through an annulus is
//   sum_e P_e sum_l Omega_l e_l / mu_e int d omega_o p_l(e.o) X(mu_o) int_{z in slab l, r(z) in [r0, r1)} e^{...} dz,
// the z-integral in closed form over the (at most two) intervals where r(z) falls in the annulus, the directions by
// Gauss-Legendre panels. The density sums, over the roots of r(z) = r, the path's weight times |dz / dr| / (2 pi r).
#pragma once

#include <span>

#include "core/spatial/entering_radiance.h"
#include "core/spatial/lateral_bottom_face.h"
#include "core/spatial/lateral_frequency_response.h"

namespace skinlayer {

// exit: the bottom face's exit fraction X(mu) (lateral_bottom_face.h); empty: index-matched, everything leaves. The
// slabs must all be finite.
double unscattered_transmitted_power(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                                     const ExitFraction& exit, double r0, double r1);
double unscattered_transmitted_density(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                                       const ExitFraction& exit, double r);

double single_scattered_transmitted_power(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                                          const ExitFraction& exit, double r0, double r1);
double single_scattered_transmitted_density(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                                            const ExitFraction& exit, double r);

}  // namespace skinlayer
