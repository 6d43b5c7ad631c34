// The boundary-value problem of one Fourier mode: the slab's homogeneous solutions (slab_eigen.h), an optional
// particular solution for an unscattered beam, and the conditions at the two interfaces, solved for every incident
// direction (one right-hand-side column each) at once. Then the radiance at arbitrary (non-node) directions by
// integrating the source function along the ray (the "intensity interpolation" of Stamnes et al. 1988).
//
// General solution (overflow-free; every exponential <= 1):
//   u+(tau) = G+ e^{-K tau} c- + G- e^{-K (tau_b - tau)} c+ + Z+ e^{-tau/mu0}
//   u-(tau) = G- e^{-K tau} c- + G+ e^{-K (tau_b - tau)} c+ + Z- e^{-tau/mu0}
// Boundary conditions (Stam 2001 slides: w-(0) = t12 + R21 w+(0), w+(tau_b) = R23 w-(tau_b)):
//   u-(0) = source_top + R_top u+(0),     u+(tau_b) = source_bottom + R_bottom u-(tau_b),
// which, with E = diag(e^{-k tau_b}), is the 2N x 2N system
//   [ G- - R_top G+          (G+ - R_top G-) E ] [c-]   [ source_top - (Z- - R_top Z+)                         ]
//   [ (G+ - R_bottom G-) E    G- - R_bottom G+ ] [c+] = [ source_bottom - (Z+ - R_bottom Z-) e^{-tau_b/mu0}   ].
// A semi-infinite slab (tau_b = infinity) keeps only c- and the top row.
#pragma once

#include <Eigen/Core>
#include <span>

#include "core/medium/slab_eigen.h"

namespace skinlayer {

// e^{-tau/mu} for each cosine mu (> 0): the slab's transmittance along each direction, unscattered.
Eigen::VectorXd slab_attenuation(std::span<const double> mu, double tau);

// Particular solution for a collimated beam travelling down at cosine mu0 (one column per beam) that is scattered
// with source J^m(tau, mu) = beam_source(mu) e^{-tau/mu0}. Solves, over all 2N signed nodes,
//   (I + diag(mu_signed)/mu0 - s P A) Z = J,   s = Omega c_m.
// beam_up(i, k) = Omega F p^m(mu_i, -mu0_k), beam_down(i, k) = Omega F p^m(-mu_i, -mu0_k).
struct BeamParticular {
  Eigen::MatrixXd up;    // Z+ (N x K)
  Eigen::MatrixXd down;  // Z- (N x K)
  Eigen::VectorXd mu0;   // the beam cosines, one per column
};
BeamParticular beam_particular_solution(std::span<const double> nodes, std::span<const double> weights,
                                        const Eigen::MatrixXd& same, const Eigen::MatrixXd& opposite, double scattering,
                                        const Eigen::MatrixXd& beam_up, const Eigen::MatrixXd& beam_down,
                                        std::span<const double> mu0);

struct BoundaryProblem {
  const SlabEigenSolution* eigen = nullptr;
  double tau = 0.0;                      // optical thickness; +infinity = semi-infinite
  Eigen::MatrixXd reflect_top;           // R21 (N x N, to-down x from-up); empty = no reflection
  Eigen::MatrixXd reflect_bottom;        // R23 (N x N, to-up x from-down); empty = no reflection
  Eigen::MatrixXd source_top;            // N x K; empty = none
  Eigen::MatrixXd source_bottom;         // N x K; empty = none
  const BeamParticular* beam = nullptr;  // null = no unscattered beam inside the slab
};

// The solution's constants and the node radiances that meet the interfaces from inside (N x K each): upward at
// the top and downward at the bottom (the ones the exits and the fluxes read).
struct NodeField {
  Eigen::MatrixXd c_minus;
  Eigen::MatrixXd c_plus;  // zero for a semi-infinite slab
  Eigen::MatrixXd up_top, down_bottom;
};
NodeField solve_boundary(const BoundaryProblem& problem, int incident_count);

// In-scattering rows for exit directions: same_row(o, j) = s p^m(mu_o, mu_j) a_j and
// opposite_row(o, j) = s p^m(mu_o, -mu_j) a_j for exit cosines mu_o > 0; beam_row(o, k) = Omega F p^m(+-mu_o, -mu0_k).
struct ExitScattering {
  std::span<const double> mu;  // exit cosines (> 0)
  Eigen::MatrixXd same_row;
  Eigen::MatrixXd opposite_row;
  Eigen::MatrixXd beam_row;  // empty = no beam
};

// u^m(0, +mu_o) for every exit mu_o and incident column: upward radiance leaving the slab's top face.
// upward_at_bottom(o, k) is u^m(tau_b, +mu_o), the radiance the bottom boundary sends up (empty = none).
Eigen::MatrixXd upward_radiance_at_top(const BoundaryProblem& problem, const NodeField& field,
                                       const ExitScattering& exit, const Eigen::MatrixXd& upward_at_bottom);

// u^m(tau_b, -mu_o): downward radiance arriving at the slab's bottom face. downward_at_top(o, k) is u^m(0, -mu_o),
// the radiance the top boundary sends down (empty = none). For this call beam_row(o, k) = Omega F p^m(-mu_o, -mu0_k).
Eigen::MatrixXd downward_radiance_at_bottom(const BoundaryProblem& problem, const NodeField& field,
                                            const ExitScattering& exit, const Eigen::MatrixXd& downward_at_top);

// (e^{-k tau} - e^{-tau/mu}) / (1 - k mu), evaluated without cancellation or overflow; 0 for tau = infinity.
double exponential_difference_ratio(double k, double mu, double tau);

}  // namespace skinlayer
