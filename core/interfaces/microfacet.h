// Beckmann microfacet statistics and the rough-dielectric BRDF and BTDF built from them
// (Cook & Torrance 1982; Walter, Marschner, Li & Torrance 2007; Stam 2001's "generalised Cook-Torrance" BTDF).
//
// Geometry: the macro normal is +z. A dielectric interface separates a medium of index n_above (z > 0) from one of
// index n_below; eta = n_below / n_above. Directions are unit vectors pointing away from the surface (graphics
// convention, core/conventions.h). All BSDFs here are in 1/sr and not cosine-weighted.
#pragma once

#include <Eigen/Core>

#include "core/interfaces/microfacet_model.h"

namespace skinlayer {

using Vec3 = Eigen::Vector3d;

// Beckmann distribution of microfacet normals h, with sigma the RMS slope magnitude (Beckmann alpha):
//   D(h) = exp(-tan^2(alpha) / sigma^2) / (pi sigma^2 cos^4(alpha)),   alpha = angle(h, n),
// normalized so that the projected area integrates to one: int D(h) cos(alpha) d omega_h = 1.  [1/sr]
double beckmann_ndf(double cos_alpha, double sigma);

// Smith masking for the Beckmann distribution, exact form (Walter et al. 2007, eq. 27):
//   a = 1/(sigma tan(theta)),  Lambda(a) = (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi)),  G1 = 1/(1 + Lambda(a)).
// cos_theta is the cosine between the direction and the macro normal (its sign is ignored).
double smith_g1_beckmann(double cos_theta, double sigma);

struct RoughDielectric {
  double eta = 1.4;    // n_below / n_above
  double sigma = 0.5;  // Beckmann RMS slope
  MicrofacetModel microfacet = MicrofacetModel::Single;  // the masking-shadowing form (smith_masking.h), and more

  bool operator==(const RoughDielectric&) const = default;
};

// The angular width of the interface's refraction lobe on the denser side, w = sigma (1 - 1/n) radians with
// n = max(eta, 1/eta): a facet tilted by sigma turns the refracted ray by that much less than it turns the normal.
double refracted_lobe_width(const RoughDielectric& interface);

// Reflection on either side:
//   f_r = F(|wi.h|, eta_rel) D(h) G2(wi, wo) / (4 |wi.n| |wo.n|),  h = normalize(wi + wo) (flipped to h.n > 0),
// with eta_rel = n_other_side / n_this_side and G2 the interface's masking-shadowing (smith_masking.h: G1(wi) G1(wo)
// under MicrofacetModel::Single). Zero unless wi and wo lie on the same side.
double microfacet_brdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo);

// Transmission from wi's side to wo's side (eta_t = n_wo_side / n_wi_side):
//   h = -normalize(wi + eta_t wo) (flipped to h.n > 0),
//   f_t = |wi.h| |wo.h| eta_t^2 (1 - F(|wi.h|, eta_t)) D(h) G2(wi, wo) / (|wi.n| |wo.n| (wi.h + eta_t wo.h)^2).
// The eta_t^2 factor is the radiance scaling: f_t is a radiance BTDF, and int f_t |wo.n| d omega_o is the transmitted
// energy fraction. Zero when either direction sees the back of h, under total internal reflection, when wi and wo
// lie on the same side, and at eta = 1 (there the interface is absent and all light passes as an unscattered beam,
// which the caller handles; no BSDF value can hold a delta).
double microfacet_btdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo);

// microfacet_brdf + microfacet_btdf: the full BSDF of the interface for any pair of directions.
double rough_dielectric_bsdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo);

// The same three functions with the macro-surface Smith factors g1_wi = G1(wi) and g1_wo = G1(wo) supplied: they
// depend only on the directions' polar angles, so a caller sweeping azimuth computes them once.
double microfacet_brdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo, double g1_wi, double g1_wo);
double microfacet_btdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo, double g1_wi, double g1_wo);
double rough_dielectric_bsdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo, double g1_wi,
                             double g1_wo);

// A unit direction from polar angle theta (from +z) and azimuth phi, radians.
Vec3 direction_from_angles(double theta, double phi);

}  // namespace skinlayer
