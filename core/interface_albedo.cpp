#include "core/interface_albedo.h"

#include <cmath>

#include "core/conventions.h"
#include "core/fresnel.h"
#include "core/quadrature.h"

namespace skinlayer {
namespace {

// The slope grid: Gauss-Legendre in u = 1 - exp(-r^2/sigma^2) (radial) and in the slope azimuth psi over [0, pi]
// (measured from wi's azimuth), with the weights of the Gaussian slope density folded in.
struct SlopeGrid {
  std::vector<double> slope;         // r at each radial node
  std::vector<double> inverse_norm;  // 1 / sqrt(1 + r^2): |(-p, -q, 1)| = sqrt(1 + r^2)
  std::vector<double> radial_weight;
  std::vector<double> cos_psi, sin_psi, azimuth_weight;
};

SlopeGrid slope_grid(double sigma, int radial_nodes, int azimuth_nodes) {
  const QuadratureRule radial = gauss_legendre(radial_nodes, 0.0, 1.0);
  const QuadratureRule azimuthal = gauss_legendre(azimuth_nodes, 0.0, kPi);
  SlopeGrid grid;
  for (int a = 0; a < radial.size(); ++a) {
    const double r = sigma * std::sqrt(-std::log1p(-radial.nodes[a]));
    grid.slope.push_back(r);
    grid.inverse_norm.push_back(1.0 / std::sqrt(1.0 + r * r));
    grid.radial_weight.push_back(radial.weights[a]);
  }
  for (int b = 0; b < azimuthal.size(); ++b) {
    grid.cos_psi.push_back(std::cos(azimuthal.nodes[b]));
    grid.sin_psi.push_back(std::sin(azimuthal.nodes[b]));
    grid.azimuth_weight.push_back(azimuthal.weights[b] / kPi);
  }
  return grid;
}

InterfaceAlbedo integrate(const RoughDielectric& interface, const Vec3& wi, const SlopeGrid& grid) {
  if (interface.eta == 1.0) return {0.0, 1.0};
  const double side = wi.z() > 0.0 ? 1.0 : -1.0;
  const double eta_t = side > 0.0 ? interface.eta : 1.0 / interface.eta;
  // wi lies in a plane containing the normal; the integrand is even in the slope azimuth about that plane, so
  // integrate over [0, pi] (from wi's azimuth) and double (the weights above are already over pi).
  const double azimuth_of_wi = std::atan2(wi.y(), wi.x());
  const double cos_wi = std::cos(azimuth_of_wi), sin_wi = std::sin(azimuth_of_wi);
  const double sigma = interface.sigma;
  const double g1_in = smith_g1_beckmann(wi.z(), sigma);
  double reflectance = 0.0;
  double transmittance = 0.0;
  for (std::size_t a = 0; a < grid.slope.size(); ++a) {
    const double r = grid.slope[a];
    for (std::size_t b = 0; b < grid.cos_psi.size(); ++b) {
      const double weight = grid.radial_weight[a] * grid.azimuth_weight[b];
      // Microfacet normal on wi's side: slopes (p, q) = r (cos psi, sin psi), h ~ (-p, -q, 1).
      const double cos_psi = grid.cos_psi[b] * cos_wi - grid.sin_psi[b] * sin_wi;
      const double sin_psi = grid.sin_psi[b] * cos_wi + grid.cos_psi[b] * sin_wi;
      const Vec3 h = side * grid.inverse_norm[a] * Vec3(-r * cos_psi, -r * sin_psi, 1.0);
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

}  // namespace

InterfaceAlbedo interface_albedo(const RoughDielectric& interface, const Vec3& wi, int radial_nodes,
                                 int azimuth_nodes) {
  return interface_albedo(interface, std::span<const Vec3>(&wi, 1), radial_nodes, azimuth_nodes).front();
}

std::vector<InterfaceAlbedo> interface_albedo(const RoughDielectric& interface, std::span<const Vec3> wi,
                                              int radial_nodes, int azimuth_nodes) {
  const SlopeGrid grid = slope_grid(interface.sigma, radial_nodes, azimuth_nodes);
  std::vector<InterfaceAlbedo> result;
  result.reserve(wi.size());
  for (const Vec3& w : wi) result.push_back(integrate(interface, w, grid));
  return result;
}

}  // namespace skinlayer
