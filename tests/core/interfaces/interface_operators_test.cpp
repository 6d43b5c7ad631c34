// The interface operators' projection skips the azimuths where a sharp lobe is negligible
// (core/interfaces/interface_operators.cpp, lobe_azimuth_samples): the coefficients must be those of the projection of
// every azimuth sample of the same sweep (interface_azimuth_sweep.h), which knows nothing of the half-vector bound.
#include "core/interfaces/interface_operators.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/interfaces/interface_azimuth_sweep.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// The same sweep as interface_fourier's (interface_azimuth_sweep.h), sampled at every azimuth.
FourierKernel every_azimuth(const RoughDielectric& interface, std::span<const double> mu_from,
                            std::span<const double> mu_to, const CosineProjector& projector) {
  const auto kernel_for_pair = [&interface](const Vec3& wi, double cos_to) {
    return InterfaceAzimuthSweep(interface, wi, cos_to, smith_g1_beckmann(wi.z(), interface.sigma),
                                 smith_g1_beckmann(cos_to, interface.sigma));
  };
  return project_propagation_kernel(kernel_for_pair, mu_from, mu_to, projector);
}

TEST(InterfaceFourier, SkippingTheNegligibleAzimuthsChangesNoCoefficientBeyondRoundOff) {
  const QuadratureRule rule = double_gauss_half_range(40);
  std::vector<double> up = rule.nodes, down = rule.nodes;
  for (double& mu : down) mu = -mu;
  const std::vector<double> grazing_in = {-1.0, -0.5, -0.05, -1e-6};
  const CosineProjector projector(48, 241);
  // Sharp and rough, dense and near-matched, from either side; reflection inside, transmission both ways.
  for (const RoughDielectric interface : {RoughDielectric{1.4, 0.05}, RoughDielectric{1.05, 0.1},
                                          RoughDielectric{1.0 / 1.4, 0.2}, RoughDielectric{2.0, 1.0}}) {
    for (const auto& [from, to] : {std::pair{std::span<const double>(up), std::span<const double>(down)},
                                   std::pair{std::span<const double>(grazing_in), std::span<const double>(down)},
                                   std::pair{std::span<const double>(down), std::span<const double>(up)},
                                   std::pair{std::span<const double>(up), std::span<const double>(up)}}) {
      const FourierKernel fast = interface_fourier(interface, from, to, projector);
      const FourierKernel full = every_azimuth(interface, from, to, projector);
      double peak = 0.0, worst = 0.0;
      for (std::size_t m = 0; m < full.size(); ++m) {
        peak = std::max(peak, full[m].cwiseAbs().maxCoeff());
        worst = std::max(worst, (fast[m] - full[m]).cwiseAbs().maxCoeff());
      }
      EXPECT_GT(peak, 0.0);
      EXPECT_LE(worst, 1e-13 * peak) << "eta " << interface.eta << ", sigma " << interface.sigma;
    }
  }
}

}  // namespace
}  // namespace skinlayer
