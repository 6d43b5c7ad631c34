#include "core/interfaces/microfacet.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/interfaces/smith_masking.h"

namespace skinlayer {
namespace {

// Whether w sees the front of the microfacet h (Smith's local masking: zero if w sees its back).
bool sees_front(const Vec3& w, const Vec3& h) { return w.dot(h) * w.z() > 0.0; }

}  // namespace

double beckmann_ndf(double cos_alpha, double sigma) {
  if (cos_alpha <= 0.0) return 0.0;
  const double cos2 = cos_alpha * cos_alpha;
  const double tan2 = (1.0 - cos2) / cos2;
  const double sigma2 = sigma * sigma;
  return std::exp(-tan2 / sigma2) / (kPi * sigma2 * cos2 * cos2);
}

double smith_g1_beckmann(double cos_theta, double sigma) {
  const double c = std::min(std::abs(cos_theta), 1.0);
  const double sin_theta = std::sqrt(1.0 - c * c);
  if (sin_theta == 0.0) return 1.0;
  if (c == 0.0) return 0.0;
  const double a = c / (sigma * sin_theta);  // 1 / (sigma tan theta)
  if (a > 30.0) return 1.0;                  // Lambda < 1e-390: underflows to exactly 0 anyway
  const double lambda = 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * std::sqrt(kPi));
  return 1.0 / (1.0 + lambda);
}

double microfacet_brdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo) {
  return microfacet_brdf(interface, wi, wo, smith_g1_beckmann(wi.z(), interface.sigma),
                         smith_g1_beckmann(wo.z(), interface.sigma));
}

double microfacet_brdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo, double g1_wi, double g1_wo) {
  if (wi.z() * wo.z() <= 0.0) return 0.0;
  if (interface.eta == 1.0) return 0.0;  // F = 0 exactly: no interface
  Vec3 h = wi + wo;
  const double length = h.norm();
  if (length == 0.0) return 0.0;
  h /= length;
  if (h.z() < 0.0) h = -h;
  const double eta_rel = wi.z() > 0.0 ? interface.eta : 1.0 / interface.eta;
  const double c = std::abs(wi.dot(h));
  if (!sees_front(wi, h) || !sees_front(wo, h)) return 0.0;
  const double g = smith_g2_reflection(g1_wi, g1_wo, interface.microfacet);
  if (g == 0.0) return 0.0;
  return fresnel_dielectric(c, eta_rel) * beckmann_ndf(h.z(), interface.sigma) * g /
         (4.0 * std::abs(wi.z()) * std::abs(wo.z()));
}

double microfacet_btdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo) {
  return microfacet_btdf(interface, wi, wo, smith_g1_beckmann(wi.z(), interface.sigma),
                         smith_g1_beckmann(wo.z(), interface.sigma));
}

double microfacet_btdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo, double g1_wi, double g1_wo) {
  if (wi.z() * wo.z() >= 0.0) return 0.0;
  if (interface.eta == 1.0) return 0.0;
  const double eta_t = wi.z() > 0.0 ? interface.eta : 1.0 / interface.eta;
  Vec3 h = -(wi + eta_t * wo);
  h.normalize();
  if (h.z() < 0.0) h = -h;
  const double i_h = wi.dot(h);
  const double o_h = wo.dot(h);
  if (!sees_front(wi, h) || !sees_front(wo, h)) return 0.0;
  const double g = smith_g2_transmission(g1_wi, g1_wo, interface.microfacet);
  if (g == 0.0) return 0.0;
  const double fresnel = fresnel_dielectric(i_h, eta_t);
  if (fresnel >= 1.0) return 0.0;
  const double denominator = i_h + eta_t * o_h;
  return std::abs(i_h) * std::abs(o_h) * eta_t * eta_t * (1.0 - fresnel) * beckmann_ndf(h.z(), interface.sigma) * g /
         (std::abs(wi.z()) * std::abs(wo.z()) * denominator * denominator);
}

double rough_dielectric_bsdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo) {
  return rough_dielectric_bsdf(interface, wi, wo, smith_g1_beckmann(wi.z(), interface.sigma),
                               smith_g1_beckmann(wo.z(), interface.sigma));
}

double rough_dielectric_bsdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo, double g1_wi,
                             double g1_wo) {
  return wi.z() * wo.z() > 0.0 ? microfacet_brdf(interface, wi, wo, g1_wi, g1_wo)
                               : microfacet_btdf(interface, wi, wo, g1_wi, g1_wo);
}

double refracted_lobe_width(const RoughDielectric& interface) {
  const double n = std::max(interface.eta, 1.0 / interface.eta);
  return interface.sigma * (1.0 - 1.0 / n);
}

Vec3 direction_from_angles(double theta, double phi) {
  const double s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

}  // namespace skinlayer
