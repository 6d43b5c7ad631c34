// docs/model.md §22.3: GGX dielectric reflection with Turquin's energy compensation, as MaterialX's graph has it.
#include "core/targets/ggx_dielectric_reflection.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/material.h"
#include "core/targets/fresnel_terms.h"
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

// MaterialX's fit, numerators and denominators of a and b: each the sum over the monomials m(mu, alpha) below of
// its coefficient times m. Monomials in the order 1, mu, alpha, mu alpha, mu^2, alpha^2, mu^2 alpha, mu alpha^2,
// mu^2 alpha^2; the columns are a's numerator, b's numerator, a's denominator, b's denominator.
constexpr std::array<std::array<double, 4>, 9> kAlbedoFit = {{
    {0.1003, 0.9345, 1.0, 1.0},
    {-0.6303, -2.323, -1.765, 0.2281},
    {9.748, 2.229, 8.263, 15.94},
    {-2.038, -3.748, 11.53, -55.83},
    {29.34, 1.424, 28.96, 13.08},
    {-8.245, -0.7684, -7.507, 41.26},
    {-26.44, 1.436, -36.11, 54.9},
    {19.99, 0.2913, 15.86, 300.2},
    {-5.448, 0.6286, 33.37, -285.1},
}};

// MaterialX clamps alpha to [1e-8, 1] before the fit (its M_FLOAT_EPS).
constexpr double kFitSmallestAlpha = 1e-8;

}  // namespace

GgxAlbedoTerms materialx_ggx_albedo_terms(double mu, double alpha) {
  const double x = std::clamp(mu, 0.0, 1.0), y = std::clamp(alpha, kFitSmallestAlpha, 1.0);
  const std::array<double, 9> monomials = {1.0, x, y, x * y, x * x, y * y, x * x * y, x * y * y, x * x * y * y};
  std::array<double, 4> sums{};
  for (std::size_t m = 0; m < monomials.size(); ++m) {
    for (std::size_t k = 0; k < 4; ++k) sums[k] += kAlbedoFit[m][k] * monomials[m];
  }
  return {std::clamp(sums[0] / sums[2], 0.0, 1.0), std::clamp(sums[1] / sums[3], 0.0, 1.0)};
}

GgxDielectricReflection::GgxDielectricReflection(double eta, double alpha) : eta_(eta), alpha_(alpha) {
  if (!(eta > 0.0) || !std::isfinite(eta)) throw ParameterError("GGX reflection: eta must be positive");
  if (!(alpha >= 0.0) || !std::isfinite(alpha)) throw ParameterError("GGX reflection: alpha must be >= 0");
  f0_ = normal_reflectance(eta);
  for (int k = 0; k < kAngles; ++k) {
    const double theta = std::min(k * kAngleStep, degrees_to_radians(89.9));
    const Vec3 view(std::sin(theta), 0.0, std::cos(theta));
    if (smooth()) {
      fresnel_[static_cast<std::size_t>(k)] = fresnel_dielectric(view.z(), eta);
      continue;
    }
    // Reciprocal: the albedo at the view is the integral over the light of the same single-scattering lobe.
    const Rgb single = microfacet_lobe_albedo(
        [&](const Vec3& light) {
          const double cos_h = std::max(0.0, light.dot((light + view).normalized()));
          return Rgb(single_scattering(alpha, light, view, fresnel_dielectric(cos_h, eta)), 0.0, 0.0);
        },
        view, alpha, 16);
    fresnel_[static_cast<std::size_t>(k)] = single(0);
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
  const GgxAlbedoTerms fit = materialx_ggx_albedo_terms(mu_o, alpha_);
  const double white = fit.a + fit.b;
  return 1.0 + fresnel_dielectric(std::clamp(mu_o, 0.0, 1.0), eta_) * (1.0 - white) / white;
}

double GgxDielectricReflection::cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const {
  if (smooth() || !(omega_i.z() > 0.0 && omega_o.z() > 0.0)) return 0.0;
  const double cos_h = omega_i.dot((omega_i + omega_o).normalized());
  return single_scattering(alpha_, omega_i, omega_o, fresnel_dielectric(cos_h, eta_)) * compensation(omega_o.z());
}

double GgxDielectricReflection::albedo(double mu_o) const { return compensation(mu_o) * interpolate(fresnel_, mu_o); }

double GgxDielectricReflection::layer_albedo(double mu_o) const {
  const GgxAlbedoTerms fit = materialx_ggx_albedo_terms(mu_o, alpha_);
  return compensation(mu_o) * (f0_ * fit.a + fit.b);
}

}  // namespace skinlayer
