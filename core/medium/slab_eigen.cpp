#include "core/medium/slab_eigen.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/conventions.h"

namespace skinlayer {

SlabEigenSolution slab_eigen(std::span<const double> nodes, std::span<const double> weights,
                             const Eigen::MatrixXd& same, const Eigen::MatrixXd& opposite, double scattering) {
  const Eigen::Index n = static_cast<Eigen::Index>(nodes.size());
  // X alpha X^-1 = diag(1/mu) - s P++ sqrt(a_i a_j / (mu_i mu_j)); X beta X^-1 = s P+- sqrt(a_i a_j / (mu_i mu_j)).
  Eigen::VectorXd root(n);  // sqrt(a_i / mu_i)
  Eigen::VectorXd x(n);     // sqrt(mu_i a_i)
  for (Eigen::Index i = 0; i < n; ++i) {
    root(i) = std::sqrt(weights[i] / nodes[i]);
    x(i) = std::sqrt(nodes[i] * weights[i]);
  }
  const Eigen::MatrixXd scale = root * root.transpose();
  Eigen::MatrixXd alpha = -scattering * same.cwiseProduct(scale);
  alpha.diagonal() += Eigen::VectorXd(n).setOnes().cwiseQuotient(Eigen::Map<const Eigen::VectorXd>(nodes.data(), n));
  const Eigen::MatrixXd beta = scattering * opposite.cwiseProduct(scale);

  const Eigen::MatrixXd difference = alpha - beta;
  const Eigen::MatrixXd sum = alpha + beta;
  // Reduce with whichever of the two symmetric factors is positive definite: alpha + beta (robust as Omega -> 1)
  // first, alpha - beta (robust when a coarse quadrature makes the phase function look like a forward delta, so
  // that alpha + beta ~ (1 - Omega g) -> 0) second. Swapping the roles swaps S and D.
  Eigen::LLT<Eigen::MatrixXd> cholesky(sum);
  const bool sum_factored = cholesky.info() == Eigen::Success;
  if (!sum_factored) cholesky.compute(difference);
  if (cholesky.info() != Eigen::Success) {
    throw std::runtime_error("slab_eigen: the discrete transfer matrix has no real eigen-decomposition; use more "
                             "ordinates for this phase function");
  }
  const Eigen::MatrixXd lower = cholesky.matrixL();
  const Eigen::MatrixXd reduced = lower.transpose() * (sum_factored ? difference : sum) * lower;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(reduced);
  if (eigen.info() != Eigen::Success) throw std::runtime_error("slab_eigen: symmetric eigen-solve failed");

  SlabEigenSolution solution;
  const double floor = std::numeric_limits<double>::epsilon() * eigen.eigenvalues().cwiseAbs().maxCoeff();
  solution.k = eigen.eigenvalues().cwiseMax(floor).cwiseSqrt();
  const Eigen::MatrixXd& z = eigen.eigenvectors();
  // Factoring alpha + beta: D~ = L^-T z, S~ = -L z / k. Factoring alpha - beta: S~ = L^-T z, D~ = -L z / k.
  const Eigen::MatrixXd inverse_transpose_z = lower.transpose().triangularView<Eigen::Upper>().solve(z);
  Eigen::MatrixXd lz = -(lower * z);
  for (Eigen::Index j = 0; j < n; ++j) lz.col(j) /= solution.k(j);
  const Eigen::MatrixXd& s = sum_factored ? lz : inverse_transpose_z;
  const Eigen::MatrixXd& d = sum_factored ? inverse_transpose_z : lz;
  // G = X^-1 (S~ +- D~) / 2, each column pair scaled to unit norm.
  const Eigen::VectorXd inverse_x = x.cwiseInverse();
  solution.g_up = inverse_x.asDiagonal() * (0.5 * (s + d));
  solution.g_down = inverse_x.asDiagonal() * (0.5 * (s - d));
  for (Eigen::Index j = 0; j < n; ++j) {
    const double norm = std::hypot(solution.g_up.col(j).norm(), solution.g_down.col(j).norm());
    solution.g_up.col(j) /= norm;
    solution.g_down.col(j) /= norm;
  }
  return solution;
}

SlabEigenSolution slab_mode_eigen(std::span<const double> nodes, std::span<const double> weights,
                                  const Eigen::MatrixXd& same, const Eigen::MatrixXd& opposite, int m, double albedo,
                                  double tau) {
  SlabEigenSolution eigen =
      slab_eigen(nodes, weights, same, opposite, std::min(albedo, kMaxSolvedAlbedo) * fourier_azimuth_weight(m));
  if (m == 0 && albedo == 1.0 && std::isinf(tau)) {
    eigen.k(0) = 0.0;
    eigen.g_up.col(0).setOnes();
    eigen.g_down.col(0).setOnes();
  }
  return eigen;
}

}  // namespace skinlayer
