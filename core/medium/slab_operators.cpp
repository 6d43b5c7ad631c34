#include "core/medium/slab_operators.h"

#include <cmath>

#include "core/solve/boundary_solve.h"

namespace skinlayer {

LayerOperators slab_operators(const SlabEigenSolution& eigen, double tau) {
  const Eigen::Index n = eigen.k.size();
  BoundaryProblem problem;
  problem.eigen = &eigen;
  problem.tau = tau;
  problem.source_top = Eigen::MatrixXd::Identity(n, n);
  const NodeField field = solve_boundary(problem, static_cast<int>(n));
  LayerOperators result;
  result.reflection = field.up_top;
  result.transmission = std::isinf(tau) ? Eigen::MatrixXd::Zero(n, n) : field.down_bottom;
  return result;
}

}  // namespace skinlayer
