// docs/model.md §21.17: the unscattered light's first bounce off a finite stack's bottom, in k-space.
#include "core/spatial/bottom_bounce_transform.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "core/conventions.h"
#include "core/series/quadrature.h"
#include "core/spatial/lateral_slab_modes.h"

namespace skinlayer {

double bottom_bounce_transform(std::span<const LateralSlab> slabs, const LateralTopInterface& top,
                               const LateralBottomFace& bottom, double k, int modes) {
  const Eigen::Index N = top.source.size();
  if (slabs.empty() || modes < 1 || !(k >= 0.0 && std::isfinite(k)) || top.exit.size() != N ||
      bottom.exit.size() != N || static_cast<int>(bottom.reflection.size()) < modes) {
    throw std::invalid_argument(
        "bottom_bounce_transform: needs slabs, k >= 0, and the faces on the same nodes for the modes asked");
  }
  double tau = 0.0, height = 0.0;
  for (const LateralSlab& s : slabs) {
    if (!(std::isfinite(s.tau) && s.tau >= 0.0 && s.relative_extinction > 0.0)) {
      throw std::invalid_argument("bottom_bounce_transform: the slabs must be finite, with relative extinction > 0");
    }
    tau += s.tau;
    height += s.tau / s.relative_extinction;
  }
  const QuadratureRule q = double_gauss_half_range(static_cast<int>(N));
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(lateral_mode_coupling(modes));
  if (eigen.info() != Eigen::Success) throw std::runtime_error("bottom_bounce_transform: eigen-solve failed");
  const Eigen::MatrixXcd W = eigen.eigenvectors(), inverse = W.inverse();
  const Eigen::VectorXcd lambda = eigen.eigenvalues();
  // Per node, mode 0 streamed to mode m (down: v) and mode m streamed to mode 0 (up: u), with their weights.
  Eigen::MatrixXd down(modes, N), up(modes, N);
  for (Eigen::Index j = 0; j < N; ++j) {
    const double mu = q.nodes[static_cast<std::size_t>(j)], sine = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    const double attenuation = std::exp(-tau / mu);
    Eigen::VectorXcd lateral(modes);
    for (int a = 0; a < modes; ++a) lateral(a) = std::exp(-height * k * sine * lambda(a) / mu);
    const Eigen::VectorXcd from_mode0 = W * lateral.cwiseProduct(inverse.col(0));
    const Eigen::VectorXcd to_mode0 = inverse.transpose() * W.row(0).transpose().cwiseProduct(lateral);
    down.col(j) = attenuation * top.source(j) * from_mode0.real();
    up.col(j) = 2.0 * kPi * q.weights[static_cast<std::size_t>(j)] * mu * top.exit(j) * attenuation * to_mode0.real();
  }
  double bounce = 0.0;
  for (int m = 0; m < modes; ++m) {
    bounce += up.row(m).dot(bottom.reflection[static_cast<std::size_t>(m)] * down.row(m).transpose());
  }
  return bounce;
}

}  // namespace skinlayer
