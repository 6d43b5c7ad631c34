// docs/model.md §21.10: single scattering under a rough top, on the ordinates' polar nodes, in k-space through the
// eigenvectors of the mode coupling and in real space with the azimuth integrated by Gauss-Legendre panels.
#include "core/spatial/rough_top_single_scattering.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/conventions.h"
#include "core/medium/henyey_greenstein.h"
#include "core/series/quadrature.h"
#include "core/spatial/lateral_slab_modes.h"
#include "core/spatial/unscattered_path_transform.h"

namespace skinlayer {
namespace {

void check(std::span<const LateralSlab> slabs, const LateralTopInterface& top, int ordinates) {
  if (slabs.empty()) throw std::invalid_argument("rough-top single scattering: needs at least one slab");
  for (std::size_t l = 0; l < slabs.size(); ++l) {
    const LateralSlab& s = slabs[l];
    if (!(s.tau >= 0.0) || (std::isinf(s.tau) && l + 1 != slabs.size()) || !(s.albedo >= 0.0 && s.albedo <= 1.0) ||
        !(std::abs(s.g) <= 0.95) || !(s.relative_extinction > 0.0 && std::isfinite(s.relative_extinction))) {
      throw std::invalid_argument(
          "rough-top single scattering: tau >= 0 (infinite only last), albedo in [0, 1], g in [-0.95, 0.95] and a "
          "finite relative extinction > 0");
    }
  }
  if (top.source.size() != ordinates || top.exit.size() != ordinates) {
    throw std::invalid_argument("rough-top single scattering: the top's operators were built for another resolution");
  }
}

// sum over node pairs (i up, j down) and slabs l of
//   2 pi a_i T_i a_j mu_j t_j Omega_l e_l e^{-T_l a / mu_j} int_0^{2 pi} p_l(d.o) along(rate, s_l, s_l + ds_l, rho)
// with rate = e_l a: along gives the path integral int e^{-rate (s - s_l)} [...] ds over the slab.
template <class Along>
double over_node_pairs(std::span<const LateralSlab> slabs, const LateralTopInterface& top, int ordinates,
                       const Along& along) {
  check(slabs, top, ordinates);
  const QuadratureRule q = double_gauss_half_range(ordinates);
  const StackDepths depths = stack_depths(slabs);
  // Panels in dphi on [0, pi] (the integrand is even), closer towards pi, where rho is least.
  const QuadratureRule azimuth = gauss_legendre_panels(
      std::array{std::pair{0.0, 0.5 * kPi}, std::pair{0.5 * kPi, 0.85 * kPi}, std::pair{0.85 * kPi, kPi}}, 24);
  double total = 0.0;
  // A collimated beam under a smooth or open top (LateralTopInterface::collimated) scatters on its vertical path:
  // the pair (i, beam) has rho = tan(theta_i) whatever the azimuth, and p is the ordinates' renormalized one, as the
  // beam's source in lateral_slab_modes.
  if (top.collimated > 0.0) {
    for (int i = 0; i < ordinates; ++i) {
      const double mu_i = q.nodes[i], sin_i = std::sqrt(std::max(0.0, 1.0 - mu_i * mu_i));
      const double a = 1.0 + 1.0 / mu_i, rho = sin_i / mu_i;
      for (std::size_t l = 0; l < slabs.size(); ++l) {
        const LateralSlab& slab = slabs[l];
        if (slab.tau == 0.0 || slab.albedo == 0.0) continue;
        // The phase function is divided by 2 pi times the nodes' share of the beam's scattering, and the azimuth's
        // integral of a p that does not depend on it is 2 pi p.
        const double scattered = beam_scattering_on_nodes(slab.g, q);
        const double s0 = depths.geometric[l], s1 = s0 + slab.tau / slab.relative_extinction;
        total += q.weights[i] * top.exit(i) * top.collimated * slab.albedo * slab.relative_extinction *
                 std::exp(-depths.optical[l] * a) * henyey_greenstein(-mu_i, slab.g) / scattered *
                 along(slab.relative_extinction * a, s0, s1, rho);
      }
    }
  }
  for (int j = 0; j < ordinates; ++j) {
    const double mu_j = q.nodes[j], sin_j = std::sqrt(std::max(0.0, 1.0 - mu_j * mu_j));
    if (top.source(j) == 0.0) continue;
    for (int i = 0; i < ordinates; ++i) {
      const double mu_i = q.nodes[i], sin_i = std::sqrt(std::max(0.0, 1.0 - mu_i * mu_i));
      const double weight = 2.0 * kPi * q.weights[i] * top.exit(i) * q.weights[j] * mu_j * top.source(j);
      const double a = 1.0 + mu_j / mu_i, lateral = mu_j * sin_i / mu_i;  // mu_j tan(theta_i)
      for (std::size_t l = 0; l < slabs.size(); ++l) {
        const LateralSlab& slab = slabs[l];
        if (slab.tau == 0.0 || slab.albedo == 0.0) continue;
        const double entry = std::exp(-depths.optical[l] * a / mu_j);
        if (entry == 0.0) continue;
        const double s0 = depths.geometric[l] / mu_j, s1 = s0 + slab.tau / slab.relative_extinction / mu_j;
        const double rate = slab.relative_extinction * a;
        double sum = 0.0;
        for (std::size_t p = 0; p < azimuth.nodes.size(); ++p) {
          const double c = std::cos(azimuth.nodes[p]);
          const double rho = std::sqrt(std::max(0.0, sin_j * sin_j + lateral * lateral + 2.0 * sin_j * lateral * c));
          sum += azimuth.weights[p] * henyey_greenstein(-mu_i * mu_j + sin_i * sin_j * c, slab.g) *
                 along(rate, s0, s1, rho);
        }
        total += weight * slab.albedo * slab.relative_extinction * entry * 2.0 * sum;
      }
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

RoughTopLowOrders rough_top_low_orders(std::span<const LateralSlab> slabs, const LateralTopInterface& top, double k,
                                       const LateralFrequencyResolution& resolution,
                                       const Eigen::VectorXd& bottom_exit) {
  const int N = resolution.ordinates, M = resolution.azimuth_modes;
  check(slabs, top, N);
  if (!(k >= 0.0 && std::isfinite(k)) || static_cast<int>(top.reflection.size()) < M) {
    throw std::invalid_argument("rough-top single scattering: finite k >= 0, and the top built for M modes");
  }
  if (bottom_exit.size() != 0 && bottom_exit.size() != N) {
    throw std::invalid_argument("rough-top single scattering: the bottom's exit fractions need one per node");
  }
  const auto leaving_bottom = [&](int node) { return bottom_exit.size() == 0 ? 1.0 : bottom_exit(node); };
  const QuadratureRule q = double_gauss_half_range(N);
  const StackDepths depths = stack_depths(slabs);
  const double total_optical = depths.tau, total_geometric = depths.height;
  const bool transmits = std::isfinite(total_optical);
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(lateral_mode_coupling(M));
  if (eigen.info() != Eigen::Success) throw std::runtime_error("rough-top single scattering: eigen-solve failed");
  const Eigen::MatrixXcd W = eigen.eigenvectors(), inverse = W.inverse();
  const Eigen::VectorXcd lambda = eigen.eigenvalues();
  // Mode 0 out of streaming along node i, and streaming of mode 0 in along node j:
  //   e0^T W diag(..) W^-1 = sum_a W(0, a) (..)_a W^-1(a, :),   W diag(..) W^-1 e0 = sum_b W(:, b) (..)_b W^-1(b, 0).
  const Eigen::MatrixXcd out = W.row(0).transpose().asDiagonal() * inverse;  // out(a, m)
  const Eigen::MatrixXcd in = W * inverse.col(0).asDiagonal();               // in(m, b)
  // Per node, the streaming's decay per unit optical depth, 1/mu, and its lateral part per unit geometric depth (first
  // slab's mean free paths), k sin(theta) lambda_a / mu: slab l decays at 1/mu + lateral / e_l.
  Eigen::MatrixXcd lateral(M, N);
  for (int node = 0; node < N; ++node) {
    const double mu = q.nodes[node], sine = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    for (int a = 0; a < M; ++a) lateral(a, node) = k * sine * lambda(a) / mu;
  }

  RoughTopLowOrders orders;
  // Unscattered: the top's node radiance streamed through the whole stack, one leg with no face on it.
  if (transmits) {
    const UnscatteredLeg stack{total_optical, total_geometric};
    const Eigen::VectorXd exit = bottom_exit.size() == 0 ? Eigen::VectorXd::Ones(N) : bottom_exit;
    orders.transmitted_unscattered = unscattered_path_transform(top.source, {&stack, 1}, {}, exit, k, M);
  }
  Eigen::MatrixXcd depth(M, M), through(M, M);
  for (std::size_t l = 0; l < slabs.size(); ++l) {
    const LateralSlab& slab = slabs[l];
    if (slab.tau == 0.0 || slab.albedo == 0.0) continue;
    const PhaseMatrices phase = lateral_phase_matrices(slab.g, q, M);
    const double e = slab.relative_extinction, above = depths.optical[l], above_geometric = depths.geometric[l];
    // Below the slab, for the light scattered down (finite stacks only).
    const double below = transmits ? total_optical - above - slab.tau : 0.0;
    const double below_geometric = transmits ? total_geometric - above_geometric - slab.tau / e : 0.0;
    // The lateral factors of the light that goes down to the slab and back, per mode and node: e^{-G_l lateral} to
    // the slab's top and e^{-tau_l lateral / e_l} through it. Their products make the exponentials of each pair.
    Eigen::MatrixXcd reach(M, N), across(M, N);
    for (int node = 0; node < N; ++node) {
      for (int a = 0; a < M; ++a) {
        reach(a, node) = std::exp(-above_geometric * lateral(a, node));
        across(a, node) = std::isinf(slab.tau) ? 0.0 : std::exp(-slab.tau * lateral(a, node) / e);
      }
    }
    for (const bool up : {true, false}) {
      if (!up && !transmits) continue;
      const FourierKernel& scattering = up ? phase.opposite : phase.same;
      for (int i = 0; i < N; ++i) {
        std::complex<double> leaving = 0.0;  // mode 0 of the once-scattered radiance leaving along node i
        for (int j = 0; j < N; ++j) {
          if (top.source(j) == 0.0) continue;
          const double mu_i = q.nodes[i], mu_j = q.nodes[j];
          const double base = 1.0 / mu_i + 1.0 / mu_j;  // the decay per optical depth down along j and up along i
          const double to_slab = std::exp(-above * base), through_slab = std::exp(-slab.tau * base);
          for (int a = 0; a < M; ++a) {
            for (int b = 0; b < M; ++b) {
              if (up) {
                // Down to the slab and back (e^{-(T_l base + G_l lateral)}), then int_0^tau_l e^{-t (base + lateral /
                // e_l)} dt, base = 1/mu_i + 1/mu_j: (1 - e^{-rate tau_l}) / rate from the factors above.
                const std::complex<double> rate = base + (lateral(a, i) + lateral(b, j)) / e;
                const std::complex<double> integral = std::isinf(slab.tau) || std::abs(rate * slab.tau) < 1e-3
                                                          ? depth_integral(rate, slab.tau)
                                                          : (1.0 - through_slab * across(a, i) * across(b, j)) / rate;
                depth(a, b) = to_slab * reach(a, i) * reach(b, j) * integral;
              } else {
                // Down along j to depth t in the slab, then down along i through the rest of the stack:
                //   e^{-(T_l / mu_j + G_l lat_j)} e^{-(B_l / mu_i + G'_l lat_i)} int_0^tau_l e^{-t d_j - (tau_l - t)
                //   d_i} dt,
                // d the decay per optical depth in the slab; the integral is referred to the end where it is largest.
                const std::complex<double> d_j = 1.0 / mu_j + lateral(b, j) / e, d_i = 1.0 / mu_i + lateral(a, i) / e;
                const std::complex<double> outside = -(above / mu_j + above_geometric * lateral(b, j)) -
                                                     (below / mu_i + below_geometric * lateral(a, i));
                depth(a, b) = (d_j - d_i).real() >= 0.0
                                  ? std::exp(outside - slab.tau * d_i) * depth_integral(d_j - d_i, slab.tau)
                                  : std::exp(outside - slab.tau * d_j) * depth_integral(d_i - d_j, slab.tau);
              }
            }
          }
          // sum_ab depth(a, b) sum_m out(a, m) pi_m in(m, b), pi_m = c_m a_j P^m(i, j) the scattering, diagonal
          // in m: sum_m pi_m sum_a out(a, m) (depth in^T)(a, m), one product instead of M outer ones.
          through.noalias() = depth * in.transpose();
          const Eigen::VectorXcd per_mode = (out.array() * through.array()).colwise().sum().transpose();
          for (int m = 0; m < M; ++m) {
            const double scatter =
                fourier_azimuth_weight(m) * q.weights[j] * scattering[static_cast<std::size_t>(m)](i, j);
            leaving += top.source(j) * scatter * per_mode(m);
          }
        }
        // mu_i cancels the 1/mu_i of the source; nothing reflects at the faces, and each lets out its exit fraction.
        const double flux = 2.0 * kPi * q.weights[i] * slab.albedo * leaving.real();
        (up ? orders.reflected_once : orders.transmitted_once) += (up ? top.exit(i) : leaving_bottom(i)) * flux;
      }
    }
  }
  return orders;
}

double rough_top_single_scattered_power(std::span<const LateralSlab> slabs, const LateralTopInterface& top,
                                        int ordinates, double r0, double r1) {
  if (!(r0 >= 0.0 && r1 >= r0)) throw std::invalid_argument("rough-top single scattering: needs 0 <= r0 <= r1");
  return over_node_pairs(slabs, top, ordinates, [&](double rate, double s0, double s1, double rho) {
    const double lo = rho > 0.0 ? std::max(s0, r0 / rho) : (r0 == 0.0 && r1 > 0.0 ? s0 : s1);
    const double hi = rho > 0.0 ? std::min(s1, r1 / rho) : s1;
    if (!(hi > lo)) return 0.0;
    const double far = std::isinf(hi) ? 0.0 : std::exp(-rate * (hi - s0));
    return (std::exp(-rate * (lo - s0)) - far) / rate;
  });
}

double rough_top_single_scattered_density(std::span<const LateralSlab> slabs, const LateralTopInterface& top,
                                          int ordinates, double r) {
  if (!(r > 0.0 && std::isfinite(r))) throw std::invalid_argument("rough-top single scattering: r must be > 0");
  return over_node_pairs(slabs, top, ordinates,
                         [&](double rate, double s0, double s1, double rho) {
                           if (rho <= 0.0) return 0.0;
                           const double s = r / rho;
                           return s >= s0 && s < s1 ? std::exp(-rate * (s - s0)) / rho : 0.0;
                         }) /
         (2.0 * kPi * r);
}

double rough_top_single_scattered_transform(double albedo, double g, const LateralTopInterface& top, int ordinates,
                                            double k) {
  if (!(k >= 0.0 && std::isfinite(k))) throw std::invalid_argument("rough-top single scattering: k must be >= 0");
  const LateralSlab half_space{std::numeric_limits<double>::infinity(), albedo, g};
  return over_node_pairs({&half_space, 1}, top, ordinates, [&](double rate, double, double, double rho) {
    return 1.0 / std::sqrt(rate * rate + k * k * rho * rho);
  });
}

}  // namespace skinlayer
