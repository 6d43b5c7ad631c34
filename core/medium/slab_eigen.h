// Homogeneous solutions of the discrete-ordinate transfer equation of one Fourier mode, by the half-size
// symmetric eigen-reduction (Stamnes & Swanson 1981; docs/model.md §8).
//
// Per mode m, with nodes mu_i > 0, weights a_i (sum 1), s = Omega c_m, P++ = p^m(mu_i, mu_j), P+- = p^m(mu_i, -mu_j):
//   alpha = M^-1 (I - s P++ A),   beta = M^-1 s P+- A,   d/dtau [u+; u-] = [[alpha, -beta], [beta, -alpha]] [u+; u-],
// where u+ travels up and u- down, and tau increases downward. Eigenvalues come in pairs +-k. With S = G+ + G- and
// D = G+ - G-, (alpha + beta)(alpha - beta) S = k^2 S and D = -(alpha - beta) S / k for the mode decaying downward.
// With X = diag(sqrt(mu_i a_i)), X alpha X^-1 and X beta X^-1 are symmetric. X(alpha + beta)X^-1 = L L^T is
// positive definite for every albedo up to 1 (its scattering part holds only the odd, |g|-bounded moments), so
// its Cholesky factor turns (alpha - beta)(alpha + beta) D = k^2 D into the symmetric semi-definite problem
//   L^T X(alpha - beta)X^-1 L z = k^2 z,   D~ = L^-T z,   S~ = -L z / k,
// which stays well conditioned as Omega -> 1, where one k -> 0 (conservative scattering, mode 0). If a coarse
// quadrature makes a strongly peaked phase function act like a forward delta, alpha + beta loses definiteness and
// the same reduction is made with the Cholesky factor of X(alpha - beta)X^-1 instead (S and D swap roles).
#pragma once

#include <Eigen/Core>
#include <span>

namespace skinlayer {

struct SlabEigenSolution {
  Eigen::VectorXd k;       // decay rates k_j > 0, ascending  [1/optical depth]
  Eigen::MatrixXd g_up;    // column j: upward components of the mode exp(-k_j tau)
  Eigen::MatrixXd g_down;  // column j: downward components of the mode exp(-k_j tau)
};

// same = P++ and opposite = P+- for this mode; scattering = Omega c_m, Omega < 1 (at Omega = 1 mode 0 has k = 0 and
// a secular solution; the caller clamps). Each column (G+, G-) is scaled to unit norm. k^2 is floored at the
// rounding level of the reduced matrix. Throws std::runtime_error if neither factor is positive definite.
SlabEigenSolution slab_eigen(std::span<const double> nodes, std::span<const double> weights,
                             const Eigen::MatrixXd& same, const Eigen::MatrixXd& opposite, double scattering);

// Omega = 1 makes mode 0's eigen-reduction singular (a double eigenvalue k = 0). Solving at Omega = 1 - 1e-9 keeps
// it positive definite; the energy this absorbs is ~1e-9 per unit optical path (about 1e-4 of the albedo of a
// conservative semi-infinite layer, whose mean path length diverges).
inline constexpr double kMaxSolvedAlbedo = 1.0 - 1e-9;

// The homogeneous solutions of mode m (c_m = fourier_azimuth_weight(m)) of a slab of albedo Omega in [0, 1] and
// optical depth tau, at Omega clamped to kMaxSolvedAlbedo. Conservative scattering (Omega = 1) in a semi-infinite
// slab takes the exact bounded solution of mode 0 instead of the clamped albedo's slowest mode: k = 0, u = constant
// (exact on the quadrature, since mode 0's phase matrix conserves energy).
SlabEigenSolution slab_mode_eigen(std::span<const double> nodes, std::span<const double> weights,
                                  const Eigen::MatrixXd& same, const Eigen::MatrixXd& opposite, int m, double albedo,
                                  double tau);

}  // namespace skinlayer
