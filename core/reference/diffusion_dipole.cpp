#include "core/reference/diffusion_dipole.h"

#include <cmath>
#include <stdexcept>

#include "core/conventions.h"

namespace skinlayer {
namespace {

constexpr double kBoundaryFactor = 1.0;  // A: index-matched

struct Dipole {
  double alpha_prime, mu_eff, z0, zb;
};

Dipole dipole(double albedo, double g) {
  if (!(albedo >= 0.0 && albedo < 1.0) || !(std::abs(g) < 1.0)) {
    throw std::invalid_argument("diffusion dipole: albedo in [0, 1) and |g| < 1");
  }
  const double mu_a = 1.0 - albedo, mu_s_prime = albedo * (1.0 - g), mu_t_prime = mu_a + mu_s_prime;
  const double D = 1.0 / (3.0 * mu_t_prime);
  return {mu_s_prime / mu_t_prime, std::sqrt(mu_a / D), 1.0 / mu_t_prime, 2.0 * kBoundaryFactor * D};
}

}  // namespace

double diffusion_dipole_reflectance(double albedo, double g, double r) {
  const Dipole d = dipole(albedo, g);
  const double z_image = d.z0 + 2.0 * d.zb;
  const double r1 = std::hypot(d.z0, r), r2 = std::hypot(z_image, r);
  return d.alpha_prime / (4.0 * kPi) *
         (d.z0 * (d.mu_eff + 1.0 / r1) * std::exp(-d.mu_eff * r1) / (r1 * r1) +
          z_image * (d.mu_eff + 1.0 / r2) * std::exp(-d.mu_eff * r2) / (r2 * r2));
}

double diffusion_dipole_total_reflectance(double albedo, double g) {
  const Dipole d = dipole(albedo, g);
  const double root = std::sqrt(3.0 * (1.0 - d.alpha_prime));
  return 0.5 * d.alpha_prime * (1.0 + std::exp(-4.0 / 3.0 * kBoundaryFactor * root)) * std::exp(-root);
}

}  // namespace skinlayer
