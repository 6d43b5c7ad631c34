// Nonlinear least squares over a box: minimize sum_i r_i(p)^2 with lo_j <= p_j <= hi_j, by Levenberg-Marquardt
// with the steps projected onto the box (Kanzow, Yamashita & Fukushima 2004's projected LM in its simplest form):
//   (J^T J + lambda diag(J^T J)) delta = -J^T r,   p <- clamp(p + delta),
// accepted when |r| falls (lambda / 3), else lambda x 4 and the step is tried again. J is by forward differences,
// stepping into the box at a bound, and a parameter held at a bound by its gradient leaves the step (an active set).
// Eigen's own Levenberg-Marquardt (unsupported/NonLinearOptimization) has no bounds, and a change of variables onto
// the box flattens its Jacobian at the bounds, where skin fits often rest (no blood, no melanin).
#pragma once

#include <Eigen/Core>
#include <functional>

namespace skinlayer {

struct BoundedFit {
  Eigen::VectorXd parameters;  // the best p found
  Eigen::VectorXd residuals;   // r(p) there
  int evaluations = 0;         // calls of the residual function
  double norm() const { return residuals.norm(); }
};

// residuals(p, r) fills r (its size fixed by `count`). start is clamped into the box; max_evaluations bounds the
// work, and the fit stops as soon as |r| <= good_enough, or when a step no longer lowers |r|^2 by 1e-12 of itself.
BoundedFit fit_in_box(const std::function<void(const Eigen::VectorXd& p, Eigen::VectorXd& r)>& residuals, int count,
                      const Eigen::VectorXd& start, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                      int max_evaluations = 200, double good_enough = 0.0);

}  // namespace skinlayer
