// Cycles' energy compensation of its GGX lobes (docs/model.md §22.1.1), as bsdf_microfacet.h's
// microfacet_ggx_preserve_energy applies it to the "Multiscatter GGX" Principled BSDF's specular and, whatever the
// distribution, to its coat (Blender 4.x-5.x). With E(r, mu) the directional albedo of the single-scattering GGX
// lobe with a white Fresnel at roughness r (alpha = r^2) for the view at cosine mu, and E_avg(r) = 2 int E mu dmu,
// the lobe is multiplied by
//   K = 1 + F_ms (1 - E) / E,   F_ms = F_ss E_avg / (1 - F_ss (1 - E_avg)),
// Kulla & Conty 2017's multiple-scattering lobe with one F_ss cancelled (F_ss the lobe's average Fresnel; F_ss = 1
// gives K = 1/E). Cycles reads E and E_avg from tables, E on 32 x 32 nodes (roughness x view cosine), E_avg on 32
// roughnesses, both by lookup_table_read (cycles_lookup_table.h); it made them by Monte Carlo
// (app/cycles_precompute.cpp, tables ggx_E and ggx_Eavg). Here the same nodes, at the same clamped coordinates
// (roughness and cosine in [1e-4, 1]), are integrated by quadrature over half vectors (ggx_lobe.h), once per
// process, and read the same way. A roughness whose alpha^2 <= 2e-10 is a mirror (BSDF_ROUGHNESS_SQ_THRESH): E = 1.
#pragma once

#include <Eigen/Core>
#include <functional>

namespace skinlayer {

class HalfVectorQuadrature;
using Rgb = Eigen::Array3d;

// Cycles' threshold: alpha_x alpha_y at or below it is a mirror, which its microfacet closures sample but do not
// evaluate.
inline constexpr double kCyclesMirrorAlphaSquared = 2e-10;
inline bool cycles_ggx_is_mirror(double alpha) { return alpha * alpha <= kCyclesMirrorAlphaSquared; }

// int fresnel(omega_i.h) D(h) G2(mu_i, mu_o) / (4 mu_o) d omega_i, the directional albedo of the single-scattering
// GGX reflection (height-correlated Smith G2, Heitz 2014) with the Fresnel factor given as a function of the
// cosine between light and half vector, for the view at cosine mu_o; `polar` nodes per azimuth (ggx_lobe.h).
// A mirror (cycles_ggx_is_mirror) reflects fresnel(mu_o).
double ggx_reflection_albedo(double alpha, double mu_o, const std::function<double(double cos_ih)>& fresnel,
                             int polar = 32);
// The same on rules computed once (half_vector_quadrature.h).
double ggx_reflection_albedo(const HalfVectorQuadrature& quadrature, double alpha, double mu_o,
                             const std::function<double(double cos_ih)>& fresnel);

// E(r, mu) and E_avg(r) read from the tables, r the Principled node's roughness (sqrt(alpha)).
double cycles_ggx_albedo(double roughness, double mu);
double cycles_ggx_average_albedo(double roughness);

// The tables' nodes themselves: E at roughness node i and cosine node j (0 to 31) and E_avg at roughness node i.
double cycles_ggx_albedo_node(int roughness_node, int cosine_node);
double cycles_ggx_average_albedo_node(int roughness_node);

// Cycles' average single-scattering Fresnel of a dielectric, 2 int F(mu, eta) mu dmu, by Kulla & Conty's fit
// (bsdf_util.h, fresnel_dielectric_Fss): (eta - 1) / (4.08567 + 1.00071 eta) for eta >= 1, and
// 0.997118 + eta (0.1014 - eta (0.965241 + eta 0.130607)) below.
double cycles_dielectric_average_fresnel(double eta);

// K above, per channel, for the view at cosine mu and the lobe's average Fresnel F_ss.
Rgb cycles_ggx_energy_factor(double roughness, double mu, const Rgb& average_fresnel);

}  // namespace skinlayer
