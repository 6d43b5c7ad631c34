#include "core/interface_operators.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"

namespace skinlayer {

FourierKernel interface_fourier(const RoughDielectric& interface, std::span<const double> mu_from,
                                std::span<const double> mu_to, const CosineProjector& projector) {
  const auto kernel_for_pair = [&interface](const Vec3& wi, double cos_to) {
    const double g1_wi = smith_g1_beckmann(wi.z(), interface.sigma);
    const double g1_wo = smith_g1_beckmann(cos_to, interface.sigma);
    return [&interface, wi, g1_wi, g1_wo](const Vec3& wo) {
      return rough_dielectric_bsdf(interface, wi, wo, g1_wi, g1_wo);
    };
  };
  return project_propagation_kernel(kernel_for_pair, mu_from, mu_to, projector);
}

void apply_quadrature_weights(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights) {
  for (std::size_t m = 0; m < kernel.size(); ++m) {
    const double c_m = fourier_azimuth_weight(static_cast<int>(m));
    for (Eigen::Index j = 0; j < kernel[m].cols(); ++j) {
      kernel[m].col(j) *= c_m * std::abs(nodes[j]) * weights[j];
    }
  }
}

void match_column_energy(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights,
                         std::span<const double> target) {
  if (kernel.empty()) return;
  for (Eigen::Index k = 0; k < kernel[0].cols(); ++k) {
    double quadrature = 0.0;
    for (Eigen::Index j = 0; j < kernel[0].rows(); ++j) {
      quadrature += fourier_azimuth_weight(0) * weights[j] * std::abs(nodes[j]) * kernel[0](j, k);
    }
    const double wanted = target[static_cast<std::size_t>(k)];
    if (quadrature <= 0.0 || wanted <= 0.0) continue;
    for (Eigen::MatrixXd& mode : kernel) mode.col(k) *= wanted / quadrature;
  }
}

void match_reflection_energy(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights,
                             std::span<const double> target) {
  constexpr int kMaxSteps = 200;
  constexpr double kTolerance = 1e-12;
  if (kernel.empty()) return;
  const Eigen::Index n = kernel[0].cols();
  Eigen::VectorXd row_weight(n);  // c_0 a_o |mu_o|
  for (Eigen::Index o = 0; o < n; ++o) row_weight(o) = fourier_azimuth_weight(0) * weights[o] * std::abs(nodes[o]);
  const Eigen::Map<const Eigen::VectorXd> wanted(target.data(), n);
  const Eigen::MatrixXd weighted = row_weight.asDiagonal() * kernel[0];
  const Eigen::Array<bool, Eigen::Dynamic, 1> active =
      (wanted.array() > 0.0) && ((weighted.colwise().sum().transpose().array()) > 0.0);
  Eigen::VectorXd d = Eigen::VectorXd::Ones(n);
  for (int step = 0; step < kMaxSteps; ++step) {
    const Eigen::VectorXd energy = d.cwiseProduct(weighted.transpose() * d);  // energy_j = d_j sum_o w_o f(o,j) d_o
    double residual = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!active(j)) continue;
      residual = std::max(residual, std::abs(energy(j) / wanted(j) - 1.0));
      d(j) *= std::sqrt(wanted(j) / energy(j));
    }
    if (residual < kTolerance) break;
  }
  for (Eigen::MatrixXd& mode : kernel) mode = d.asDiagonal() * mode * d.asDiagonal();
}

}  // namespace skinlayer
