#include "core/unscattered/two_interface_series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"
#include "core/series/fourier.h"
#include "core/series/quadrature.h"

namespace skinlayer {

namespace {

// Propagation cosines of directions travelling down at polar angles theta.
std::vector<double> downward(std::span<const double> theta) {
  std::vector<double> mu(theta.size());
  std::ranges::transform(theta, mu.begin(), [](double t) { return -std::cos(t); });
  return mu;
}

// f_t of the interface for a pair of polar angles, as a function of the exit direction: the callable that
// project_propagation_kernel samples in azimuth.
auto btdf_for_pair(const RoughDielectric& interface) {
  return [&interface](const Vec3& wi, double mu_to) {
    const double g1_in = smith_g1_beckmann(wi.z(), interface.sigma);
    const double g1_out = smith_g1_beckmann(mu_to, interface.sigma);
    return
        [&interface, wi, g1_in, g1_out](const Vec3& wo) { return microfacet_btdf(interface, wi, wo, g1_in, g1_out); };
  };
}

// The largest forward value (Delta phi_prop = 0, where a refraction lobe peaks) of the interface's BTDF between two
// lists of downward directions.
double largest_forward_btdf(const RoughDielectric& interface, std::span<const double> mu_from,
                            std::span<const double> mu_to) {
  const auto pair = btdf_for_pair(interface);
  double largest = 0.0;
  for (double from : mu_from) {
    const Vec3 wi = -propagation_direction(from, 0.0);
    for (double to : mu_to) largest = std::max(largest, pair(wi, to)(propagation_direction(to, 0.0)));
  }
  return largest;
}

// The interface's transmission kernel between two lists of downward directions (fourier.h's propagation labels).
// A pair whose forward value (where a refraction lobe peaks) is below `floor` is taken as 0, and so are the azimuth
// samples after the last one at or above it (project_propagation_kernel's support): a narrow lobe is sampled and
// projected over its own width only (sigma 0.05: 5% of the pairs, a few of the azimuths).
FourierKernel transmission_kernel(const RoughDielectric& interface, std::span<const double> mu_from,
                                  std::span<const double> mu_to, const CosineProjector& projector, double floor) {
  const auto pair = btdf_for_pair(interface);
  const auto support = [&](int a, int b) {
    const auto kernel = pair(-propagation_direction(mu_from[a], 0.0), mu_to[b]);
    if (kernel(propagation_direction(mu_to[b], 0.0)) < floor) return 0;
    const double sin_to = std::sqrt(std::max(0.0, 1.0 - mu_to[b] * mu_to[b]));
    int count = projector.samples();
    while (count > 0 && kernel(Vec3(sin_to * projector.cos_angle(count - 1), sin_to * projector.sin_angle(count - 1),
                                    mu_to[b])) < floor) {
      --count;
    }
    return count;
  };
  return project_propagation_kernel(pair, support, mu_from, mu_to, projector);
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
  // Values below 1e-9 of each interface's peak are dropped (transmission_kernel).
  const double top_floor = 1e-9 * largest_forward_btdf(light.top(), mu_in, mu_mid);
  const double bottom_floor = 1e-9 * largest_forward_btdf(light.bottom(), mu_mid, mu_out);
  // e^{-tau/mu} outside the path's interfaces: 1 where there is no depth, at any angle.
  const auto outer = [](double tau, std::span<const double> theta) {
    Eigen::VectorXd factor(theta.size());
    for (std::size_t k = 0; k < theta.size(); ++k) factor(k) = tau == 0.0 ? 1.0 : std::exp(-tau / std::cos(theta[k]));
    return factor;
  };
  const Eigen::VectorXd outer_in = outer(light.tau_before(), theta_i), outer_out = outer(light.tau_after(), theta_o);

  // The mu' integral in chunks of internal directions, so that the kernels' memory stays bounded (modes x chunk x n).
  const CosineProjector projector(modes, 2 * modes + 1);
  constexpr std::size_t kChunk = 48;
  for (std::size_t start = 0; start < theta_mid.size(); start += kChunk) {
    const std::size_t count = std::min(kChunk, theta_mid.size() - start);
    const std::span<const double> mid(mu_mid.data() + start, count);
    FourierKernel top, bottom;
    run_parallel(parallel_for, 2, [&](int which) {
      if (which == 0) top = transmission_kernel(light.top(), mu_in, mid, projector, top_floor);
      if (which == 1) bottom = transmission_kernel(light.bottom(), mid, mu_out, projector, bottom_floor);
    });
    const Eigen::Map<const Eigen::VectorXd> w(weight.data() + start, static_cast<Eigen::Index>(count));
    for (int m = 0; m < modes; ++m) result[m] += bottom[m] * w.asDiagonal() * top[m];
  }
  for (int m = 0; m < modes; ++m) {
    const double scale = azimuth_parity(m) * fourier_azimuth_weight(m);
    result[m] = scale * outer_out.asDiagonal() * result[m] * outer_in.asDiagonal();
  }
  return result;
}

}  // namespace skinlayer
