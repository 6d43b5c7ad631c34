// One homogeneous slab's discrete-ordinate system at one lateral spatial frequency (docs/model.md §21.2–§21.3): the
// state's layout over modes and nodes, the k.s coupling, and the eigen-solution with the collimated beam's particular
// solution. lateral_frequency_response.h joins slabs through their faces.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/medium/henyey_greenstein.h"
#include "core/series/quadrature.h"

namespace skinlayer {

// The state: cosine modes m of I = sum_m i^m a_m(tau, mu) cos(m phi), each at the nodes down (+mu_j) then up
// (-mu_j). With the factor i^m the k.s term couples the modes with real coefficients (§21.2).
struct LateralLayout {
  int nodes = 0;  // N
  int modes = 0;  // M
  int size() const { return 2 * nodes * modes; }
  int at(int m, int up, int j) const { return (m * 2 + up) * nodes + j; }
};

// The phase function's Fourier matrices on the nodes, as every lateral solve projects them (mode 0 renormalized to
// conserve energy on the nodes, §7).
PhaseMatrices lateral_phase_matrices(double g, const QuadratureRule& quadrature, int modes);

// C, the k.s term between the modes (§21.2): with I = sum_m i^m a_m cos(m phi), the streaming operator of node mu is
// (1 + k sin(theta) C) / mu on the coefficients a_m, C(m, m - 1) = 1 for m = 1 and 1/2 above, C(m, m + 1) = -1/2.
Eigen::MatrixXd lateral_mode_coupling(int modes);

// sum_j a_j [p(mu_j) + p(-mu_j)]: how much of a collimated beam's first scattering the nodes hold, per 2 pi. The
// beam's source is p / (2 pi times it), so that the quadrature scatters exactly what the beam loses (§6.2).
double beam_scattering_on_nodes(double g, const QuadratureRule& quadrature);

// The slab's solutions in its own optical depth t (0 at its top): v e^{-lambda t} for the first size/2 columns
// (Re lambda > 0, decaying downward) and, swapped, v e^{-lambda t} with lambda = -root for the rest (growing; the
// caller refers them to the slab's bottom). `beam`: X with (A - 1) X = D^-1 s, the particular solution X e^{-t} of a
// collimated beam of unit flux at the slab's top, travelling straight down, whose first scattering s has the albedo
// `source_albedo`; zero where source_albedo is 0.
//
// The system is real, so its complex solutions come in conjugate pairs, adjacent (the one with Im lambda^2 > 0
// first). A real basis takes the real part of the first and the imaginary part of the second (the conjugate's
// imaginary part, negated): `imaginary` marks the latter, and real_solutions() gives them (§21.3).
struct LateralSlabModes {
  Eigen::VectorXcd lambda;
  Eigen::MatrixXcd vectors;
  Eigen::VectorXd beam;
  std::vector<bool> imaginary;  // per column: the solution's imaginary part stands for it, else its real part

  // The real solutions of columns [0, count) at depth t, each referred to its own depth: the decaying columns to
  // t = 0 and the growing ones (from size/2 on) to t = bottom.
  Eigen::MatrixXd real_solutions(double t, double bottom, int count) const;
};

// operator_albedo in [0, 1] scatters in the operator, at most kMaxSolvedAlbedo (slab_eigen.h) as in the BSDF solve;
// operator_albedo = 0 (streaming alone) is solved as one M x M
// eigenproblem per node. k >= 0 in 1 / the slab's mean free path. Throws std::invalid_argument for values outside
// those ranges, or for a mode that neither decays nor grows.
LateralSlabModes lateral_slab_modes(double operator_albedo, double source_albedo, double g, double k,
                                    const QuadratureRule& quadrature, int modes);

}  // namespace skinlayer
