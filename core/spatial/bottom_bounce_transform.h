// The light that enters a finite stack as node radiance, crosses it unscattered, reflects once off its bottom face
// and leaves through the top, still unscattered, in k-space (docs/model.md §21.17). On the ordinates it leaves along
// node pairs only, one ring per pair about the entry point: the spatial form of the ray effect that the BSDF solve
// meets in angle (core/unscattered/bottom_bounce.h). The profile swaps the solve's own image of it for the same
// image on finer ordinates.
//
// With C = W diag(lambda) W^-1 the k.s coupling of the modes (lateral_mode_coupling), streaming along node mu through
// the whole stack (optical depth tau, geometric depth H in the first slab's mean free paths) is
//   S(mu) = e^{-tau / mu} W diag(e^{-H k sin(theta) lambda / mu}) W^-1,
// so the bounce is, with t_j the top's source, X_i its exit fraction and R^m the face's reflection:
//   B(k) = 2 pi sum_m sum_ij a_i mu_i X_i S(mu_i)_{0m} R^m(i, j) S(mu_j)_{m0} t_j.
// At k = 0 it is mode 0 alone: B(0) = 2 pi sum_ij a_i mu_i X_i e^{-tau/mu_i} R^0(i, j) e^{-tau/mu_j} t_j.
#pragma once

#include <span>

#include "core/spatial/lateral_bottom_face.h"
#include "core/spatial/lateral_frequency_response.h"
#include "core/spatial/lateral_top_interface.h"

namespace skinlayer {

// The slabs must be finite, top and bottom built on the same nodes for at least `modes` modes; k >= 0 in 1 / the
// first slab's mean free path. Dimensionless (power out per unit power in). Throws std::invalid_argument otherwise.
double bottom_bounce_transform(std::span<const LateralSlab> slabs, const LateralTopInterface& top,
                               const LateralBottomFace& bottom, double k, int modes);

}  // namespace skinlayer
