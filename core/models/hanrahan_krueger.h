// Hanrahan & Krueger 1993, "Reflection from layered surfaces due to subsurface scattering" (SIGGRAPH '93): the
// analytic first-order (single-scattering) term of a homogeneous layer with smooth Fresnel boundaries. Their
// approximation of the multiple-scattering part is not included: this is the single-scattering model only, so it
// lacks the energy of light scattered more than once.
//
// With primed angles refracted into the layer (sin theta' = sin theta / eta), T = 1 - F the Fresnel transmittance,
// p the Henyey-Greenstein phase function at the angle between the refracted incident and outgoing directions, and
// the radiance scaling of leaving a denser medium:
//   f_r = Omega T12(theta_i) T21(theta_o') p (1 - e^{-tau (1/mu_i' + 1/mu_o')}) / (eta^2 (mu_i' + mu_o'))     [1/sr]
//   f_t = Omega T12(theta_i) T23(theta_o') p (e^{-tau/mu_i'} - e^{-tau/mu_o'}) / (eta_3^2 (mu_i' - mu_o'))
// where eta_3 = n_layer / n_below (1 for a matched bottom; a Lambertian bottom transmits nothing). In the
// index-matched limit f_r is the exact single-scattering BRDF of the slab. The surface term is the caller's
// (the same rough-dielectric term as the layer model). Angles: core/conventions.h. The material must be valid
// (validate() in material.h); these are evaluated per sample and do not check it.
#pragma once

#include "core/material.h"

namespace skinlayer {

double hanrahan_krueger_brdf_subsurface(const Material& material, double theta_i, double theta_o, double phi);
double hanrahan_krueger_btdf(const Material& material, double theta_i, double theta_o, double phi);

}  // namespace skinlayer
