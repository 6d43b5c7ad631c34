// docs/model.md §21.17: light crossing a stack unscattered through its faces, in k-space.
#include "core/spatial/unscattered_path_transform.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "core/conventions.h"
#include "core/series/quadrature.h"
#include "core/spatial/lateral_slab_modes.h"

namespace skinlayer {

double unscattered_path_transform(const Eigen::VectorXd& source, std::span<const UnscatteredLeg> legs,
                                  std::span<const std::vector<Eigen::MatrixXd>* const> faces,
                                  const Eigen::VectorXd& exit, double k, int modes) {
  const Eigen::Index N = source.size();
  bool ok = N >= 1 && modes >= 1 && k >= 0.0 && std::isfinite(k) && exit.size() == N && legs.size() == faces.size() + 1;
  for (const UnscatteredLeg& leg : legs) ok = ok && leg.tau >= 0.0 && leg.height >= 0.0 && std::isfinite(leg.tau);
  for (const std::vector<Eigen::MatrixXd>* face : faces) {
    ok = ok && face != nullptr && static_cast<int>(face->size()) >= modes && face->front().rows() == N;
  }
  if (!ok) {
    throw std::invalid_argument(
        "unscattered_path_transform: needs k >= 0, finite legs one more than the faces, and every operator on the "
        "source's nodes for the modes asked");
  }
  const QuadratureRule q = double_gauss_half_range(static_cast<int>(N));
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(lateral_mode_coupling(modes));
  if (eigen.info() != Eigen::Success) throw std::runtime_error("unscattered_path_transform: eigen-solve failed");
  const Eigen::MatrixXcd W = eigen.eigenvectors(), inverse = W.inverse();
  const Eigen::VectorXcd lambda = eigen.eigenvalues();
  // The light on the mode coefficients (rows) of each node (columns); it enters in mode 0.
  Eigen::MatrixXd light = Eigen::MatrixXd::Zero(modes, N);
  light.row(0) = source.transpose();
  for (std::size_t step = 0; step < legs.size(); ++step) {
    if (step > 0) {
      const std::vector<Eigen::MatrixXd>& face = *faces[step - 1];
      for (int m = 0; m < modes; ++m) {
        light.row(m) = (face[static_cast<std::size_t>(m)] * light.row(m).transpose()).transpose();
      }
    }
    const UnscatteredLeg& leg = legs[step];
    for (Eigen::Index j = 0; j < N; ++j) {
      const double mu = q.nodes[static_cast<std::size_t>(j)], sine = std::sqrt(std::max(0.0, 1.0 - mu * mu));
      Eigen::VectorXcd lateral(modes);
      for (int a = 0; a < modes; ++a) lateral(a) = std::exp(-leg.height * k * sine * lambda(a) / mu);
      const Eigen::VectorXcd streamed = W * lateral.cwiseProduct(inverse * light.col(j).cast<std::complex<double>>());
      light.col(j) = std::exp(-leg.tau / mu) * streamed.real();
    }
  }
  double leaving = 0.0;
  for (Eigen::Index i = 0; i < N; ++i) {
    leaving += 2.0 * kPi * q.weights[static_cast<std::size_t>(i)] * q.nodes[static_cast<std::size_t>(i)] * exit(i) *
               light(0, i);
  }
  return leaving;
}

}  // namespace skinlayer
