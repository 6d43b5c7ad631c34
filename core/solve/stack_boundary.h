// The boundary-value problem of one Fourier mode for a stack of homogeneous slabs: every slab's general solution
// (core/solve/boundary_solve.h: its eigen-decomposition and, where the open top's beam reaches it, the beam's
// particular solution) coupled at the faces between them, solved for every incident direction at once. This is the exact
// composition DISORT uses for multilayer media (Stamnes et al. 1988, §4): the same equations as adding the slabs'
// reflection and transmission operators (core/solve/adding.h), but the collimated beam, which no node operator can
// carry (it is a delta in direction), stays a particular solution in each slab it reaches, and every slab's constants
// come out, so exits and fluxes can be read at any face.
//
// Unknowns: c-_i, c+_i per slab (c+ absent for a semi-infinite last slab). Conditions, with u+- the node radiances
// (up, down) at a slab's top (0) and bottom (tau_i) face:
//   top of slab 1:          u-_1(0) = source_top + R_top u+_1(0)
//   face between a and b:   u+_a(tau_a) = source_up + R_a u-_a(tau_a) + T_up u+_b(0)
//                           u-_b(0)     = source_down + R_b u+_b(0) + T_down u-_a(tau_a)
//                           (an index-matched face: R = 0, T = I, no sources: continuity)
//   bottom of slab n:       u+_n(tau_n) = source_bottom + R_bottom u-_n(tau_n)
// One dense block system of size sum_i 2N (N per semi-infinite slab), solved by LU with partial pivoting; every
// exponential in it is <= 1 (the general solution of boundary_solve.h), so it is as well conditioned as one slab's.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/solve/boundary_solve.h"

namespace skinlayer {

// The coupling at the face between slab a (above) and slab b (below). Empty reflections are 0 and empty
// transmissions the identity (an index-matched face); empty sources are 0.
struct FaceCoupling {
  Eigen::MatrixXd reflect_above;  // R_a: down at a's bottom -> up at a's bottom
  Eigen::MatrixXd reflect_below;  // R_b: up at b's top -> down at b's top
  Eigen::MatrixXd transmit_down;  // T_down: down at a's bottom -> down at b's top
  Eigen::MatrixXd transmit_up;    // T_up: up at b's top -> up at a's bottom
  Eigen::MatrixXd source_up;      // N x K into a, up
  Eigen::MatrixXd source_down;    // N x K into b, down
};

// The solved constants of each slab, and the node radiances at all its faces (N x K each).
struct StackField {
  std::vector<NodeField> slabs;                      // c-, c+, up_top and down_bottom per slab
  std::vector<Eigen::MatrixXd> down_top, up_bottom;  // u-_i(0) and u+_i(tau_i) (zero for a semi-infinite slab);
                                                     // empty for one slab, whose fluxes up_top and down_bottom give
};

// slabs: top to bottom; slabs[0]'s reflect_top and source_top are the top condition, slabs.back()'s reflect_bottom
// and source_bottom the bottom condition, and those of the other slabs must be empty. Each slab's beam, if any, is
// its particular solution already scaled by the beam's amplitude at the slab's top. faces: slabs.size() - 1.
StackField solve_stack_boundary(std::span<const BoundaryProblem> slabs, std::span<const FaceCoupling> faces,
                                int incident_count);

}  // namespace skinlayer
