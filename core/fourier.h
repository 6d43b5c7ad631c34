// Projection of azimuth-dependent kernels onto the full cosine series of core/conventions.h.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "core/microfacet.h"

namespace skinlayer {

// Per Fourier mode m, a matrix K^m(to, from).
using FourierKernel = std::vector<Eigen::MatrixXd>;

// The memory a kernel's coefficients take, in bytes.
std::size_t fourier_kernel_bytes(const FourierKernel& kernel);

// Cosine coefficients of even, 2pi-periodic functions from samples at phi_k = k pi / (n - 1), k = 0..n-1:
//   K^0 = (1/pi) int_0^pi K dphi,   K^m = (2/pi) int_0^pi K cos(m phi) dphi,
// by the trapezoid rule, which is spectrally accurate for smooth periodic functions.
class CosineProjector {
 public:
  CosineProjector(int modes, int samples);

  int modes() const { return static_cast<int>(weights_.rows()); }
  int samples() const { return static_cast<int>(weights_.cols()); }
  double angle(int k) const;
  double cos_angle(int k) const { return cos_[k]; }
  double sin_angle(int k) const { return sin_[k]; }

  // samples: one column per function, one row per azimuth sample. Returns modes x functions.
  Eigen::MatrixXd project(const Eigen::MatrixXd& samples) const { return weights_ * samples; }

 private:
  Eigen::MatrixXd weights_;  // modes x samples
  std::vector<double> cos_, sin_;
};

// A direction of propagation with cosine mu (signed, mu > 0 travels up) and azimuth phi.
Vec3 propagation_direction(double mu, double phi);

// Fourier coefficients in Delta phi_prop of a kernel used with propagation labels:
//   K^m(to b, from a) = coefficients of  Delta phi -> kernel(omega_i = -d_a(0), omega_o = d_b(Delta phi)),
// where the kernel is a BSDF-like function of graphics-convention directions. mu_from and mu_to are signed
// propagation cosines. kernel_for_pair(wi, mu_to) returns the callable wo -> value for one pair of polar angles,
// so that work depending only on the polar angles is done once per pair. Returns one (to x from) matrix per mode.
template <class PairKernel>
FourierKernel project_propagation_kernel(const PairKernel& kernel_for_pair, std::span<const double> mu_from,
                                         std::span<const double> mu_to, const CosineProjector& projector) {
  const int n_from = static_cast<int>(mu_from.size());
  const int n_to = static_cast<int>(mu_to.size());
  Eigen::MatrixXd samples(projector.samples(), n_from * n_to);
  for (int a = 0; a < n_from; ++a) {
    const Vec3 wi = -propagation_direction(mu_from[a], 0.0);
    for (int b = 0; b < n_to; ++b) {
      const auto kernel = kernel_for_pair(wi, mu_to[b]);
      const double sin_to = std::sqrt(std::max(0.0, 1.0 - mu_to[b] * mu_to[b]));
      for (int k = 0; k < projector.samples(); ++k) {
        const Vec3 wo(sin_to * projector.cos_angle(k), sin_to * projector.sin_angle(k), mu_to[b]);
        samples(k, a * n_to + b) = kernel(wo);
      }
    }
  }
  const Eigen::MatrixXd coefficients = projector.project(samples);
  FourierKernel result(projector.modes(), Eigen::MatrixXd(n_to, n_from));
  for (int m = 0; m < projector.modes(); ++m) {
    for (int a = 0; a < n_from; ++a) {
      for (int b = 0; b < n_to; ++b) result[m](b, a) = coefficients(m, a * n_to + b);
    }
  }
  return result;
}

}  // namespace skinlayer
