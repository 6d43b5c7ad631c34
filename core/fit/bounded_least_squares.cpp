#include "core/fit/bounded_least_squares.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace skinlayer {

BoundedFit fit_in_box(const std::function<void(const Eigen::VectorXd& p, Eigen::VectorXd& r)>& residuals, int count,
                      const Eigen::VectorXd& start, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                      int max_evaluations, double good_enough) {
  const Eigen::Index n = start.size();
  BoundedFit fit;
  const auto evaluate = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    r.resize(count);
    residuals(p, r);
    ++fit.evaluations;
    return r.allFinite();
  };
  Eigen::VectorXd p = start.cwiseMax(lo).cwiseMin(hi), r;
  if (!evaluate(p, r)) {
    fit.parameters = p;
    fit.residuals = r;
    return fit;
  }
  double cost = r.squaredNorm();
  double lambda = 1e-3;
  Eigen::MatrixXd jacobian(count, n);
  while (fit.evaluations + n + 1 <= max_evaluations && std::sqrt(cost) > good_enough) {
    // Forward differences, stepping into the box.
    for (Eigen::Index j = 0; j < n; ++j) {
      const double step = 1e-6 * (hi(j) - lo(j));
      Eigen::VectorXd q = p;
      q(j) = p(j) + step <= hi(j) ? p(j) + step : p(j) - step;
      Eigen::VectorXd rq;
      evaluate(q, rq);
      jacobian.col(j) = (rq - r) / (q(j) - p(j));
    }
    const Eigen::VectorXd gradient = jacobian.transpose() * r;
    // Parameters at a bound that the descent direction pushes outward stay there.
    Eigen::Array<bool, Eigen::Dynamic, 1> free(n);
    for (Eigen::Index j = 0; j < n; ++j) {
      free(j) = !((p(j) <= lo(j) && gradient(j) > 0.0) || (p(j) >= hi(j) && gradient(j) < 0.0));
    }
    bool improved = false;
    for (int attempt = 0; attempt < 10 && fit.evaluations < max_evaluations; ++attempt) {
      Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
      for (Eigen::Index j = 0; j < n; ++j) {
        normal(j, j) += lambda * std::max(normal(j, j), 1e-12);
        if (!free(j)) {
          normal.row(j).setZero();
          normal.col(j).setZero();
          normal(j, j) = 1.0;
        }
      }
      Eigen::VectorXd rhs = -gradient;
      for (Eigen::Index j = 0; j < n; ++j)
        if (!free(j)) rhs(j) = 0.0;
      const Eigen::VectorXd delta = normal.ldlt().solve(rhs);
      const Eigen::VectorXd trial = (p + delta).cwiseMax(lo).cwiseMin(hi);
      Eigen::VectorXd trial_r;
      if (evaluate(trial, trial_r) && trial_r.squaredNorm() < cost) {
        improved = cost - trial_r.squaredNorm() > 1e-12 * cost;
        p = trial;
        r = trial_r;
        cost = r.squaredNorm();
        lambda = std::max(lambda / 3.0, 1e-9);
        break;
      }
      lambda *= 4.0;
    }
    if (!improved) break;
  }
  fit.parameters = p;
  fit.residuals = r;
  return fit;
}

}  // namespace skinlayer
