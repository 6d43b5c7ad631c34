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
#include <functional>
#include <random>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

// Smith's Lambda for Beckmann slopes of RMS sigma, for any direction (w.z of either sign; 0 straight up, -1 down).
double beckmann_lambda(const Vec3& w, double sigma);

// The height-correlated single-scattering BSDF of the interface (the walk's first order), in 1/sr, not cosine-
// weighted: reflection when wi and wo lie on one side, transmission otherwise (eta^2 radiance scaling as in
// microfacet_btdf). Zero at eta = 1.
double height_correlated_bsdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo);

// The density, per steradian of the leaving direction o, with which light meeting the microsurface leaves one
// meeting in a direction it can escape along: the walk's scattering at a microfacet drawn from the normals visible
// from w (D_w, above), reflected with probability F and refracted otherwise,
//   reflected up (o.z > 0):     p = F(w.h) D(h) / (4 A(w)),                                h = (w + o) / |w + o|
//   refracted down (o.z < 0):   p = (1 - F(w.h)) D(h) (w.h) |o.h| e^2 / (A(w) (w.h + e o.h)^2),   h ~ -(w + e o)
// with A(w) = w.z (1 + Lambda(w)) = int max(0, w.m) D(m) dm the microsurface's area seen from w (w.z of either sign)
// and e the index beyond over the index of w's medium. All in the frame of the medium the light travels in (the
// microsurface below it): w points back along the ray, o away from the meeting. Light reflected down or refracted up
// (off a steep facet) travels down toward the microsurface on its side and meets it again for certain, and is left
// out: the density integrates to the share of the visible facets that send the light up or through. Built once per
// meeting (A(w) is an erfc and an exp), then evaluated at many o.
class MicrosurfaceScatterDensity {
 public:
  MicrosurfaceScatterDensity(const RoughDielectric& interface, bool from_above, const Vec3& w);
  double operator()(const Vec3& o) const;

 private:
  double sigma_, eta_, area_;
  Vec3 w_;
};

// One meeting of a walk with the microsurface, in the frame of the medium the ray travels in (z up there, the
// microsurface below): the direction back along the ray and the cumulative C1 of the meeting's height in that frame.
// From there the light leaves toward o (o.z > 0) meeting the microsurface no more with probability C1^Lambda(o) (the
// height-correlated G1 of Heitz 2014), and toward -o beyond it with (1 - C1)^Lambda(o) (the same height seen from
// the other side).
struct MicrosurfaceMeeting {
  int order = 0;          // 1 for the first meeting
  bool above = true;      // the ray travels in the medium above the microsurface
  Vec3 toward_source;     // -ray, in that medium's frame
  double height_cdf = 0;  // C1 of the meeting's height in that frame, in [0, 1]
};
using MeetingVisitor = std::function<void(const MicrosurfaceMeeting&)>;

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
  // The same walk, told of every meeting before the light scatters there (a null visitor is none).
  MicrosurfaceExit walk(const Vec3& wi, std::mt19937_64& random, const MeetingVisitor& visit) const;

  static constexpr int kMaxOrder = 10000;

 private:
  // A normal visible from w (w.z > 0, the walk's frame with the microsurface below it), drawn from D_w(m).
  Vec3 visible_normal(const Vec3& w, std::mt19937_64& random) const;

  RoughDielectric interface_;
};

}  // namespace skinlayer
