// Light that enters as node radiance and travels through a stack without being scattered by the media, meeting faces
// on the way (a bottom that reflects it, interfaces between slabs that pass or reflect it), in k-space (docs/model.md
// §21.17). On the ordinates such light travels along nodes only, so it leaves as one ring per sequence of nodes about
// the entry point: the spatial form of the ray effect that the BSDF solve meets in angle
// (core/unscattered/bottom_bounce.h). The profile swaps the solve's own image of it for the same image on finer
// ordinates.
//
// With C = W diag(lambda) W^-1 the k.s coupling of the modes (lateral_mode_coupling), a leg through optical depth tau
// and geometric depth H (in the first slab's mean free paths) along node mu is, on the mode coefficients,
//   S(mu) = e^{-tau / mu} W diag(e^{-H k sin(theta) lambda / mu}) W^-1,
// the same going down or up; a face acts on each mode m as its operator F^m (N x N, quadrature weights included). For
// source t_j (mode 0), legs S_0 .. S_n and faces F_1 .. F_n between them, and exit fractions X_i at the end:
//   P(k) = 2 pi sum_i a_i mu_i X_i [S_n F_n ... F_1 S_0 t]_{mode 0, node i}.
// The first bounce off a bottom: legs down and up through the stack, the face's reflection between them. At k = 0 only
// mode 0 is left.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

namespace skinlayer {

struct UnscatteredLeg {
  double tau = 0.0;     // optical depth crossed
  double height = 0.0;  // geometric depth crossed, in the first slab's mean free paths
};

// source and exit on N double-Gauss nodes per hemisphere; legs.size() == faces.size() + 1, each face with at least
// `modes` N x N operators; k >= 0 in 1 / the first slab's mean free path. Dimensionless (power out per unit power in).
// Throws std::invalid_argument otherwise.
double unscattered_path_transform(const Eigen::VectorXd& source, std::span<const UnscatteredLeg> legs,
                                  std::span<const std::vector<Eigen::MatrixXd>* const> faces,
                                  const Eigen::VectorXd& exit, double k, int modes);

}  // namespace skinlayer
