// OpenPBR Surface's fuzz (docs/model.md §22.3): the sheen of Zeltner, Burley & Chiang 2022, a layer of fibres
// (SGGX microflakes, optical depth 1, white, index-matched) whose reflection is fitted by a linearly transformed
// cosine (LTC) in the light direction and an albedo, both functions of the view's cosine x = mu_o and the fuzz
// roughness r in [0.01, 1] (the fits as OpenPBR's MaterialX reference evaluates them, MaterialX 1.39's
// mx_microfacet_sheen.glsl):
//   f cos(theta_i) = E(x, r) D(omega_i),   D = (w.z / pi) (a / |w|^2)^2,   w = (a l_x + b l_z, a l_y, l_z),
// with l the light in the frame whose x axis is the view's tangent direction, a and b the LTC's inverse-matrix
// entries, and E(x, r) = exp(-((x - m) / s)^2 / 2) / (s sqrt(2 pi)) + o the lobe's albedo at the view (held at 0 or
// above: at roughness 0.1 the fit dips to -2e-5). D integrates to
// 1 over the light's hemisphere, so E is the directional albedo. Not reciprocal: it is a function of the view.
#pragma once

#include "core/interfaces/microfacet.h"

namespace skinlayer {

// The lobe's albedo E(mu_o, r).
double zeltner_fuzz_albedo(double mu_o, double roughness);

// The LTC's cosine-weighted density D over the light omega_i for the inverse-matrix entries a and b, in the frame
// whose x axis is omega_o's tangent direction (any, at normal view); it integrates to 1 over the upper hemisphere.
double zeltner_ltc_distribution(double a, double b, const Vec3& omega_i, const Vec3& omega_o);

// f cos(theta_i) for a white fuzz of weight 1 (0 where either direction is below the surface).
double zeltner_fuzz_cosine_weighted(double roughness, const Vec3& omega_i, const Vec3& omega_o);

}  // namespace skinlayer
