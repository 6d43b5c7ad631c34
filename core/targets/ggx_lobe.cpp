// docs/model.md §22.1: the GGX lobe, and the albedo of a lobe on half vectors.
#include "core/targets/ggx_lobe.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/series/quadrature.h"

namespace skinlayer {

double ggx_masking(double mu, double alpha) {
  const double tan2 = (1.0 - mu * mu) / (mu * mu);
  return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

double ggx_height_correlated_masking(double mu_i, double mu_o, double alpha) {
  const auto lambda = [alpha](double mu) {
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * (1.0 - mu * mu) / (mu * mu)) - 1.0);
  };
  return 1.0 / (1.0 + lambda(mu_i) + lambda(mu_o));
}

double ggx_distribution(double cos_m, double alpha) {
  const double cos2 = cos_m * cos_m, tan2 = (1.0 - cos2) / cos2, a2 = alpha * alpha;
  return a2 / (kPi * cos2 * cos2 * (a2 + tan2) * (a2 + tan2));
}

Rgb microfacet_lobe_albedo(const std::function<Rgb(const Vec3& omega_o)>& lobe, const Vec3& omega_i, double width,
                           int polar) {
  // The polar rule is computed once on [0, 1] and mapped onto each azimuth's [0, v_max] (as integrate_mapped does).
  const QuadratureRule phi = gauss_legendre(2 * polar, 0.0, 2.0 * kPi), unit = gauss_legendre(polar, 0.0, 1.0);
  const double sin_i = std::sqrt(std::max(0.0, 1.0 - omega_i.z() * omega_i.z()));
  const double phi_i = std::atan2(omega_i.y(), omega_i.x());
  Rgb sum = Rgb::Zero();
  for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
    const double theta_max = 0.5 * (0.5 * kPi + std::atan2(sin_i * std::cos(phi.nodes[b] - phi_i), omega_i.z()));
    const double v_max = 2.0 * kInvPi * std::atan(std::tan(theta_max) / width);
    for (std::size_t a = 0; a < unit.nodes.size(); ++a) {
      const double v = v_max * unit.nodes[a], t = std::tan(0.5 * kPi * v), theta = std::atan(width * t);
      const double dtheta_dv = width * 0.5 * kPi * (1.0 + t * t) / (1.0 + width * width * t * t);
      const Vec3 h(std::sin(theta) * std::cos(phi.nodes[b]), std::sin(theta) * std::sin(phi.nodes[b]), std::cos(theta));
      const double cos_ih = omega_i.dot(h);
      if (cos_ih <= 0.0) continue;
      const Vec3 omega_o = 2.0 * cos_ih * h - omega_i;
      const double w = v_max * unit.weights[a] * dtheta_dv * std::sin(theta) * phi.weights[b] * 4.0 * cos_ih;
      sum += w * lobe(omega_o);
    }
  }
  return sum;
}

}  // namespace skinlayer
