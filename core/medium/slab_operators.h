// A homogeneous slab's reflection and transmission operators of one Fourier mode on the discrete ordinates: the
// building block of stacked layers (adding.h). With no interface on either side, unit downward radiance at node j
// entering the top gives the upward radiance at node i leaving the top, R(i, j), and the downward radiance at node
// i leaving the bottom, T(i, j), the unscattered part e^{-tau/mu_j} on T's diagonal included (the discrete-ordinate
// solution carries it exactly). The slab is symmetric under z -> -z, so light entering from below sees the same R
// and T. Both act on node radiances: the quadrature weights are inside them.
//
// Computed from the slab's eigen-decomposition (slab_eigen.h) by the boundary solve (boundary_solve.h) with no
// reflection at either face and the identity as the top source: u-(0) = I, u+(tau_b) = 0; then R = u+(0) and
// T = u-(tau_b). A semi-infinite slab has T = 0.
#pragma once

#include <Eigen/Core>

#include "core/medium/slab_eigen.h"

namespace skinlayer {

struct LayerOperators {
  Eigen::MatrixXd reflection;    // N x N: down at the top face -> up at the top face (and up -> down at the bottom)
  Eigen::MatrixXd transmission;  // N x N: down at the top face -> down at the bottom face (and up -> up)
};

// tau: optical thickness, > 0 or +infinity.
LayerOperators slab_operators(const SlabEigenSolution& eigen, double tau);

}  // namespace skinlayer
