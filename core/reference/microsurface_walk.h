// The microsurface random walk of Heitz, Hanika, d'Eon & Dachsbacher 2016 ("Multiple-Scattering Microfacet BSDFs
// with the Smith Model", SIGGRAPH), for a rough dielectric interface with Beckmann slopes: an independent reference
// for what light does on the interface when it may meet the microsurface more than once. It shares only the Fresnel
// reflectance (core/interfaces/fresnel.h) with the solver; the Smith statistics are written here from the paper.
//
// The Smith microsurface is a random height field whose slopes are Beckmann (independent of height) and whose heights
// follow a distribution P1 with cumulative C1; the walk's result does not depend on P1, and the uniform distribution
// on [-1, 1] is used (C1(h) = (h + 1) / 2). For a direction w with polar cosine mu (w.z), Smith's
//   Lambda(w) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)),   a = mu / (sigma sqrt(1 - mu^2)),
// which for a downward direction (a < 0) is -1 - Lambda(-w). A ray at height h going up leaves the microsurface
// with probability C1(h)^Lambda(w) (the height-correlated G1); otherwise it meets it at the height h' with
// C1(h') = C1(h) / U^(1 / Lambda(w)), U uniform. A ray going down always meets it, the same formula giving h'.
// At each meeting a microfacet normal m is drawn from the distribution of normals visible from the ray,
//   D_w(m) = G1(w) max(0, w.m) D(m) / w.z   (Heitz & d'Eon 2014),
// and the ray is reflected about m with probability F(w.m), refracted through it otherwise; a refracted ray walks on
// the other side, where the microsurface is the same height field seen from below (heights and z negated).
//
// Directions point away from the surface (graphics convention, core/conventions.h). Light arrives from wi's side:
// wi.z > 0 is light from above (the medium of index n_above), wi.z < 0 from below. The walk ends where the ray leaves
// the microsurface: above (reflected, for light from above) or below.
//
// Its single-scattering part (paths with one meeting) is the height-correlated microfacet BSDF (Heitz 2014,
// "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs"):
//   reflection    f_r = F D(h) G2_r / (4 |wi.z| |wo.z|),               G2_r = 1 / (1 + Lambda(wi) + Lambda(wo))
//   transmission  f_t = (the microfacet_btdf form) with G2_t = B(1 + Lambda(wi), 1 + Lambda(-wo)),
// B the Beta function, where the solver's separable Smith form uses G1(wi) G1(wo) = 1 / ((1 + Lambda(wi))(1 +
// Lambda(wo))) in both. In reflection the correlated G2 is the larger: a point visible from two directions on one side
// is likely high, and seen from one it is more likely seen from the other. In transmission it is the smaller: a
// point seen from above is likely high and one seen from below likely low. So the walk reflects more and transmits
// less in single scattering than the separable BSDF (at sigma 0.5, eta 1.4, from inside at 60 degrees the two lose
// about the same in all), and it returns through higher orders whatever single scattering loses.
#pragma once

#include <cstdint>
#include <random>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

// Smith's Lambda for Beckmann slopes of RMS sigma, for any direction (w.z of either sign; 0 straight up, -1 down).
double beckmann_lambda(const Vec3& w, double sigma);

// The height-correlated single-scattering BSDF of the interface (the walk's first order), in 1/sr, not cosine-
// weighted: reflection when wi and wo lie on one side, transmission otherwise (eta^2 radiance scaling as in
// microfacet_btdf). Zero at eta = 1.
double height_correlated_bsdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo);

struct MicrosurfaceExit {
  Vec3 direction;  // where the light leaves: z > 0 above, z < 0 below
  int order = 0;   // the number of times it met the microsurface (at least 1)
};

class MicrosurfaceWalk {
 public:
  explicit MicrosurfaceWalk(RoughDielectric interface);

  // One walk of light arriving along -wi (|wi| = 1, wi.z != 0). eta = 1 (no interface) passes it straight through
  // at order 1. A walk longer than kMaxOrder meetings (none in practice: the mean order stays below 10) ends where
  // it stands.
  MicrosurfaceExit walk(const Vec3& wi, std::mt19937_64& random) const;

  static constexpr int kMaxOrder = 10000;

 private:
  // A normal visible from w (w.z > 0, the walk's frame with the microsurface below it), drawn from D_w(m).
  Vec3 visible_normal(const Vec3& w, std::mt19937_64& random) const;

  RoughDielectric interface_;
};

}  // namespace skinlayer
