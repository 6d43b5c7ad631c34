// The sheen lobe of glTF's KHR_materials_sheen (section "Implementation Notes": "Sheen distribution", "Sheen
// visibility", "Sheen layering") as three.js renders it (MeshPhysicalMaterial, lights_physical_pars_fragment), the
// choices the extension leaves to the renderer taken as three.js takes them:
//   distribution  Conty & Kulla 2017's "Charlie": D(h) = (2 + 1/a) sin(theta_h)^(1/a) / (2 pi), a = r^2 with r the
//                 sheen roughness (1/sr);
//   visibility    Ashikhmin & Premoze 2007's, in Neubelt & Pettineo 2013's form, which the extension offers as the
//                 cheaper choice: V = 1 / (4 (mu_i + mu_o - mu_i mu_o)), held at 1 or below (three.js's saturate);
//   albedo E      for the layering's albedo scaling, three.js's curve fit of the Charlie lobe's directional albedo,
//                 E(mu, r) = exp(a(r) mu + b(r)) held in [0, 1], a(r) = -1.9362 + 1.0678 r + 0.4573 r^2 -
//                 0.8469 / (r + 0.1), b(r) = -0.6014 + 0.5538 r - 0.4670 r^2 - 0.1255 / (r + 0.1).
// The extension's "Charlie" visibility (Estevez & Kulla's fitted Lambda) is not this one; with the Ashikhmin term the
// lobe's own albedo is not E, so the layering keeps energy only approximately (the extension says so). The lobe is
// reciprocal: D and V are symmetric in the two directions.
#pragma once

#include "core/interfaces/microfacet.h"

namespace skinlayer {

// three.js's least sheen roughness (its clamp, 1e-4), below which 1/a overflows.
inline constexpr double kLeastSheenRoughness = 1e-4;

// D above for a microfacet normal of cosine cos_h, 1/sr.
double charlie_sheen_distribution(double cos_h, double roughness);

// V above for the two cosines.
double ashikhmin_sheen_visibility(double mu_i, double mu_o);

// D V cos(theta_i) for a white sheen (0 where either direction is below the surface).
double charlie_sheen_cosine_weighted(double roughness, const Vec3& omega_i, const Vec3& omega_o);

// E(mu, r) above: three.js's fit, not the integral of the lobe.
double threejs_sheen_albedo(double mu, double roughness);

}  // namespace skinlayer
