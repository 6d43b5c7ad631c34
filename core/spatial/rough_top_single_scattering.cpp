// docs/model.md §21.10: single scattering under a rough top, on the ordinates' polar nodes, in k-space through the
// eigenvectors of the mode coupling and in real space with the azimuth integrated by Gauss-Legendre panels.
#include "core/spatial/rough_top_single_scattering.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

#include "core/conventions.h"
#include "core/medium/henyey_greenstein.h"
#include "core/series/quadrature.h"
#include "core/spatial/lateral_slab_modes.h"

namespace skinlayer {
namespace {

void check(double albedo, double g, const LateralTopInterface& top, int ordinates) {
  if (!(albedo >= 0.0 && albedo <= 1.0) || !(std::abs(g) <= 0.95)) {
    throw std::invalid_argument("rough-top single scattering: albedo in [0, 1] and g in [-0.95, 0.95]");
  }
  if (top.source.size() != ordinates || top.exit.size() != ordinates) {
    throw std::invalid_argument("rough-top single scattering: the top's operators were built for another resolution");
  }
}

// sum over node pairs (i up, j down) of 2 pi a_i T_i a_j mu_j t_j Omega int_0^{2 pi} p(d.o) along(a, rho) ddphi.
template <class Along>
double over_node_pairs(double albedo, double g, const LateralTopInterface& top, int ordinates, const Along& along) {
  check(albedo, g, top, ordinates);
  const QuadratureRule q = double_gauss_half_range(ordinates);
  // Panels in dphi on [0, pi] (the integrand is even), closer towards pi, where rho is least.
  QuadratureRule azimuth;
  for (const auto& [from, to] :
       {std::pair{0.0, 0.5 * kPi}, std::pair{0.5 * kPi, 0.85 * kPi}, std::pair{0.85 * kPi, kPi}}) {
    const QuadratureRule panel = gauss_legendre(24, from, to);
    azimuth.nodes.insert(azimuth.nodes.end(), panel.nodes.begin(), panel.nodes.end());
    azimuth.weights.insert(azimuth.weights.end(), panel.weights.begin(), panel.weights.end());
  }
  double total = 0.0;
  for (int j = 0; j < ordinates; ++j) {
    const double mu_j = q.nodes[j], sin_j = std::sqrt(std::max(0.0, 1.0 - mu_j * mu_j));
    if (top.source(j) == 0.0) continue;
    for (int i = 0; i < ordinates; ++i) {
      const double mu_i = q.nodes[i], sin_i = std::sqrt(std::max(0.0, 1.0 - mu_i * mu_i));
      const double weight = 2.0 * kPi * q.weights[i] * top.exit(i) * q.weights[j] * mu_j * top.source(j) * albedo;
      const double a = 1.0 + mu_j / mu_i, lateral = mu_j * sin_i / mu_i;  // mu_j tan(theta_i)
      double sum = 0.0;
      for (std::size_t p = 0; p < azimuth.nodes.size(); ++p) {
        const double c = std::cos(azimuth.nodes[p]);
        const double rho = std::sqrt(std::max(0.0, sin_j * sin_j + lateral * lateral + 2.0 * sin_j * lateral * c));
        sum += azimuth.weights[p] * henyey_greenstein(-mu_i * mu_j + sin_i * sin_j * c, g) * along(a, rho);
      }
      total += weight * 2.0 * sum;
    }
  }
  return total;
}

// int_0^tau e^{-rate t} dt = (1 - e^{-rate tau}) / rate, by its series where rate tau is small.
std::complex<double> depth_integral(std::complex<double> rate, double tau) {
  if (std::isinf(tau)) return 1.0 / rate;
  const std::complex<double> x = rate * tau;
  if (std::abs(x) < 1e-3) return tau * (1.0 - x / 2.0 + x * x / 6.0 - x * x * x / 24.0);
  return (1.0 - std::exp(-x)) / rate;
}

}  // namespace

double rough_top_single_scattering_reflectance(double tau, double albedo, double g, const LateralTopInterface& top,
                                               double k, const LateralFrequencyResolution& resolution) {
  const int N = resolution.ordinates, M = resolution.azimuth_modes;
  check(albedo, g, top, N);
  if (!(tau >= 0.0) || !(k >= 0.0 && std::isfinite(k)) || static_cast<int>(top.reflection.size()) < M) {
    throw std::invalid_argument("rough-top single scattering: tau >= 0, finite k >= 0, and the top built for M modes");
  }
  const QuadratureRule q = double_gauss_half_range(N);
  const PhaseMatrices phase = lateral_phase_matrices(g, q, M);
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(lateral_mode_coupling(M));
  if (eigen.info() != Eigen::Success) throw std::runtime_error("rough-top single scattering: eigen-solve failed");
  const Eigen::MatrixXcd W = eigen.eigenvectors(), inverse = W.inverse();
  const Eigen::VectorXcd lambda = eigen.eigenvalues();
  // Mode 0 out of streaming along node i, and streaming of mode 0 in along node j:
  //   e0^T W diag(..) W^-1 = sum_a W(0, a) (..)_a W^-1(a, :),   W diag(..) W^-1 e0 = sum_b W(:, b) (..)_b W^-1(b, 0).
  const Eigen::MatrixXcd out = W.row(0).transpose().asDiagonal() * inverse;  // out(a, m)
  const Eigen::MatrixXcd in = W * inverse.col(0).asDiagonal();               // in(m, b)
  Eigen::MatrixXcd gamma(M, N);  // gamma(a, node) = (1 + k sin(theta) lambda_a) / mu: the streaming's decay rates
  for (int node = 0; node < N; ++node) {
    const double mu = q.nodes[node], sine = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    for (int a = 0; a < M; ++a) gamma(a, node) = (1.0 + k * sine * lambda(a)) / mu;
  }

  double reflectance = 0.0;
  Eigen::MatrixXcd depth(M, M), mixed(M, M);
  for (int i = 0; i < N; ++i) {
    std::complex<double> up = 0.0;  // mode 0 of the once-scattered radiance leaving node i upward at the top
    for (int j = 0; j < N; ++j) {
      if (top.source(j) == 0.0) continue;
      // int_0^tau e^{-t (gamma_ia + gamma_jb)} dt
      for (int a = 0; a < M; ++a) {
        for (int b = 0; b < M; ++b) {
          depth(a, b) = depth_integral(gamma(a, i) + gamma(b, j), tau);
        }
      }
      // sum_m pi_m out(a, m) in(m, b), pi_m = c_m a_j P_opp^m(i, j): the scattering, diagonal in m.
      mixed.setZero();
      for (int m = 0; m < M; ++m) {
        const double scatter =
            fourier_azimuth_weight(m) * q.weights[j] * phase.opposite[static_cast<std::size_t>(m)](i, j);
        mixed.noalias() += scatter * out.col(m) * in.row(m);
      }
      up += top.source(j) * (depth.array() * mixed.array()).sum();
    }
    reflectance +=
        2.0 * kPi * q.weights[i] * top.exit(i) * albedo * up.real();  // mu_i cancels the 1/mu_i of the source
  }
  return reflectance;
}

double rough_top_single_scattered_power(double albedo, double g, const LateralTopInterface& top, int ordinates,
                                        double r0, double r1) {
  if (!(r0 >= 0.0 && r1 >= r0)) throw std::invalid_argument("rough-top single scattering: needs 0 <= r0 <= r1");
  return over_node_pairs(albedo, g, top, ordinates, [&](double a, double rho) {
    if (rho <= 0.0) return r0 == 0.0 && r1 > 0.0 ? 1.0 / a : 0.0;
    const double outer = std::isinf(r1) ? 0.0 : std::exp(-a * r1 / rho);
    return (std::exp(-a * r0 / rho) - outer) / a;
  });
}

double rough_top_single_scattered_density(double albedo, double g, const LateralTopInterface& top, int ordinates,
                                          double r) {
  if (!(r > 0.0 && std::isfinite(r))) throw std::invalid_argument("rough-top single scattering: r must be > 0");
  return over_node_pairs(albedo, g, top, ordinates,
                         [&](double a, double rho) { return rho <= 0.0 ? 0.0 : std::exp(-a * r / rho) / rho; }) /
         (2.0 * kPi * r);
}

double rough_top_single_scattered_transform(double albedo, double g, const LateralTopInterface& top, int ordinates,
                                            double k) {
  if (!(k >= 0.0 && std::isfinite(k))) throw std::invalid_argument("rough-top single scattering: k must be >= 0");
  return over_node_pairs(albedo, g, top, ordinates,
                         [&](double a, double rho) { return 1.0 / std::sqrt(a * a + k * k * rho * rho); });
}

}  // namespace skinlayer
