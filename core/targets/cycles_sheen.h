// The Sheen closure of Blender 4.x-5.x as Cycles evaluates it (closure/bsdf_sheen.h, bsdf_sheen_setup and
// bsdf_sheen_eval; docs/model.md §22.1.1): Zeltner, Burley & Chiang 2022's microfibre sheen, the same linearly
// transformed cosine as zeltner_fuzz.h,
//   f cos(theta_i) = E(mu_o, r) D_ltc(a, b; omega_i, omega_o),
// but with a, b and E read from Cycles' table of the paper's tabulated fit (cycles_sheen_ltc_table.inc: 32 x 32
// nodes in the view's cosine mu_o and the roughness r, bilinear as cycles_lookup_table.h reads them) instead of the
// paper's analytic fit of that table. The two differ by up to a few per cent of the albedo and more of the lobe's
// shape at grazing views and full roughness (tests/core/targets/cycles_sheen_test.cpp). Cycles clamps r to
// [1e-3, 1] and makes no closure where |a| < 1e-5 or E < 1e-5. Units: E is a fraction, f is 1/sr.
#pragma once

#include "core/interfaces/microfacet.h"

namespace skinlayer {

// The lobe's albedo E(mu_o, r) at the view, as Cycles' table gives it (0 where Cycles makes no closure).
double cycles_sheen_albedo(double mu_o, double roughness);

// f cos(theta_i) for a white sheen of weight 1 (0 where either direction is below the surface or where Cycles makes
// no closure).
double cycles_sheen_cosine_weighted(double roughness, const Vec3& omega_i, const Vec3& omega_o);

}  // namespace skinlayer
