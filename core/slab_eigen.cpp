#include "core/slab_eigen.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

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
  const Eigen::LLT<Eigen::MatrixXd> cholesky(difference);
  if (cholesky.info() != Eigen::Success) {
    throw std::runtime_error("slab_eigen: alpha - beta is not positive definite (single-scattering albedo too close to 1)");
  }
  const Eigen::MatrixXd lower = cholesky.matrixL();
  const Eigen::MatrixXd reduced = lower.transpose() * sum * lower;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(reduced);
  if (eigen.info() != Eigen::Success) throw std::runtime_error("slab_eigen: symmetric eigen-solve failed");

  SlabEigenSolution solution;
  solution.k = eigen.eigenvalues().cwiseMax(1e-300).cwiseSqrt();
  const Eigen::MatrixXd& z = eigen.eigenvectors();
  // S~ = L^-T z, D~ = -L z / k.
  const Eigen::MatrixXd s = lower.transpose().triangularView<Eigen::Upper>().solve(z);
  Eigen::MatrixXd d = -(lower * z);
  for (Eigen::Index j = 0; j < n; ++j) d.col(j) /= solution.k(j);
  // G = X^-1 (S~ +- D~) / 2.
  const Eigen::VectorXd inverse_x = x.cwiseInverse();
  solution.g_up = inverse_x.asDiagonal() * (0.5 * (s + d));
  solution.g_down = inverse_x.asDiagonal() * (0.5 * (s - d));
  return solution;
}

}  // namespace skinlayer
