// Blender 3.4's Principled BSDF, as Cycles evaluates it, for the opaque parts a fit uses (docs/model.md §22.1): the
// target whose parameters `skinlayer fit --target principled` will choose. Written from the Principled closure's
// setup and the closures it makes in Blender 3.4.1's Cycles kernel (svm/closure.h, closure/bsdf_principled_diffuse.h,
// bsdf_principled_sheen.h, bsdf_microfacet.h), with the node's "GGX" distribution, whose specular is the
// single-scattering GGX lobe that Cycles evaluates in closed form ("Multiscatter GGX" is a stochastic walk).
//
// With weights w_d = (1 - metallic)(1 - transmission) and w_s = 1 - transmission (1 - metallic), the BRDF is a sum of
// lobes, each evaluated for light from omega_i seen from omega_o (both away from the surface, graphics convention):
//   diffuse   w_d C f_d,            f_d cos_i = (1/pi) cos_i [(1 - F_o/2)(1 - F_i/2) + R (F_i + F_o + F_i F_o (R -
//   1))],
//             F_x = (1 - cos_x)^5 (Schlick's weight), R = roughness (omega_i.omega_o + 1) (Burley 2012's
//             retro-reflection, with 2 (omega_i.h)^2 written as omega_i.omega_o + 1);
//   sheen     w_d sheen C_sheen,    f cos_i = (1 - omega_i.h)^5 cos_i (no 1/pi: as Cycles has it);
//   specular  w_s,                  f cos_i = F(omega_i.h) G1(omega_i) G1(omega_o) D(h) / (4 cos_o), GGX with
//             alpha = roughness^2, the Fresnel blend F = c0 (1 - t) + t, t = (F_eta(omega_i.h) - F_eta(1)) /
//             (1 - F_eta(1)), eta = 2 / (1 - sqrt(0.08 specular)) - 1 (so that F_eta(1) = 0.08 specular), and
//             c0 = 0.08 specular tint (1 - metallic) + C metallic;
//   clearcoat 1,                    the same with Berry's GTR1 distribution at alpha = clearcoat_roughness^2, Smith
//             masking at a fixed alpha of 0.25, eta 1.5, c0 0.04, times 0.25 clearcoat.
// C is the base colour; the tints mix white with the base colour divided by its luminance (0.3, 0.6, 0.1 for the
// specular tint, Rec. 709's for the sheen tint). Subsurface scattering, at the BRDF's scale (a flat surface, light
// leaving where it entered), is the diffuse lobe with the colour mix(C, subsurface_color, subsurface): Cycles swaps
// the diffuse closure for a BSSRDF whose entry and exit weights are the lobe's Lambertian part, (1 - F_o/2) and
// (1 - F_i/2) cos_i / pi, keeps the retro-reflection as a closure of its own, and sets the walk's albedo so that a
// flat half-space reflects the colour (svm/closure.h, closure/bssrdf.h). Its radius does not enter the BRDF.
// Measured in Blender 3.4's random walk, a sphere of radius 500 mean free paths renders 2-5% brighter than this.
// Transmission t (with w_t = t (1 - metallic)) is Cycles' single-scattering glass (svm/closure.h): a reflection
//   glass      w_t F_ior(cos_o) F_c(omega_i.h) G1(omega_i) G1(omega_o) D(h) / (4 cos_o),  GGX, alpha = r^2,
// with F_c the Fresnel blend toward white from c0 = C tint + (1 - tint) (the specular tint), weighted by the
// dielectric Fresnel of the node's IOR at the view's angle (so the BRDF is no longer reciprocal); and a refraction,
// the BTDF below (principled_btdf_cosine_weighted). Anisotropy is not here yet: it must be 0.
#pragma once

#include <Eigen/Core>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

using Rgb = Eigen::Array3d;

// The node's inputs, with Blender 3.4's defaults.
struct PrincipledParameters {
  Rgb base_color = Rgb(0.8, 0.8, 0.8);
  double metallic = 0.0;
  double specular = 0.5;
  double specular_tint = 0.0;
  double roughness = 0.5;
  double sheen = 0.0;
  double sheen_tint = 0.5;
  double clearcoat = 0.0;
  double clearcoat_roughness = 0.03;
  double ior = 1.45;  // the glass's index (transmission only)
  double transmission = 0.0;
  double transmission_roughness = 0.0;
  double subsurface = 0.0;
  Rgb subsurface_color = Rgb(0.8, 0.8, 0.8);
  Rgb subsurface_radius = Rgb(1.0, 0.2, 0.1);  // scene units (Blender's: metres); no part of the BRDF
  double subsurface_anisotropy = 0.0;          // the walk's Henyey-Greenstein g; no part of the BRDF
  double anisotropic = 0.0;                    // must be 0 for now
};

// The lobes apart, each already weighted as in the sum above; f times cos(theta_i), per RGB channel (1/sr times the
// cosine: dimensionless per steradian). omega_i and omega_o are unit vectors; either below the surface gives 0.
struct PrincipledLobes {
  Rgb diffuse = Rgb::Zero(), sheen = Rgb::Zero(), specular = Rgb::Zero(), clearcoat = Rgb::Zero();
  Rgb glass = Rgb::Zero();  // the transmission's reflection
  Rgb sum() const { return diffuse + sheen + specular + clearcoat + glass; }
};
PrincipledLobes principled_lobes_cosine_weighted(const PrincipledParameters& parameters, const Vec3& omega_i,
                                                 const Vec3& omega_o);

// The directional albedo of each lobe at the view omega_i: int f(omega, omega_i) cos(theta) d omega, the light sent
// toward omega_i under a white sky (for the reciprocal lobes also the light reflected from a beam from omega_i);
// and their sum, the BRDF's. The
// diffuse and sheen lobes on `polar` Gauss-Legendre cosines times 2 `polar` azimuths of the view; the specular and
// clearcoat lobes over their half vectors, `polar` nodes following the lobe's width up to the horizon times 2 `polar`
// azimuths, so that sharp lobes converge as fast as rough ones.
PrincipledLobes principled_lobe_albedos(const PrincipledParameters& parameters, const Vec3& omega_i, int polar = 48);
Rgb principled_albedo(const PrincipledParameters& parameters, const Vec3& omega_i, int polar = 48);

// The whole BRDF, f (1/sr, not cosine-weighted), and f cos(theta_i). Throws ParameterError for a parameter outside
// [0, 1] (the node's ranges; a radius >= 0, an IOR > 0) or for anisotropy, not built yet.
Rgb principled_brdf(const PrincipledParameters& parameters, const Vec3& omega_i, const Vec3& omega_o);
Rgb principled_brdf_cosine_weighted(const PrincipledParameters& parameters, const Vec3& omega_i, const Vec3& omega_o);

// The transmission's refraction, as Cycles 3.4 evaluates it for light from omega_i below the surface (z < 0) seen
// from omega_o above (Walter et al. 2007's GGX BTDF, eq. 21, without its Fresnel factor, which the closure's weight
// carries): f |cos(theta_i)| = w_t C max(1e-4, 1 - F_ior(cos_o)) G1(omega_i) G1(omega_o) D(h) |omega_i.h| |omega_o.h|
// ior^2 / (cos_o |ior omega_i + omega_o|^2), h = -(ior omega_i + omega_o) normalized, GGX of roughness
// 1 - (1 - r)(1 - transmission_roughness). 0 unless omega_i is below and omega_o above.
Rgb principled_btdf_cosine_weighted(const PrincipledParameters& parameters, const Vec3& omega_i, const Vec3& omega_o);

}  // namespace skinlayer
