// docs/model.md §22.3: the energy-preserving Oren-Nayar diffuse (EON).
#include "core/targets/eon_diffuse.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"

namespace skinlayer {
namespace {

constexpr double kC1 = 0.5 - 2.0 / (3.0 * kPi);
constexpr double kC2 = 2.0 / 3.0 - 28.0 / (15.0 * kPi);

// Below this 1 - E_avg the multiple scattering has nothing to give back (sigma near 0, where E_FON is 1).
constexpr double kNoLoss = 1e-12;

Rgb multiple_scattering_albedo(const Rgb& albedo, double average) {
  return albedo.square() * average / (1.0 - albedo * (1.0 - average));
}

}  // namespace

double eon_single_scattering_albedo(double mu, double roughness) {
  const double A = 1.0 / (1.0 + kC1 * roughness);
  const double c = std::clamp(mu, 0.0, 1.0), s = std::sqrt(1.0 - c * c), theta = std::acos(c);
  // tan(theta) (1 - sin^3) = sin (1 - sin^3) / cos; 1 - sin^3 = (1 - sin)(1 + sin + sin^2) and 1 - sin = cos^2 /
  // (1 + sin), so the ratio stays finite at grazing: sin cos (1 + sin + sin^2) / (1 + sin).
  const double tan_term = s * c * (1.0 + s + s * s) / (1.0 + s);
  const double G = s * (theta - s * c) + (2.0 / 3.0) * (tan_term - s);
  return A + roughness * A * kInvPi * G;
}

double eon_average_single_scattering_albedo(double roughness) {
  return (1.0 + kC2 * roughness) / (1.0 + kC1 * roughness);
}

Rgb eon_diffuse_cosine_weighted(const Rgb& albedo, double roughness, const Vec3& omega_i, const Vec3& omega_o) {
  const double mu_i = omega_i.z(), mu_o = omega_o.z();
  if (!(mu_i > 0.0 && mu_o > 0.0)) return Rgb::Zero();
  const double A = 1.0 / (1.0 + kC1 * roughness);
  const double s = omega_i.dot(omega_o) - mu_i * mu_o;
  const double s_over_t = s > 0.0 ? s / std::max(mu_i, mu_o) : s;
  Rgb f = albedo * kInvPi * A * (1.0 + roughness * s_over_t);
  const double average = eon_average_single_scattering_albedo(roughness);
  if (1.0 - average > kNoLoss) {
    f += multiple_scattering_albedo(albedo, average) * kInvPi * (1.0 - eon_single_scattering_albedo(mu_i, roughness)) *
         (1.0 - eon_single_scattering_albedo(mu_o, roughness)) / (1.0 - average);
  }
  return f * mu_i;
}

Rgb eon_diffuse_albedo(const Rgb& albedo, double roughness, double mu) {
  const double single = eon_single_scattering_albedo(mu, roughness);
  return albedo * single +
         multiple_scattering_albedo(albedo, eon_average_single_scattering_albedo(roughness)) * (1.0 - single);
}

}  // namespace skinlayer
