#include "core/interface_albedo.h"

#include <cmath>

#include "core/conventions.h"
#include "core/fresnel.h"
#include "core/quadrature.h"

namespace skinlayer {

InterfaceAlbedo interface_albedo(const RoughDielectric& interface, const Vec3& wi, int radial_nodes,
                                 int azimuth_nodes) {
  if (interface.eta == 1.0) return {0.0, 1.0};
  const double side = wi.z() > 0.0 ? 1.0 : -1.0;
  const double eta_t = side > 0.0 ? interface.eta : 1.0 / interface.eta;
  const QuadratureRule radial = gauss_legendre(radial_nodes, 0.0, 1.0);
  // wi lies in a plane containing the normal; the integrand is even in the slope azimuth about that plane, so
  // integrate over [0, pi] and double.
  const QuadratureRule azimuthal = gauss_legendre(azimuth_nodes, 0.0, kPi);
  const double azimuth_of_wi = std::atan2(wi.y(), wi.x());
  const double sigma = interface.sigma;
  const double g1_in = smith_g1_beckmann(wi.z(), sigma);
  double reflectance = 0.0;
  double transmittance = 0.0;
  for (int a = 0; a < radial.size(); ++a) {
    const double r = sigma * std::sqrt(-std::log1p(-radial.nodes[a]));
    for (int b = 0; b < azimuthal.size(); ++b) {
      const double weight = radial.weights[a] * azimuthal.weights[b] / kPi;
      // Microfacet normal on wi's side: slopes (p, q) = r (cos psi, sin psi), h ~ (-p, -q, 1).
      const double psi = azimuthal.nodes[b] + azimuth_of_wi;
      Vec3 h(-r * std::cos(psi), -r * std::sin(psi), 1.0);
      h.normalize();
      h *= side;
      const double cos_i = wi.dot(h);
      if (cos_i <= 0.0) continue;  // wi sees the back of this facet
      const double common = g1_in * cos_i / (std::abs(wi.z()) * std::abs(h.z())) * weight;
      const double fresnel = fresnel_dielectric(cos_i, eta_t);
      // Reflection: wo = 2 (wi.h) h - wi must leave on wi's side and see the front of h.
      const Vec3 wo_r = 2.0 * cos_i * h - wi;
      if (wo_r.z() * side > 0.0) reflectance += fresnel * smith_g1_beckmann(wo_r.z(), sigma) * common;
      // Refraction (Snell at the facet).
      const double sin2_t = (1.0 - cos_i * cos_i) / (eta_t * eta_t);
      if (sin2_t < 1.0 && fresnel < 1.0) {
        const double cos_t = std::sqrt(1.0 - sin2_t);
        const Vec3 wo_t = -wi / eta_t + (cos_i / eta_t - cos_t) * h;
        if (wo_t.z() * side < 0.0) transmittance += (1.0 - fresnel) * smith_g1_beckmann(wo_t.z(), sigma) * common;
      }
    }
  }
  return {reflectance, transmittance};
}

}  // namespace skinlayer
