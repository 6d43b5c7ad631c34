#include "core/henyey_greenstein.h"

#include <cmath>
#include <vector>

#include "core/conventions.h"

namespace skinlayer {

double henyey_greenstein(double cos_theta, double g) {
  const double denominator = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (4.0 * kPi * denominator * std::sqrt(denominator));
}

FourierKernel henyey_greenstein_fourier(double g, std::span<const double> mu_from, std::span<const double> mu_to,
                                        const CosineProjector& projector) {
  // kernel(wi, wo) with wi = -d_from and wo = d_to: cos Theta = d_from . d_to = -wi . wo.
  const auto kernel_for_pair = [g](const Vec3& wi, double) {
    return [g, wi](const Vec3& wo) { return henyey_greenstein(-wi.dot(wo), g); };
  };
  return project_propagation_kernel(kernel_for_pair, mu_from, mu_to, projector);
}

PhaseMatrices henyey_greenstein_matrices(double g, std::span<const double> nodes, std::span<const double> weights,
                                         const CosineProjector& projector) {
  const int n = static_cast<int>(nodes.size());
  std::vector<double> down(nodes.begin(), nodes.end());
  for (double& mu : down) mu = -mu;
  PhaseMatrices phase{henyey_greenstein_fourier(g, nodes, nodes, projector),
                      henyey_greenstein_fourier(g, down, nodes, projector)};
  const double c0 = fourier_azimuth_weight(0);
  for (int i = 0; i < n; ++i) {
    double total = 0.0;
    for (int j = 0; j < n; ++j) total += c0 * (phase.same[0](i, j) + phase.opposite[0](i, j)) * weights[j];
    phase.same[0](i, i) += (1.0 - total) / (c0 * weights[i]);
  }
  return phase;
}

}  // namespace skinlayer
