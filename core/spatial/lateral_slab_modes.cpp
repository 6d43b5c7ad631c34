// docs/model.md §21.2–§21.3: one slab's discrete-ordinate system at one lateral frequency, and its eigen-solution.
#include "core/spatial/lateral_slab_modes.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/medium/slab_eigen.h"
#include "core/series/fourier.h"

namespace skinlayer {
namespace {

void check(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("lateral_slab_modes: " + message);
}

}  // namespace

PhaseMatrices lateral_phase_matrices(double g, const QuadratureRule& quadrature, int modes) {
  const double forwardness = 1.0 - std::abs(g);
  const int azimuths = std::max({2 * modes + 1, static_cast<int>(std::ceil(20.0 / forwardness)) + 1, 49});
  return henyey_greenstein_matrices(g, quadrature.nodes, quadrature.weights, CosineProjector(modes, azimuths));
}

Eigen::MatrixXd lateral_mode_coupling(int modes) {
  // i cos(phi) i^(m-1) cos((m-1) phi) and i cos(phi) i^(m+1) cos((m+1) phi), divided by i^m (§21.2).
  Eigen::MatrixXd coupling = Eigen::MatrixXd::Zero(modes, modes);
  for (int m = 0; m < modes; ++m) {
    if (m >= 1) coupling(m, m - 1) = m - 1 == 0 ? 1.0 : 0.5;
    if (m + 1 < modes) coupling(m, m + 1) = -0.5;
  }
  return coupling;
}

double beam_scattering_on_nodes(double g, const QuadratureRule& q) {
  double scattered = 0.0;
  for (std::size_t j = 0; j < q.nodes.size(); ++j) {
    scattered += q.weights[j] * (henyey_greenstein(q.nodes[j], g) + henyey_greenstein(-q.nodes[j], g));
  }
  return scattered;
}

LateralSlabModes lateral_slab_modes(double operator_albedo, double source_albedo, double g, double k,
                                    const QuadratureRule& q, int modes) {
  check(operator_albedo >= 0.0 && operator_albedo <= 1.0, "albedo must be in [0, 1]");
  check(source_albedo >= 0.0 && source_albedo <= 1.0, "albedo must be in [0, 1]");
  check(std::abs(g) <= 0.95, "g must be in [-0.95, 0.95]");
  check(k >= 0.0 && std::isfinite(k), "k must be finite and >= 0");
  check(q.size() >= 2 && modes >= 1, "needs >= 2 ordinates and >= 1 mode");
  const LateralLayout layout{static_cast<int>(q.size()), modes};
  const int N = layout.nodes, M = layout.modes, n = layout.size();

  const PhaseMatrices phase = lateral_phase_matrices(g, q, M);
  const Eigen::MatrixXd coupling = lateral_mode_coupling(M);
  // Conservative scattering is solved at the BSDF's clamped albedo (slab_eigen.h): at k = 0 mode 0 would have a double
  // eigenvalue 0.
  operator_albedo = std::min(operator_albedo, kMaxSolvedAlbedo);

  // L U = (1 + k sin(theta) C) U - Omega S U, and A = D^-1 L with D = diag(signed mu): dU/dtau = -A U + D^-1 s e^-tau.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int m = 0; m < M; ++m) {
    const double c_m = fourier_azimuth_weight(m);
    for (int up = 0; up < 2; ++up) {
      for (int i = 0; i < N; ++i) {
        const int row = layout.at(m, up, i);
        const double sin_theta = std::sqrt(std::max(0.0, 1.0 - q.nodes[i] * q.nodes[i]));
        A(row, row) += 1.0;
        if (m >= 1) A(row, layout.at(m - 1, up, i)) += k * sin_theta * coupling(m, m - 1);
        if (m + 1 < M) A(row, layout.at(m + 1, up, i)) += k * sin_theta * coupling(m, m + 1);
        for (int from_up = 0; from_up < 2; ++from_up) {
          const Eigen::MatrixXd& p =
              from_up == up ? phase.same[static_cast<std::size_t>(m)] : phase.opposite[static_cast<std::size_t>(m)];
          for (int j = 0; j < N; ++j)
            A(row, layout.at(m, from_up, j)) -= operator_albedo * c_m * q.weights[j] * p(i, j);
        }
      }
    }
  }
  Eigen::VectorXd source = Eigen::VectorXd::Zero(n);  // D^-1 s: the beam's first scattering, mode 0
  const double norm = 1.0 / (2.0 * kPi * beam_scattering_on_nodes(g, q));
  for (int up = 0; up < 2; ++up) {
    for (int i = 0; i < N; ++i) {
      const double mu = up ? -q.nodes[i] : q.nodes[i];
      source(layout.at(0, up, i)) = source_albedo * henyey_greenstein(mu, g) * norm / mu;
    }
  }
  for (int row = 0; row < n; ++row) {
    const int i = row % N;
    const bool up = (row / N) % 2 == 1;
    A.row(row) /= up ? -q.nodes[i] : q.nodes[i];
  }

  // Particular solution X e^-tau: (A - 1) X = D^-1 s (none without a beam: light that enters as node radiance).
  const Eigen::VectorXd X = source_albedo == 0.0
                                ? Eigen::VectorXd::Zero(n)
                                : Eigen::VectorXd((A - Eigen::MatrixXd::Identity(n, n)).partialPivLu().solve(source));

  // Homogeneous solutions v e^{-lambda tau}, at half size (§21.3). Within each mode block A is
  // [[D^-1 L1, D^-1 L2], [-D^-1 L2, -D^-1 L1]] (down, up); for S = v_down + v_up and Delta = v_down - v_up,
  //   lambda^2 S = D^-1 (L1 - L2) D^-1 (L1 + L2) S,   Delta = D^-1 (L1 + L2) S / lambda,
  // and -lambda swaps v_down and v_up. Here the blocks are gathered over the modes.
  const int h = n / 2;
  std::vector<int> down_rows, up_rows;
  for (int m = 0; m < M; ++m) {
    for (int i = 0; i < N; ++i) {
      down_rows.push_back(layout.at(m, 0, i));
      up_rows.push_back(layout.at(m, 1, i));
    }
  }
  Eigen::MatrixXd P(h, h), Q(h, h);  // D^-1 (L1 + L2) and D^-1 (L1 - L2): A's down rows are D^-1 (L1, L2)
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < h; ++c) {
      const double same = A(down_rows[static_cast<std::size_t>(r)], down_rows[static_cast<std::size_t>(c)]);
      const double opposite = A(down_rows[static_cast<std::size_t>(r)], up_rows[static_cast<std::size_t>(c)]);
      P(r, c) = same + opposite;
      Q(r, c) = same - opposite;
    }
  }
  // lambda^2 and S. Without scattering in the operator only the k-term couples, mode to mode at one node, so
  // Q P falls apart into one M x M block per node.
  const Eigen::MatrixXd QP = Q * P;
  Eigen::VectorXcd squared(h);
  Eigen::MatrixXcd S = Eigen::MatrixXcd::Zero(h, h);
  if (operator_albedo == 0.0) {
    for (int i = 0; i < N; ++i) {  // down_rows[m N + i] is mode m at node i
      Eigen::MatrixXd block(M, M);
      for (int a = 0; a < M; ++a) {
        for (int b = 0; b < M; ++b) block(a, b) = QP(a * N + i, b * N + i);
      }
      const Eigen::EigenSolver<Eigen::MatrixXd> eigen(block);
      check(eigen.info() == Eigen::Success, "the eigen-decomposition failed");
      for (int l = 0; l < M; ++l) {
        squared(i * M + l) = eigen.eigenvalues()(l);
        for (int a = 0; a < M; ++a) S(a * N + i, i * M + l) = eigen.eigenvectors()(a, l);
      }
    }
  } else {
    const Eigen::EigenSolver<Eigen::MatrixXd> eigen(QP);
    check(eigen.info() == Eigen::Success, "the eigen-decomposition failed");
    squared = eigen.eigenvalues();
    S = eigen.eigenvectors();
  }
  LateralSlabModes slab;
  slab.beam = X;
  Eigen::VectorXcd& lambda = slab.lambda;
  Eigen::MatrixXcd& V = slab.vectors;
  lambda.resize(n);
  V.resize(n, n);
  // P real, S complex: two real products cost half of one complex one.
  Eigen::MatrixXcd PS(h, h);
  PS.real() = P * S.real();
  PS.imag() = P * S.imag();
  slab.imaginary.assign(static_cast<std::size_t>(n), false);
  for (int l = 0; l < h; ++l) {
    // The second of a conjugate pair (its lambda^2 and vector the first's conjugates, as EigenSolver gives them).
    const bool second = l > 0 && squared(l).imag() != 0.0 && squared(l) == std::conj(squared(l - 1)) &&
                        !slab.imaginary[static_cast<std::size_t>(l - 1)];
    slab.imaginary[static_cast<std::size_t>(l)] = slab.imaginary[static_cast<std::size_t>(h + l)] = second;
    const std::complex<double> root = std::sqrt(squared(l));  // Re >= 0: the decaying one
    check(root.real() > 0.0, "a mode neither decays nor grows (conservative scattering at k = 0?)");
    const Eigen::VectorXcd delta = PS.col(l) / root;
    lambda(l) = root;
    lambda(h + l) = -root;
    for (int r = 0; r < h; ++r) {
      const std::complex<double> down = 0.5 * (S(r, l) + delta(r)), up = 0.5 * (S(r, l) - delta(r));
      V(down_rows[static_cast<std::size_t>(r)], l) = down;
      V(up_rows[static_cast<std::size_t>(r)], l) = up;
      V(down_rows[static_cast<std::size_t>(r)], h + l) = up;  // -lambda swaps the halves
      V(up_rows[static_cast<std::size_t>(r)], h + l) = down;
    }
  }
  return slab;
}

Eigen::MatrixXd LateralSlabModes::real_solutions(double t, double bottom, int count) const {
  const int h = static_cast<int>(lambda.size()) / 2;
  Eigen::MatrixXd solutions(vectors.rows(), count);
  for (int c = 0; c < count; ++c) {
    const std::complex<double> factor = std::exp(-lambda(c) * (c < h ? t : t - bottom));
    if (imaginary[static_cast<std::size_t>(c)]) {
      solutions.col(c) = (vectors.col(c) * factor).imag();
    } else {
      solutions.col(c) = (vectors.col(c) * factor).real();
    }
  }
  return solutions;
}

}  // namespace skinlayer
