#include "core/solve/boundary_solve.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace skinlayer {
namespace {

bool is_semi_infinite(double tau) { return std::isinf(tau); }

// R u, or zero when the operator is absent.
Eigen::MatrixXd apply(const Eigen::MatrixXd& op, const Eigen::MatrixXd& u) {
  return op.size() == 0 ? Eigen::MatrixXd::Zero(u.rows(), u.cols()) : Eigen::MatrixXd(op * u);
}

Eigen::MatrixXd or_zero(const Eigen::MatrixXd& m, Eigen::Index rows, Eigen::Index cols) {
  return m.size() == 0 ? Eigen::MatrixXd::Zero(rows, cols) : m;
}

// int_0^tau e^{-k t} e^{-t/mu} dt/mu = (1 - e^{-(k + 1/mu) tau}) / (1 + k mu).
double decaying_integral(double k, double mu, double tau) {
  return -std::expm1(-(k + 1.0 / mu) * tau) / (1.0 + k * mu);
}

// int_0^tau e^{-t/mu0} e^{-t/mu} dt/mu = mu0/(mu0 + mu) (1 - e^{-tau (1/mu0 + 1/mu)}).
double beam_integral(double mu0, double mu, double tau) {
  return mu0 / (mu0 + mu) * -std::expm1(-tau * (1.0 / mu0 + 1.0 / mu));
}

}  // namespace

Eigen::VectorXd slab_attenuation(std::span<const double> mu, double tau) {
  Eigen::VectorXd result(static_cast<Eigen::Index>(mu.size()));
  for (std::size_t k = 0; k < mu.size(); ++k) result(static_cast<Eigen::Index>(k)) = std::exp(-tau / mu[k]);
  return result;
}

double exponential_difference_ratio(double k, double mu, double tau) {
  if (is_semi_infinite(tau)) return 0.0;
  const double x = 1.0 / mu - k;  // (1 - k mu) = mu x
  if (x == 0.0) return std::exp(-k * tau) * tau / mu;
  if (x > 0.0) return std::exp(-k * tau) * -std::expm1(-x * tau) / (mu * x);
  return std::exp(-tau / mu) * std::expm1(x * tau) / (mu * x);
}

BeamParticular beam_particular_solution(std::span<const double> nodes, std::span<const double> weights,
                                        const Eigen::MatrixXd& same, const Eigen::MatrixXd& opposite, double scattering,
                                        const Eigen::MatrixXd& beam_up, const Eigen::MatrixXd& beam_down,
                                        std::span<const double> mu0) {
  const Eigen::Index n = static_cast<Eigen::Index>(nodes.size());
  const Eigen::Index count = static_cast<Eigen::Index>(mu0.size());
  BeamParticular result{Eigen::MatrixXd(n, count), Eigen::MatrixXd(n, count), Eigen::VectorXd(count)};
  const Eigen::Map<const Eigen::VectorXd> a(weights.data(), n);
  // s P A over the signed nodes, ordered [up; down]; P-+ = P+-, P-- = P++.
  Eigen::MatrixXd scatter(2 * n, 2 * n);
  scatter.topLeftCorner(n, n) = scattering * same * a.asDiagonal();
  scatter.topRightCorner(n, n) = scattering * opposite * a.asDiagonal();
  scatter.bottomLeftCorner(n, n) = scattering * opposite * a.asDiagonal();
  scatter.bottomRightCorner(n, n) = scattering * same * a.asDiagonal();
  Eigen::VectorXd rhs(2 * n);
  for (Eigen::Index k = 0; k < count; ++k) {
    const double mu = mu0[k];
    result.mu0(k) = mu;
    if (scattering == 0.0) {
      result.up.col(k).setZero();
      result.down.col(k).setZero();
      continue;
    }
    Eigen::MatrixXd system = -scatter;
    for (Eigen::Index i = 0; i < n; ++i) {
      system(i, i) += 1.0 + nodes[i] / mu;
      system(n + i, n + i) += 1.0 - nodes[i] / mu;
    }
    rhs << beam_up.col(k), beam_down.col(k);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(system);
    Eigen::VectorXd z = lu.solve(rhs);
    // Resonance (1/mu0 equal to a slab eigenvalue) makes the system singular; the solution is smooth in mu0, so
    // step mu0 off the resonance by a relative 1e-7 (DISORT's remedy).
    for (double shift = 1e-7; !z.allFinite() || (system * z - rhs).norm() > 1e-8 * (rhs.norm() + 1e-300);
         shift *= 10.0) {
      if (shift > 1e-3) break;
      const double nudged = mu * (1.0 + shift);
      result.mu0(k) = nudged;
      system = -scatter;
      for (Eigen::Index i = 0; i < n; ++i) {
        system(i, i) += 1.0 + nodes[i] / nudged;
        system(n + i, n + i) += 1.0 - nodes[i] / nudged;
      }
      lu.compute(system);
      z = lu.solve(rhs);
    }
    result.up.col(k) = z.head(n);
    result.down.col(k) = z.tail(n);
  }
  return result;
}

NodeField solve_boundary(const BoundaryProblem& problem, int incident_count) {
  const SlabEigenSolution& eigen = *problem.eigen;
  const Eigen::Index n = eigen.k.size();
  const Eigen::Index count = incident_count;
  const Eigen::MatrixXd& gp = eigen.g_up;
  const Eigen::MatrixXd& gm = eigen.g_down;
  const bool semi_infinite = is_semi_infinite(problem.tau);

  Eigen::MatrixXd z_up = Eigen::MatrixXd::Zero(n, count);
  Eigen::MatrixXd z_down = Eigen::MatrixXd::Zero(n, count);
  Eigen::VectorXd beam_attenuation = Eigen::VectorXd::Zero(count);  // e^{-tau_b/mu0}
  if (problem.beam != nullptr) {
    z_up = problem.beam->up;
    z_down = problem.beam->down;
    for (Eigen::Index k = 0; k < count; ++k) {
      beam_attenuation(k) = semi_infinite ? 0.0 : std::exp(-problem.tau / problem.beam->mu0(k));
    }
  }

  // Without a beam inside the slab z = 0, and its terms are left out rather than multiplied.
  const bool beam = problem.beam != nullptr;
  Eigen::MatrixXd top_rhs = or_zero(problem.source_top, n, count);
  if (beam) top_rhs -= z_down - apply(problem.reflect_top, z_up);

  NodeField field;
  if (semi_infinite) {
    const Eigen::MatrixXd system = gm - apply(problem.reflect_top, gp);
    field.c_minus = Eigen::PartialPivLU<Eigen::MatrixXd>(system).solve(top_rhs);
    field.c_plus = Eigen::MatrixXd::Zero(n, count);
    field.up_top = gp * field.c_minus + z_up;
    field.down_bottom = Eigen::MatrixXd::Zero(n, count);
    return field;
  }

  const Eigen::VectorXd e = (-eigen.k * problem.tau).array().exp();
  Eigen::MatrixXd bottom_rhs = or_zero(problem.source_bottom, n, count);
  if (beam) bottom_rhs -= (z_up - apply(problem.reflect_bottom, z_down)) * beam_attenuation.asDiagonal();
  Eigen::MatrixXd system(2 * n, 2 * n);
  system.topLeftCorner(n, n) = gm - apply(problem.reflect_top, gp);
  system.topRightCorner(n, n) = (gp - apply(problem.reflect_top, gm)) * e.asDiagonal();
  system.bottomLeftCorner(n, n) = (gp - apply(problem.reflect_bottom, gm)) * e.asDiagonal();
  system.bottomRightCorner(n, n) = gm - apply(problem.reflect_bottom, gp);
  Eigen::MatrixXd rhs(2 * n, count);
  rhs << top_rhs, bottom_rhs;
  const Eigen::MatrixXd c = Eigen::PartialPivLU<Eigen::MatrixXd>(system).solve(rhs);
  field.c_minus = c.topRows(n);
  field.c_plus = c.bottomRows(n);
  const Eigen::MatrixXd ec_minus = e.asDiagonal() * field.c_minus;
  const Eigen::MatrixXd ec_plus = e.asDiagonal() * field.c_plus;
  field.up_top = gp * field.c_minus + gm * ec_plus;
  field.down_bottom = gm * ec_minus + gp * field.c_plus;
  if (beam) {
    field.up_top += z_up;
    field.down_bottom += z_down * beam_attenuation.asDiagonal();
  }
  return field;
}

Eigen::MatrixXd upward_radiance_at_top(const BoundaryProblem& problem, const NodeField& field,
                                       const ExitScattering& exit, const Eigen::MatrixXd& upward_at_bottom) {
  const SlabEigenSolution& eigen = *problem.eigen;
  const Eigen::Index n = eigen.k.size();
  const Eigen::Index outs = static_cast<Eigen::Index>(exit.mu.size());
  const Eigen::Index count = field.c_minus.cols();
  const double tau = problem.tau;
  // J(t, +mu) = H+ e^{-K t} c- + H- e^{-K (tau_b - t)} c+ + Jp e^{-t/mu0}.
  Eigen::MatrixXd h_plus = exit.same_row * eigen.g_up + exit.opposite_row * eigen.g_down;
  Eigen::MatrixXd h_minus = exit.same_row * eigen.g_down + exit.opposite_row * eigen.g_up;
  for (Eigen::Index o = 0; o < outs; ++o) {
    for (Eigen::Index j = 0; j < n; ++j) {
      h_plus(o, j) *= decaying_integral(eigen.k(j), exit.mu[o], tau);
      h_minus(o, j) *= exponential_difference_ratio(eigen.k(j), exit.mu[o], tau);
    }
  }
  Eigen::MatrixXd result = h_plus * field.c_minus + h_minus * field.c_plus;
  if (problem.beam != nullptr) {
    Eigen::MatrixXd particular = exit.same_row * problem.beam->up + exit.opposite_row * problem.beam->down;
    if (exit.beam_row.size() != 0) particular += exit.beam_row;
    for (Eigen::Index o = 0; o < outs; ++o) {
      for (Eigen::Index k = 0; k < count; ++k) {
        result(o, k) += particular(o, k) * beam_integral(problem.beam->mu0(k), exit.mu[o], tau);
      }
    }
  }
  if (upward_at_bottom.size() != 0 && !std::isinf(tau)) {
    for (Eigen::Index o = 0; o < outs; ++o) result.row(o) += upward_at_bottom.row(o) * std::exp(-tau / exit.mu[o]);
  }
  return result;
}

Eigen::MatrixXd downward_radiance_at_bottom(const BoundaryProblem& problem, const NodeField& field,
                                            const ExitScattering& exit, const Eigen::MatrixXd& downward_at_top) {
  const SlabEigenSolution& eigen = *problem.eigen;
  const Eigen::Index n = eigen.k.size();
  const Eigen::Index outs = static_cast<Eigen::Index>(exit.mu.size());
  const Eigen::Index count = field.c_minus.cols();
  const double tau = problem.tau;
  if (std::isinf(tau)) return Eigen::MatrixXd::Zero(outs, count);
  // J(t, -mu): the roles of same_row and opposite_row swap (p^m(-mu, mu_j) = p^m(mu, -mu_j)).
  Eigen::MatrixXd h_plus = exit.opposite_row * eigen.g_up + exit.same_row * eigen.g_down;   // with c- e^{-K t}
  Eigen::MatrixXd h_minus = exit.opposite_row * eigen.g_down + exit.same_row * eigen.g_up;  // with c+ e^{-K(tau_b-t)}
  for (Eigen::Index o = 0; o < outs; ++o) {
    for (Eigen::Index j = 0; j < n; ++j) {
      h_plus(o, j) *= exponential_difference_ratio(eigen.k(j), exit.mu[o], tau);
      h_minus(o, j) *= decaying_integral(eigen.k(j), exit.mu[o], tau);
    }
  }
  Eigen::MatrixXd result = h_plus * field.c_minus + h_minus * field.c_plus;
  if (problem.beam != nullptr) {
    Eigen::MatrixXd particular = exit.opposite_row * problem.beam->up + exit.same_row * problem.beam->down;
    if (exit.beam_row.size() != 0) particular += exit.beam_row;
    for (Eigen::Index o = 0; o < outs; ++o) {
      for (Eigen::Index k = 0; k < count; ++k) {
        result(o, k) += particular(o, k) * exponential_difference_ratio(1.0 / problem.beam->mu0(k), exit.mu[o], tau);
      }
    }
  }
  if (downward_at_top.size() != 0) {
    for (Eigen::Index o = 0; o < outs; ++o) result.row(o) += downward_at_top.row(o) * std::exp(-tau / exit.mu[o]);
  }
  return result;
}

}  // namespace skinlayer
