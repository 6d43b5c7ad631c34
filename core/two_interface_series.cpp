#include "core/two_interface_series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"
#include "core/fourier.h"
#include "core/quadrature.h"

namespace skinlayer {

namespace {

// Propagation cosines of directions travelling down at polar angles theta.
std::vector<double> downward(std::span<const double> theta) {
  std::vector<double> mu(theta.size());
  std::ranges::transform(theta, mu.begin(), [](double t) { return -std::cos(t); });
  return mu;
}

// The interface's transmission kernel between two lists of downward directions (fourier.h's propagation labels).
FourierKernel transmission_kernel(const RoughDielectric& interface, std::span<const double> mu_from,
                                  std::span<const double> mu_to, const CosineProjector& projector) {
  const auto pair = [&interface](const Vec3& wi, double mu_to_value) {
    const double g1_in = smith_g1_beckmann(wi.z(), interface.sigma);
    const double g1_out = smith_g1_beckmann(mu_to_value, interface.sigma);
    return
        [&interface, wi, g1_in, g1_out](const Vec3& wo) { return microfacet_btdf(interface, wi, wo, g1_in, g1_out); };
  };
  return project_propagation_kernel(pair, mu_from, mu_to, projector);
}

}  // namespace

int two_interface_series_modes(const UnscatteredLight& light) {
  const double sigma = std::min(light.top().sigma, light.bottom().sigma);
  return std::clamp(static_cast<int>(std::ceil(24.0 / sigma)), 32, 512);
}

std::vector<Eigen::MatrixXd> two_interface_btdf_series(const UnscatteredLight& light, std::span<const double> theta_i,
                                                       std::span<const double> theta_o, int modes,
                                                       const ParallelFor& parallel_for) {
  if (light.path() != UnscatteredPath::TopThenBottom) {
    throw std::invalid_argument("two_interface_btdf_series: the light's path is not TopThenBottom");
  }
  // theta' panels half as wide as the narrower refraction lobe, 6 Gauss-Legendre nodes each.
  const double width = std::min(refracted_lobe_width(light.top()), refracted_lobe_width(light.bottom()));
  const int panels = std::clamp(static_cast<int>(std::ceil((kPi / 2) / (0.5 * width))), 8, 2000);
  constexpr int kNodesPerPanel = 6;
  std::vector<double> theta_mid, weight;
  for (int p = 0; p < panels; ++p) {
    const QuadratureRule rule = gauss_legendre(kNodesPerPanel, p * (kPi / 2) / panels, (p + 1) * (kPi / 2) / panels);
    for (int k = 0; k < rule.size(); ++k) {
      const double mu = std::cos(rule.nodes[k]);
      const double attenuation = std::exp(-light.tau() / mu);
      if (attenuation == 0.0) continue;
      theta_mid.push_back(rule.nodes[k]);
      weight.push_back(rule.weights[k] * std::sin(rule.nodes[k]) * mu * attenuation);  // mu' dmu' e^{-tau/mu'}
    }
  }
  std::vector<Eigen::MatrixXd> result(modes, Eigen::MatrixXd::Zero(theta_o.size(), theta_i.size()));
  if (theta_mid.empty()) return result;

  const std::vector<double> mu_in = downward(theta_i), mu_mid = downward(theta_mid), mu_out = downward(theta_o);
  const CosineProjector projector(modes, 2 * modes + 1);
  FourierKernel top, bottom;
  run_parallel(parallel_for, 2, [&](int which) {
    if (which == 0) top = transmission_kernel(light.top(), mu_in, mu_mid, projector);
    if (which == 1) bottom = transmission_kernel(light.bottom(), mu_mid, mu_out, projector);
  });
  const Eigen::Map<const Eigen::VectorXd> w(weight.data(), static_cast<Eigen::Index>(weight.size()));
  // e^{-tau/mu} outside the path's interfaces: 1 where there is no depth, at any angle.
  const auto outer = [](double tau, std::span<const double> theta) {
    Eigen::VectorXd factor(theta.size());
    for (std::size_t k = 0; k < theta.size(); ++k) factor(k) = tau == 0.0 ? 1.0 : std::exp(-tau / std::cos(theta[k]));
    return factor;
  };
  const Eigen::VectorXd outer_in = outer(light.tau_before(), theta_i), outer_out = outer(light.tau_after(), theta_o);
  for (int m = 0; m < modes; ++m) {
    const double scale = azimuth_parity(m) * fourier_azimuth_weight(m);
    result[m] = scale * outer_out.asDiagonal() * (bottom[m] * w.asDiagonal() * top[m]) * outer_in.asDiagonal();
  }
  return result;
}

}  // namespace skinlayer
