// How Cycles estimates the albedo of a GGX reflection with the Principled BSDF's Fresnel (docs/model.md §22.1.1), for
// its layering: bsdf_microfacet.h's bsdf_microfacet_estimate_albedo (Blender 4.x-5.x), which assumes the microfacet
// lobe reflects all the light (the energy compensation's business) and estimates only the Fresnel's share.
// The Principled Fresnel ("generalized Schlick" with a negative exponent) blends F0 toward white as the real
// dielectric Fresnel of the index eta rises from its own F0:
//   F(c) = mix(f0, 1, s(c)),   s(c) = saturate((F_eta(c) - F0(eta)) / (1 - F0(eta))),   F0(eta) = ((eta-1)/(eta+1))^2,
// and the estimate is mix(f0, 1, s_bar(r, mu_o, eta)) with s_bar read from a 16 x 16 x 16 table (roughness, view
// cosine, z = sqrt|(eta - 1)/(eta + 1)| = F0^(1/4)), Cycles' ggx_gen_schlick_ior_s (app/cycles_precompute.cpp).
// Its generator samples visible normals from the view and averages s over the samples, a sample whose reflection
// falls below the horizon counting 0:
//   s_bar = int s(omega_i.h) G1(mu_o) D(h) / (4 mu_o) d omega_i   (omega_i over the upper hemisphere),
// G1 = 1 / (1 + Lambda(mu_o)), the probability density of VNDF sampling, not the lobe's G2: a VNDF-weighted mean of s,
// not the ratio of the Fresnel-weighted albedo to the white one. Its nodes sit at roughness and cosine
// clamp(k/15, 1e-4, 1) and z = clamp(k/15, 1e-4, 0.99), eta = (1 + z^2) / (1 - z^2); here they are integrated by
// quadrature, once per process, and read trilinearly (cycles_lookup_table.h). The coat's exact dielectric Fresnel
// (index > 1) uses the same table with f0 = F0(eta).
#pragma once

#include <Eigen/Core>

namespace skinlayer {

using Rgb = Eigen::Array3d;

// bsdf_util.h's ior_from_F0, which clamps F0 to [0, 0.99]; its F0_from_ior is normal_reflectance
// (core/targets/fresnel_terms.h).
double cycles_ior_from_f0(double f0);

// s(c) above: the share of the way from F0 to white at the cosine c between light and half vector.
double cycles_fresnel_blend(double cos_ih, double eta);

// s_bar(r, mu, eta): the table read; and the integral it tabulates, at any point (for the tests).
double cycles_ggx_fresnel_blend(double roughness, double mu, double eta);
double ggx_visible_fresnel_blend(double roughness, double mu, double eta, int polar = 32);

// Cycles' albedo estimate of the Principled specular, mix(f0, 1, s_bar); and of the coat (exact dielectric Fresnel
// of index eta >= 1), mix(F0(eta), 1, s_bar), 0 at eta = 1.
Rgb cycles_principled_fresnel_estimate(double roughness, double mu, double eta, const Rgb& f0);
double cycles_dielectric_fresnel_estimate(double roughness, double mu, double eta);

}  // namespace skinlayer
