// A rough interface between two slabs of a stack, as the ordinates of a lateral-frequency solve see it (docs/model.md
// §21.16): the BSDF solve's own operators between stacked layers (core/interfaces/internal_interface.h), on the same
// nodes and energy-matched the same way, so that the k = 0 response is the stack's subsurface reflectance.
//
// Like the top it has no thickness and moves no light sideways, so it acts on each azimuthal mode at every frequency
// as it does in the BSDF. For node radiances u+- just above (a) and below (b) it:
//   u+_a = R_a u-_a + T_up u+_b,    u-_b = R_b u+_b + T_down u-_a.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

struct LateralInternalFace {
  // Per cosine mode m = 0 .. modes - 1, N x N with the quadrature weights: down-above -> up-above (R_a),
  // up-below -> down-below (R_b), down-above -> down-below (T_down), up-below -> up-above (T_up).
  std::vector<Eigen::MatrixXd> reflect_above, reflect_below, transmit_down, transmit_up;
};

// interface.eta = n_below / n_above (!= 1: at 1 there is no interface), on `ordinates` double-Gauss nodes per
// hemisphere and `modes` cosine modes, projected on `azimuths` samples as the BSDF solve projects them.
LateralInternalFace lateral_internal_face(const RoughDielectric& interface, int ordinates, int modes,
                                          int azimuths = 97);

}  // namespace skinlayer
