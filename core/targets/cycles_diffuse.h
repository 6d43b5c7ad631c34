// The diffuse closure of Cycles' Principled BSDF (docs/model.md §22.1.1), Blender 4.x-5.x: Lambert's rho cos/pi
// (closure/bsdf_diffuse.h; 4.0-4.2, and 4.3+ while Diffuse Roughness < 1e-5) or, from 4.3 on, the Oren-Nayar closure
// of closure/bsdf_oren_nayar.h: Fujii's single scattering and OpenPBR's multiple-scattering lobe, EON's pair
// (eon_diffuse.h). With sigma the diffuse roughness, E and E_avg EON's albedos of the white single scattering, and
// the closure weight rho (the base colour):
//   f cos_i = rho [f_FON cos_i + m(rho) cos_i (1 - E(mu_i)) (1 - E(mu_o)) / (pi (1 - E_avg))],
//   m(rho) = rho^2 E_avg / (1 - rho (1 - E_avg)),
// with f_FON EON's white single scattering. EON (and OpenPBR) weight the multiple scattering by m(rho); Cycles
// computes the same m from the colour and then multiplies the whole closure by the colour again, so its multiple
// scattering is rho m(rho): a white surface reflects all the light, a coloured one less than EON's. Reciprocal.
#pragma once

#include <Eigen/Core>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

using Rgb = Eigen::Array3d;

// Below this roughness Cycles' Principled BSDF sets up Lambert (CLOSURE_WEIGHT_CUTOFF).
inline constexpr double kCyclesLambertBelow = 1e-5;

// f cos(theta_i) for the closure weight rho; 0 where either direction is below the surface.
Rgb cycles_diffuse_cosine_weighted(const Rgb& rho, double roughness, const Vec3& omega_i, const Vec3& omega_o);

// Its directional albedo at the view, in closed form: rho [E(mu_o) + m(rho) (1 - E(mu_o))] (rho for Lambert).
Rgb cycles_diffuse_albedo(const Rgb& rho, double roughness, double mu_o);

}  // namespace skinlayer
