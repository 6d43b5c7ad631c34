#include "core/medium/henyey_greenstein.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/conventions.h"

namespace skinlayer {

double henyey_greenstein(double cos_theta, double g) {
  const double denominator = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (4.0 * kPi * denominator * std::sqrt(denominator));
}

FourierKernel henyey_greenstein_fourier(double g, std::span<const double> mu_from, std::span<const double> mu_to,
                                        const CosineProjector& projector, const CancelCheck& cancelled) {
  // kernel(wi, wo) with wi = -d_from and wo = d_to: cos Theta = d_from . d_to = -wi . wo.
  const auto kernel_for_pair = [g](const Vec3& wi, double) {
    return [g, wi](const Vec3& wo) { return henyey_greenstein(-wi.dot(wo), g); };
  };
  return project_propagation_kernel(kernel_for_pair, mu_from, mu_to, projector, cancelled);
}

namespace {

// p^m between the nodes, travelling along sign * mu_a and mu_b: cos Theta = sign mu_a mu_b + s_a s_b cos(Delta phi)
// is symmetric in a and b, so each pair a <= b is sampled and projected once (half of henyey_greenstein_fourier's
// work for the same coefficients).
FourierKernel symmetric_node_kernel(double g, std::span<const double> nodes, double sign,
                                    const CosineProjector& projector, const CancelCheck& cancelled) {
  const int n = static_cast<int>(nodes.size());
  Eigen::MatrixXd samples(projector.samples(), n * (n + 1) / 2);
  int column = 0;
  for (int a = 0; a < n; ++a) {
    throw_if_cancelled(cancelled);
    const double sin_a = std::sqrt(std::max(0.0, 1.0 - nodes[a] * nodes[a]));
    for (int b = a; b < n; ++b, ++column) {
      const double sin_b = std::sqrt(std::max(0.0, 1.0 - nodes[b] * nodes[b]));
      for (int k = 0; k < projector.samples(); ++k) {
        samples(k, column) = henyey_greenstein(sign * nodes[a] * nodes[b] + sin_a * sin_b * projector.cos_angle(k), g);
      }
    }
  }
  const Eigen::MatrixXd coefficients = projector.project(samples, cancelled);
  FourierKernel result(projector.modes(), Eigen::MatrixXd(n, n));
  for (int m = 0; m < projector.modes(); ++m) {
    column = 0;
    for (int a = 0; a < n; ++a) {
      for (int b = a; b < n; ++b, ++column) result[m](a, b) = result[m](b, a) = coefficients(m, column);
    }
  }
  return result;
}

}  // namespace

PhaseMatrices henyey_greenstein_matrices(double g, std::span<const double> nodes, std::span<const double> weights,
                                         const CosineProjector& projector, const CancelCheck& cancelled) {
  const int n = static_cast<int>(nodes.size());
  PhaseMatrices phase{symmetric_node_kernel(g, nodes, 1.0, projector, cancelled),
                      symmetric_node_kernel(g, nodes, -1.0, projector, cancelled)};
  const double c0 = fourier_azimuth_weight(0);
  for (int i = 0; i < n; ++i) {
    double total = 0.0;
    for (int j = 0; j < n; ++j) total += c0 * (phase.same[0](i, j) + phase.opposite[0](i, j)) * weights[j];
    phase.same[0](i, i) += (1.0 - total) / (c0 * weights[i]);
  }
  return phase;
}

}  // namespace skinlayer
