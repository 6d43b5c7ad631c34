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
// Transmission and anisotropy are not here yet: their parameters must be 0.
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
  double transmission = 0.0;  // must be 0 for now
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
  Rgb sum() const { return diffuse + sheen + specular + clearcoat; }
};
PrincipledLobes principled_lobes_cosine_weighted(const PrincipledParameters& parameters, const Vec3& omega_i,
                                                 const Vec3& omega_o);

// The directional albedo of each lobe for light from omega_i, int f cos(theta_o) d omega_o (by reciprocity the
// cosine-weighted lobe with the two directions swapped, integrated over omega_o); and their sum, the BRDF's. The
// diffuse and sheen lobes on `polar` Gauss-Legendre cosines times 2 `polar` azimuths of the view; the specular and
// clearcoat lobes over their half vectors, `polar` nodes following the lobe's width up to the horizon times 2 `polar`
// azimuths, so that sharp lobes converge as fast as rough ones.
PrincipledLobes principled_lobe_albedos(const PrincipledParameters& parameters, const Vec3& omega_i, int polar = 48);
Rgb principled_albedo(const PrincipledParameters& parameters, const Vec3& omega_i, int polar = 48);

// The whole BRDF, f (1/sr, not cosine-weighted), and f cos(theta_i). Throws ParameterError for a parameter outside
// [0, 1] (the node's ranges; a radius >= 0) or for the parts not built yet (transmission, anisotropy).
Rgb principled_brdf(const PrincipledParameters& parameters, const Vec3& omega_i, const Vec3& omega_o);
Rgb principled_brdf_cosine_weighted(const PrincipledParameters& parameters, const Vec3& omega_i, const Vec3& omega_o);

}  // namespace skinlayer
