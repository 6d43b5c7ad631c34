#include "core/interface_operators.h"

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

}  // namespace skinlayer
