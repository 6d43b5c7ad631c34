// Homogeneous solutions of the discrete-ordinate transfer equation of one Fourier mode, by the half-size
// symmetric eigen-reduction (Stamnes & Swanson 1981; model-spec §6).
//
// Per mode m, with nodes mu_i > 0, weights a_i (sum 1), s = Omega c_m, P++ = p^m(mu_i, mu_j), P+- = p^m(mu_i, -mu_j):
//   alpha = M^-1 (I - s P++ A),   beta = M^-1 s P+- A,   d/dtau [u+; u-] = [[alpha, -beta], [beta, -alpha]] [u+; u-],
// where u+ travels up and u- down, and tau increases downward. Eigenvalues come in pairs +-k. With S = G+ + G- and
// D = G+ - G-, (alpha + beta)(alpha - beta) S = k^2 S and D = -(alpha - beta) S / k for the mode decaying downward.
// With X = diag(sqrt(mu_i a_i)), X alpha X^-1 and X beta X^-1 are symmetric; Cholesky (X(alpha - beta)X^-1) = L L^T
// turns the product into the symmetric problem L^T X(alpha + beta)X^-1 L z = k^2 z, S~ = L^-T z, D~ = -L z / k.
#pragma once

#include <Eigen/Core>
#include <span>

namespace skinlayer {

struct SlabEigenSolution {
  Eigen::VectorXd k;       // decay rates k_j > 0, ascending  [1/optical depth]
  Eigen::MatrixXd g_up;    // column j: upward components of the mode exp(-k_j tau)
  Eigen::MatrixXd g_down;  // column j: downward components of the mode exp(-k_j tau)
};

// same = P++ and opposite = P+- for this mode; scattering = Omega c_m. Requires Omega < 1 for mode 0 (the caller
// clamps); throws std::runtime_error if the reduction is not positive definite.
SlabEigenSolution slab_eigen(std::span<const double> nodes, std::span<const double> weights,
                             const Eigen::MatrixXd& same, const Eigen::MatrixXd& opposite, double scattering);

}  // namespace skinlayer
