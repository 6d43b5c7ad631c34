// glTF's sheen lobe as three.js evaluates it.
#include "core/targets/charlie_sheen.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"

namespace skinlayer {

double charlie_sheen_distribution(double cos_h, double roughness) {
  const double r = std::max(roughness, kLeastSheenRoughness);
  const double inverse_alpha = 1.0 / (r * r);
  // three.js keeps sin^2 at 2^-7 or above (so that its square stays a normal half float); the same here.
  const double sin2 = std::max(1.0 - cos_h * cos_h, 0.0078125);
  return (2.0 + inverse_alpha) * std::pow(sin2, 0.5 * inverse_alpha) / (2.0 * kPi);
}

double ashikhmin_sheen_visibility(double mu_i, double mu_o) {
  return std::min(1.0, 1.0 / (4.0 * (mu_i + mu_o - mu_i * mu_o)));
}

double charlie_sheen_cosine_weighted(double roughness, const Vec3& omega_i, const Vec3& omega_o) {
  const double mu_i = omega_i.z(), mu_o = omega_o.z();
  if (!(mu_i > 0.0 && mu_o > 0.0)) return 0.0;
  const double cos_h = std::clamp((omega_i + omega_o).normalized().z(), 0.0, 1.0);
  return charlie_sheen_distribution(cos_h, roughness) * ashikhmin_sheen_visibility(mu_i, mu_o) * mu_i;
}

double threejs_sheen_albedo(double mu, double roughness) {
  const double r = roughness, r2 = r * r, inverse = 1.0 / (r + 0.1);
  const double a = -1.9362 + 1.0678 * r + 0.4573 * r2 - 0.8469 * inverse;
  const double b = -0.6014 + 0.5538 * r - 0.4670 * r2 - 0.1255 * inverse;
  return std::clamp(std::exp(a * std::clamp(mu, 0.0, 1.0) + b), 0.0, 1.0);
}

}  // namespace skinlayer
