#include "core/medium/slab_eigen.h"

#include <gtest/gtest.h>

#include "core/conventions.h"
#include "core/medium/henyey_greenstein.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// Checks the eigen-pairs against the full 2N x 2N transfer matrix [[alpha, -beta], [beta, -alpha]], built here
// directly from its definition, not from the reduction.
TEST(SlabEigen, EigenPairsSatisfyTheFullTransferMatrix) {
  const int n = 10;
  const QuadratureRule rule = double_gauss_half_range(n);
  const CosineProjector projector(4, 301);
  const PhaseMatrices phase = henyey_greenstein_matrices(0.8, rule.nodes, rule.weights, projector);
  for (int m = 0; m < 4; ++m) {
    for (double omega : {0.0, 0.5, 0.99, 1.0 - 1e-9}) {
      const double s = omega * fourier_azimuth_weight(m);
      const SlabEigenSolution solution = slab_eigen(rule.nodes, rule.weights, phase.same[m], phase.opposite[m], s);
      Eigen::MatrixXd alpha(n, n), beta(n, n);
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          alpha(i, j) = ((i == j ? 1.0 : 0.0) - s * phase.same[m](i, j) * rule.weights[j]) / rule.nodes[i];
          beta(i, j) = s * phase.opposite[m](i, j) * rule.weights[j] / rule.nodes[i];
        }
      }
      Eigen::MatrixXd transfer(2 * n, 2 * n);
      transfer << alpha, -beta, beta, -alpha;
      for (int j = 0; j < n; ++j) {
        Eigen::VectorXd v(2 * n);
        v << solution.g_up.col(j), solution.g_down.col(j);
        const Eigen::VectorXd residual = transfer * v + solution.k(j) * v;
        EXPECT_LT(residual.norm(), 1e-8 * (1.0 + solution.k(j)) * v.norm()) << "m " << m << " omega " << omega;
        EXPECT_GT(solution.k(j), 0.0);
      }
    }
  }
}

TEST(SlabEigen, PureAbsorberDecaysAtOneOverMu) {
  const QuadratureRule rule = double_gauss_half_range(6);
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(6, 6);
  const SlabEigenSolution solution = slab_eigen(rule.nodes, rule.weights, zero, zero, 0.0);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(solution.k(i), 1.0 / rule.nodes[5 - i], 1e-10);
  EXPECT_LT(solution.g_up.norm(), 1e-10);
}

}  // namespace
}  // namespace skinlayer
