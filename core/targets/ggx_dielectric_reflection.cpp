// docs/model.md §22.3: GGX dielectric reflection with Turquin's energy compensation.
#include "core/targets/ggx_dielectric_reflection.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/material.h"
#include "core/targets/ggx_lobe.h"

namespace skinlayer {
namespace {

constexpr double kAngleStep = 0.5 * kPi / (GgxDielectricReflection::kAngles - 1);

// f_ss cos(theta_i) with the Fresnel factor given.
double single_scattering(double alpha, const Vec3& omega_i, const Vec3& omega_o, double fresnel) {
  const Vec3 h = (omega_i + omega_o).normalized();
  return fresnel * ggx_distribution(h.z(), alpha) * ggx_height_correlated_masking(omega_i.z(), omega_o.z(), alpha) /
         (4.0 * omega_o.z());
}

}  // namespace

GgxDielectricReflection::GgxDielectricReflection(double eta, double alpha) : eta_(eta), alpha_(alpha) {
  if (!(eta > 0.0) || !std::isfinite(eta)) throw ParameterError("GGX reflection: eta must be positive");
  if (!(alpha >= 0.0) || !std::isfinite(alpha)) throw ParameterError("GGX reflection: alpha must be >= 0");
  const double f0 = fresnel_dielectric(1.0, eta);
  fresnel_average_ = f0 + (1.0 - f0) / 21.0;
  for (int k = 0; k < kAngles; ++k) {
    const double theta = std::min(k * kAngleStep, degrees_to_radians(89.9));
    const Vec3 view(std::sin(theta), 0.0, std::cos(theta));
    if (smooth()) {
      white_[static_cast<std::size_t>(k)] = 1.0;
      fresnel_[static_cast<std::size_t>(k)] = fresnel_dielectric(view.z(), eta);
      continue;
    }
    // Reciprocal: the albedo at the view is the integral over the light of the same single-scattering lobe.
    const Rgb both = microfacet_lobe_albedo(
        [&](const Vec3& light) {
          const double cos_h = std::max(0.0, light.dot((light + view).normalized()));
          return Rgb(single_scattering(alpha, light, view, 1.0),
                     single_scattering(alpha, light, view, fresnel_dielectric(cos_h, eta)), 0.0);
        },
        view, alpha, 16);
    white_[static_cast<std::size_t>(k)] = both(0);
    fresnel_[static_cast<std::size_t>(k)] = both(1);
  }
}

double GgxDielectricReflection::interpolate(const std::array<double, kAngles>& table, double mu) const {
  const double position = std::acos(std::clamp(mu, 0.0, 1.0)) / kAngleStep;
  const int k = std::min(static_cast<int>(position), kAngles - 2);
  const double t = position - k;
  const auto at = [&](int j) { return table[static_cast<std::size_t>(std::clamp(j, 0, kAngles - 1))]; };
  const double p0 = at(k - 1), p1 = at(k), p2 = at(k + 1), p3 = at(k + 2);
  return p1 + 0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + t * (3.0 * (p1 - p2) + p3 - p0)));
}

double GgxDielectricReflection::compensation(double mu_o) const {
  if (smooth()) return 1.0;
  const double white = interpolate(white_, mu_o);
  return 1.0 + fresnel_average_ * (1.0 - white) / white;
}

double GgxDielectricReflection::cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const {
  if (smooth() || !(omega_i.z() > 0.0 && omega_o.z() > 0.0)) return 0.0;
  const double cos_h = omega_i.dot((omega_i + omega_o).normalized());
  return single_scattering(alpha_, omega_i, omega_o, fresnel_dielectric(cos_h, eta_)) * compensation(omega_o.z());
}

double GgxDielectricReflection::albedo(double mu_o) const { return compensation(mu_o) * interpolate(fresnel_, mu_o); }

}  // namespace skinlayer
