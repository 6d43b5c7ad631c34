// Projection of azimuth-dependent kernels onto the full cosine series of core/conventions.h.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "core/cancellation.h"
#include "core/interfaces/microfacet.h"

namespace skinlayer {

// Per Fourier mode m, a matrix K^m(to, from).
using FourierKernel = std::vector<Eigen::MatrixXd>;

// The memory a matrix's and a kernel's coefficients take, in bytes.
std::size_t matrix_bytes(const Eigen::MatrixXd& matrix);
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
  // The same, kProjectBlock functions at a time, asking `cancelled` before each block (core/cancellation.h): the
  // projection of a whole kernel (tens of ms at 120 ordinates) stops part-way when a solve is cancelled.
  Eigen::MatrixXd project(const Eigen::MatrixXd& samples, const CancelCheck& cancelled) const;
  static constexpr Eigen::Index kProjectBlock = 1024;
  // The same for one function that is 0 beyond its first head.size() samples (phi_0 = 0, phi_1, ...).
  Eigen::VectorXd project_head(const Eigen::Ref<const Eigen::VectorXd>& head) const {
    return weights_.leftCols(head.size()) * head;
  }

 private:
  Eigen::MatrixXd weights_;  // modes x samples
  std::vector<double> cos_, sin_;
};

// Cosine coefficients (the convention above: K^0 the mean, K^m for m >= 1) of an even, 2pi-periodic function known
// by its values on [0, pi], sampled at 2M + 1 equally spaced azimuths for M = 16, 32, 64, ... (each level keeps the
// previous samples) until the upper half of the M modes sums, in absolute value, to at most `tolerance` times the
// largest |sample|, or M reaches max_modes. Returns the M coefficients of the last level.
class AdaptiveCosineSeries {
 public:
  AdaptiveCosineSeries(int max_modes, double tolerance);

  int max_modes() const { return projectors_.back().modes(); }
  std::vector<double> operator()(const std::function<double(double phi)>& function) const;

 private:
  std::vector<CosineProjector> projectors_;  // M = 16, 32, ... with 2M + 1 samples each
  double tolerance_;
};

// A direction of propagation with cosine mu (signed, mu > 0 travels up) and azimuth phi.
Vec3 propagation_direction(double mu, double phi);

// Fourier coefficients in Delta phi_prop of a kernel used with propagation labels:
//   K^m(to b, from a) = coefficients of  Delta phi -> kernel(omega_i = -d_a(0), omega_o = d_b(Delta phi)),
// where the kernel is a BSDF-like function of graphics-convention directions. mu_from and mu_to are signed
// propagation cosines. kernel_for_pair(wi, mu_to) returns the callable wo -> value for one pair of polar angles,
// so that work depending only on the polar angles is done once per pair; where that object has at_azimuth(cos, sin),
// a function of Delta phi alone (core/interfaces/interface_azimuth_sweep.h), it is called instead.
// support_for_pair(a, b) gives how many leading azimuth samples (phi_0 = 0, phi_1, ...) can hold a non-negligible
// value for the pair (mu_from[a], mu_to[b]); the rest are taken as 0, neither evaluated nor projected, so a narrow
// lobe costs in proportion to its azimuthal width. Returns one (to x from) matrix per mode. `cancelled` is asked
// before each incident direction's column (throw_if_cancelled).
template <class PairKernel, class PairSupport>
FourierKernel project_propagation_kernel(const PairKernel& kernel_for_pair, const PairSupport& support_for_pair,
                                         std::span<const double> mu_from, std::span<const double> mu_to,
                                         const CosineProjector& projector, const CancelCheck& cancelled = {}) {
  const int n_from = static_cast<int>(mu_from.size());
  const int n_to = static_cast<int>(mu_to.size());
  const int n = projector.samples();
  const auto incident = [&mu_from](int a) { return Vec3(-propagation_direction(mu_from[a], 0.0)); };
  std::vector<int> support(static_cast<std::size_t>(n_from) * n_to);
  long long filled = 0;
  for (int a = 0; a < n_from; ++a) {
    for (int b = 0; b < n_to; ++b) {
      const int count = std::clamp(static_cast<int>(support_for_pair(a, b)), 0, n);
      support[static_cast<std::size_t>(a) * n_to + b] = count;
      filled += count;
    }
  }
  // Samples of pair (a, b) at azimuths 0 .. count - 1 into `column`.
  const auto sample_pair = [&](const Vec3& wi, int b, int count, auto&& column) {
    if (count == 0) return;
    const auto kernel = kernel_for_pair(wi, mu_to[b]);
    if constexpr (requires { kernel.at_azimuth(1.0, 0.0); }) {  // a kernel of the azimuth alone: no direction built
      for (int k = 0; k < count; ++k) column(k) = kernel.at_azimuth(projector.cos_angle(k), projector.sin_angle(k));
    } else {
      const double sin_to = std::sqrt(std::max(0.0, 1.0 - mu_to[b] * mu_to[b]));
      for (int k = 0; k < count; ++k) {
        const Vec3 wo(sin_to * projector.cos_angle(k), sin_to * projector.sin_angle(k), mu_to[b]);
        column(k) = kernel(wo);
      }
    }
  };
  const long long pairs = static_cast<long long>(n_from) * n_to;
  if (2 * filled >= pairs * n) {  // mostly full: one matrix product over every pair
    Eigen::MatrixXd samples(n, n_from * n_to);
    for (int a = 0; a < n_from; ++a) {
      throw_if_cancelled(cancelled);
      const Vec3 wi = incident(a);
      for (int b = 0; b < n_to; ++b) {
        const int count = support[static_cast<std::size_t>(a) * n_to + b];
        auto column = samples.col(a * n_to + b);
        sample_pair(wi, b, count, column);
        column.tail(n - count).setZero();
      }
    }
    FourierKernel result(projector.modes(), Eigen::MatrixXd(n_to, n_from));
    const Eigen::MatrixXd coefficients = projector.project(samples, cancelled);
    for (int m = 0; m < projector.modes(); ++m) {
      for (int a = 0; a < n_from; ++a) {
        for (int b = 0; b < n_to; ++b) result[m](b, a) = coefficients(m, a * n_to + b);
      }
    }
    return result;
  }
  FourierKernel result(projector.modes(), Eigen::MatrixXd::Zero(n_to, n_from));
  Eigen::VectorXd head(n);
  for (int a = 0; a < n_from; ++a) {
    throw_if_cancelled(cancelled);
    const Vec3 wi = incident(a);
    for (int b = 0; b < n_to; ++b) {
      const int count = support[static_cast<std::size_t>(a) * n_to + b];
      if (count == 0) continue;
      sample_pair(wi, b, count, head);
      const Eigen::VectorXd coefficients = projector.project_head(head.head(count));
      for (int m = 0; m < projector.modes(); ++m) result[m](b, a) = coefficients(m);
    }
  }
  return result;
}

// The same for a kernel that may be non-zero at every azimuth.
template <class PairKernel>
FourierKernel project_propagation_kernel(const PairKernel& kernel_for_pair, std::span<const double> mu_from,
                                         std::span<const double> mu_to, const CosineProjector& projector,
                                         const CancelCheck& cancelled = {}) {
  const int every = projector.samples();
  return project_propagation_kernel(
      kernel_for_pair, [every](int, int) { return every; }, mu_from, mu_to, projector, cancelled);
}

}  // namespace skinlayer
